#include "lang/cpfg_contour.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "lang/source_text.h"

namespace simeco::lang {

namespace {

// cpfg allocates 20 nesting levels for `points:` lines inside a curve.
constexpr size_t kMaxLevels = 20;
constexpr long kMaxPoints = 1'000'000;
constexpr long kMaxMultiplicity = 1000;

struct Token {
    std::string_view text;
    int col = 1; // 1-based byte column in the line
};

std::vector<Token> tokens(std::string_view line, size_t from) {
    std::vector<Token> out;
    size_t i = from;
    while (i < line.size()) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t' || line[i] == '\r'))
            ++i;
        if (i >= line.size()) break;
        size_t start = i;
        while (i < line.size() && line[i] != ' ' && line[i] != '\t' && line[i] != '\r')
            ++i;
        out.push_back({line.substr(start, i - start), static_cast<int>(start + 1)});
    }
    return out;
}

bool toNumber(std::string_view text, double& value) {
    std::string s(text);
    char* end = nullptr;
    value = std::strtod(s.c_str(), &end);
    return !s.empty() && end == s.c_str() + s.size() && std::isfinite(value);
}

// A `points:` level: the top level is the curve; deeper levels belong to single points and only matter to
// cpfg's interactive editing, so they are read and dropped.
struct Level {
    long count = 0;
    long index = -1; // the last point read
    int dimension = 2;
};

class ContourReader {
public:
    explicit ContourReader(const std::string& path) : path_(path) {}

    ir::ContourCurve read() {
        std::string text = readSourceFile(path_);
        curve_.name = std::filesystem::path(path_).filename().string();
        size_t start = 0;
        while (start <= text.size()) {
            size_t end = text.find('\n', start);
            if (end == std::string::npos) end = text.size();
            std::string_view line(text.data() + start, end - start);
            if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
            ++lineNumber_;
            readLine(line);
            if (end == text.size()) break;
            start = end + 1;
        }
        if (levels_.empty()) throw ir::InputError({path_, 1, 1}, "expected a 'points: N' line");
        const Level& top = levels_.front();
        if (top.index + 1 != top.count)
            throw ir::InputError({path_, pointsLine_, 1},
                                 fmt::format("the file declares {} points but lists {}", top.count, top.index + 1));
        ir::sampleContourCurve(curve_);
        return std::move(curve_);
    }

private:
    [[noreturn]] void fail(int col, const std::string& message) const {
        throw ir::InputError({path_, lineNumber_, col}, message);
    }

    // The numbers after a label (cpfg reads them with sscanf, so extra words are ignored).
    std::vector<double> numbers(std::string_view line, size_t from, size_t count, const char* label) {
        std::vector<Token> words = tokens(line, from);
        std::vector<double> out;
        for (size_t i = 0; i < count; ++i) {
            double v = 0;
            if (i >= words.size())
                fail(static_cast<int>(line.size() + 1), fmt::format("'{}' needs {} number(s)", label, count));
            if (!toNumber(words[i].text, v))
                fail(words[i].col, fmt::format("'{}' expected a number, found '{}'", label, words[i].text));
            out.push_back(v);
        }
        return out;
    }

    long integer(std::string_view line, size_t from, const char* label, long low, long high) {
        double v = numbers(line, from, 1, label)[0];
        // The range first: converting a double outside long's range is undefined.
        if (!(v >= static_cast<double>(low) && v <= static_cast<double>(high)) || v != std::floor(v))
            fail(tokens(line, from)[0].col, fmt::format("'{}' expects a whole number from {} to {}", label, low, high));
        return static_cast<long>(v);
    }

