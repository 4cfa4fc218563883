#include "lang/cpfg_cylinder_contour.h"

#include <cmath>
#include <cstdlib>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "ir/source_loc.h"
#include "lang/source_text.h"

namespace simeco::lang {

namespace {

// Far above any drawn contour, far below what a ring of them costs in memory.
constexpr long kMostPoints = 100'000;
constexpr long kMostMultiplicity = 1000;

struct Word {
    std::string_view text;
    int col = 1;
};

class ContourLines {
public:
    ContourLines(const std::string& text, const std::string& file) : file_(file) {
        size_t start = 0;
        while (start <= text.size()) {
            size_t end = text.find('\n', start);
            if (end == std::string::npos) end = text.size();
            lines_.push_back(std::string_view(text).substr(start, end - start));
            start = end + 1;
        }
        while (!lines_.empty() && words(lines_.back()).empty()) lines_.pop_back();
    }

    bool atEnd() const { return next_ >= lines_.size(); }
    int lineNumber() const { return static_cast<int>(next_) + 1; }

    // The next line's words (the line is then behind).
    std::vector<Word> line(const char* expected) {
        if (atEnd())
            throw ir::InputError({file_, lineNumber(), 1}, fmt::format("expected {}, found the end of the file",
                                                                        expected));
        return words(lines_[next_++]);
    }
    // The next line's words, without passing it.
    std::vector<Word> peek() const { return atEnd() ? std::vector<Word>{} : words(lines_[next_]); }

    [[noreturn]] void fail(int line, int col, const std::string& message) const {
        throw ir::InputError({file_, line, col}, message);
    }

    double number(const std::vector<Word>& ws, size_t k, const char* what) const {
        const int line = lineNumber() - 1;
        if (k >= ws.size()) fail(line, ws.empty() ? 1 : ws.back().col, fmt::format("expected {}", what));
        const std::string text(ws[k].text);
        char* end = nullptr;
        const double v = std::strtod(text.c_str(), &end);
        if (end != text.c_str() + text.size() || !std::isfinite(v))
            fail(line, ws[k].col, fmt::format("expected a finite number for {}, found '{}'", what, text));
        return v;
    }
    long whole(const std::vector<Word>& ws, size_t k, const char* what, long least, long most) const {
        const double v = number(ws, k, what);
        if (v != std::floor(v) || v < double(least) || v > double(most))
            fail(lineNumber() - 1, ws[k].col,
                 fmt::format("{} is a whole number from {} to {}, found {}", what, least, most, ws[k].text));
        return static_cast<long>(v);
    }
    // The line `key: ...`'s words after the key.
    std::vector<Word> keyed(std::string_view key, const char* expected) {
        std::vector<Word> ws = line(expected);
        if (ws.empty() || ws[0].text != key)
            fail(lineNumber() - 1, ws.empty() ? 1 : ws[0].col, fmt::format("expected {}", expected));
        ws.erase(ws.begin());
        return ws;
    }

private:
    static std::vector<Word> words(std::string_view line) {
        std::vector<Word> out;
        size_t i = 0;
        auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
        while (i < line.size()) {
            while (i < line.size() && blank(line[i])) ++i;
            if (i >= line.size()) break;
            const size_t start = i;
            while (i < line.size() && !blank(line[i])) ++i;
            out.push_back({line.substr(start, i - start), static_cast<int>(start) + 1});
        }
        return out;
    }