    void readLine(std::string_view line) {
        auto starts = [&](std::string_view label) { return line.substr(0, label.size()) == label; };
        if (starts("//")) return;
        if (starts("version:")) {
            if (tokens(line, 8).empty()) fail(9, "'version:' needs a value");
        } else if (starts("contact:")) {
            numbers(line, 8, 3, "contact:");
        } else if (starts("end:")) {
            numbers(line, 4, 3, "end:");
        } else if (starts("heading:")) {
            numbers(line, 8, 3, "heading:");
        } else if (starts("up:")) {
            numbers(line, 3, 3, "up:");
        } else if (starts("size:")) {
            numbers(line, 5, 1, "size:");
        } else if (starts("points:")) {
            startLevel(integer(line, 7, "points:", 0, kMaxPoints));
        } else if (starts("range:")) {
            numbers(line, 6, 2, "range:");
        } else if (starts("dim:") || starts("dimension:")) {
            size_t from = starts("dim:") ? 4 : 10;
            int dimension = static_cast<int>(integer(line, from, starts("dim:") ? "dim:" : "dimension:", 2, 4));
            if (levels_.empty()) fail(1, "'dimension:' must follow a 'points:' line");
            levels_.back().dimension = dimension;
        } else if (starts("type:")) {
            std::vector<Token> words = tokens(line, 5);
            if (words.empty()) fail(6, "'type:' needs a curve type");
            if (levels_.empty()) fail(1, "'type:' must follow a 'points:' line");
            if (levels_.size() == 1) curve_.type = curveType(words[0]);
        } else if (line.size() > 2 && line.find(':') == std::string_view::npos) {
            readPoint(line);
        }
        // Other lines (short ones, unknown `label:` lines) are skipped, as cpfg skips them.
    }

    ir::ContourType curveType(const Token& word) const {
        if (word.text == "bezier-surface")
            fail(word.col, "bezier-surface contours are not supported as curves (curveX/curveY/curveZ)");
        if (word.text == "bezier") return ir::ContourType::Bezier;
        if (word.text == "bspline-phantom") return ir::ContourType::BSplinePhantom;
        if (word.text == "bspline-endpoint") return ir::ContourType::BSplineEndpoint;
        if (word.text == "bspline-closed") return ir::ContourType::BSplineClosed;
        return ir::ContourType::BSpline; // cpfg's fallback for any other word
    }

    void startLevel(long count) {
        if (!levels_.empty() && levels_.back().index < 0)
            fail(1, "a nested 'points:' line must follow the point it belongs to");
        if (levels_.size() >= kMaxLevels) fail(1, "too many nested 'points:' lines");
        if (levels_.empty()) pointsLine_ = lineNumber_;
        levels_.push_back({count, -1, 2});
    }

    void readPoint(std::string_view line) {
        std::vector<Token> words = tokens(line, 0);
        if (words.empty()) return;
        if (levels_.empty()) {
            std::string hint =
                words[0].text == "cver" ? " (this looks like a 'cver' contour, which 'contour:' lines read)" : "";
            fail(words[0].col, "expected a 'points: N' line before the points" + hint);
        }
        size_t given = std::min<size_t>(words.size(), 4);
        if (given != static_cast<size_t>(levels_.back().dimension))
            fail(words[0].col, fmt::format("expected {} numbers per point ('dimension: {}'), found {}",
                                           levels_.back().dimension, levels_.back().dimension, words.size()));
        levels_.back().index += 1;
        while (levels_.back().index >= levels_.back().count) {
            levels_.pop_back();
            if (levels_.empty()) fail(words[0].col, "more points than the 'points:' line declares");
            levels_.back().index += 1;
        }
        int dimension = levels_.back().dimension;
        if (given < static_cast<size_t>(dimension))
            fail(words[0].col, fmt::format("expected {} numbers per point", dimension));
        double v[4] = {0, 0, 0, 1};
        for (int i = 0; i < dimension; ++i)
            if (!toNumber(words[static_cast<size_t>(i)].text, v[i]))
                fail(words[static_cast<size_t>(i)].col,
                     fmt::format("expected a number, found '{}'", words[static_cast<size_t>(i)].text));
        if (levels_.size() != 1) return;
        ir::ContourPoint p;
        p.x = v[0];
        p.y = v[1];
        if (dimension > 2) p.z = v[2];
        if (dimension > 3) {
            if (!(v[3] >= 0 && v[3] < static_cast<double>(kMaxMultiplicity + 1))) // NaN too
                fail(words[3].col, fmt::format("multiplicity must be from 0 to {}", kMaxMultiplicity));
            p.multiplicity = static_cast<int>(v[3]); // cpfg truncates
        }
        curve_.points.push_back(p);
    }

    std::string path_;
    int lineNumber_ = 0;
    int pointsLine_ = 0; // the line of the curve's own `points:`
    ir::ContourCurve curve_;
    std::vector<Level> levels_;
};

} // namespace

ir::ContourCurve parseContourFile(const std::string& path) {
    return ContourReader(path).read();
}

} // namespace simeco::lang