    std::string file_;
    std::vector<std::string_view> lines_;
    size_t next_ = 0;
};

// cpfg's older contours: `N dimension open|closed`, then N points of two or three numbers.
ir::CylinderContour olderContour(ContourLines& in) {
    ir::CylinderContour c;
    std::vector<Word> head = in.line("'points dimension type'");
    const long count = in.whole(head, 0, "the number of points", 1, kMostPoints);
    c.dimension = in.whole(head, 1, "the dimension", 2, 3) == 3 ? 3 : 2;
    c.closed = head.size() > 2 && head[2].text == "closed";
    for (long k = 0; k < count; ++k) {
        std::vector<Word> p = in.line("a contour point");
        std::array<float, 3> point{};
        for (int a = 0; a < c.dimension; ++a)
            point[size_t(a)] = static_cast<float>(in.number(p, size_t(a), a == 0 ? "x" : a == 1 ? "y" : "z"));
        c.points.push_back(point);
    }
    return c;
}

// `cver 1 1`, `1 2` and `1 3`.
ir::CylinderContour versionedContour(ContourLines& in, int version) {
    ir::CylinderContour c;
    c.dimension = 3;
    in.line("'name: ...'"); // the contour's name, which nothing reads
    std::vector<Word> points = in.keyed("points:", "'points: N M'");
    const long listed = in.whole(points, 0, "the number of listed points", 1, kMostPoints);
    const long total = in.whole(points, 1, "the number of points with their multiplicities", 1, kMostPoints);
    std::vector<Word> type = in.keyed("type:", "'type: ...'");
    const std::string_view word = type.empty() ? std::string_view{} : type[0].text;
    // 1.1 says `open` or `closed`; later versions two letters, o or c then r or e (which cpfg draws as r).
    c.closed = version == 101 ? word != "open" : !word.starts_with("o");
    if (version >= 103) {
        in.keyed("samples:", "'samples: N'"); // cpfg samples by the cylinder's sides instead
        // Optional lines of the contour editor.
        while (!in.atEnd() && !in.peek().empty() &&
               (in.peek()[0].text.starts_with("background") || in.peek()[0].text.starts_with("markers")))
            in.line("");
    }
    long sum = 0;
    for (long k = 0; k < listed; ++k) {
        std::vector<Word> p = in.line("a contour point 'x y z multiplicity'");
        std::array<float, 3> point{};
        for (int a = 0; a < 3; ++a)
            point[size_t(a)] = static_cast<float>(in.number(p, size_t(a), a == 0 ? "x" : a == 1 ? "y" : "z"));
        const long multiplicity = p.size() > 3 ? in.whole(p, 3, "a multiplicity", 1, kMostMultiplicity) : 1;
        sum += multiplicity;
        if (sum > total)
            in.fail(in.lineNumber() - 1, 1,
                    fmt::format("the points' multiplicities add up to more than the {} that 'points:' says", total));
        for (long m = 0; m < multiplicity; ++m) c.points.push_back(point);
    }
    if (sum != total)
        in.fail(in.lineNumber(), 1,
                fmt::format("the points' multiplicities add up to {}, 'points:' says {}", sum, total));
    return c;
}

} // namespace

ir::CylinderContour parseCylinderContour(const std::string& text, const std::string& file) {
    ContourLines in(text, file);
    std::vector<Word> first = in.peek();
    ir::CylinderContour c;
    if (!first.empty() && first[0].text == "cver") {
        in.line("");
        const long major = in.whole(first, 1, "the major version", 0, 99);
        const long minor = in.whole(first, 2, "the minor version", 0, 99);
        const int version = static_cast<int>(100 * major + minor);
        if (version < 101 || version > 103)
            in.fail(1, first[1].col, fmt::format("contour version {}.{} is not one cpfg reads (1.1 to 1.3)", major,
                                                 minor));
        c = versionedContour(in, version);
    } else {
        c = olderContour(in);
    }
    // A uniform cubic B-spline spans its points less three where open, all of them where closed.
    if (c.closed ? c.points.size() < 3 : c.points.size() < 4)
        in.fail(1, 1, fmt::format("an {} contour needs at least {} points (with their multiplicities), found {}",
                                  c.closed ? "closed" : "open", c.closed ? 3 : 4, c.points.size()));
    return c;
}

ir::CylinderContour readCylinderContour(const std::string& path) {
    const std::string text = readSourceFile(path);
    return parseCylinderContour(text, path);
}

} // namespace simeco::lang
