#include "skeleton/skeleton_obj.h"

#include <charconv>
#include <cmath>
#include <string_view>

#include <fmt/format.h>

#include "ir/source_loc.h"
#include "skeleton/json_reader.h"
#include "skeleton/skeleton_check.h"
#include "skeleton/stem_parents.h"

namespace simeco::skeleton {

namespace {

struct Token {
    std::string_view text;
    int col = 0; // from 1
};

// The words of one line, up to a `#` comment.
std::vector<Token> words(std::string_view line) {
    std::vector<Token> out;
    size_t k = 0;
    auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; };
    while (k < line.size() && line[k] != '#') {
        if (space(line[k])) {
            ++k;
            continue;
        }
        size_t start = k;
        while (k < line.size() && !space(line[k]) && line[k] != '#')
            ++k;
        out.push_back({line.substr(start, k - start), int(start) + 1});
    }
    return out;
}

// A vertex index as the file gives it, checked against the vertex count once the whole file is read (an `l` may
// name vertices defined after it).
struct VertexRef {
    long index = 0; // from 1
    int line = 0, col = 0;
};

struct LineElement {
    std::vector<VertexRef> vertices;
};

class ObjReader {
public:
    ObjReader(const std::string& text, const std::string& file) : text_(text), file_(file) {}

    Skeleton read() {
        int lineNo = 0;
        for (size_t start = 0; start <= text_.size();) {
            size_t end = text_.find('\n', start);
            if (end == std::string::npos) end = text_.size();
            ++lineNo;
            statement(std::string_view(text_).substr(start, end - start), lineNo);
            start = end + 1;
        }
        if (lines_.empty()) fail(0, 0, "the file has no line elements ('l i j ...'): there are no stems to read");

        Plant plant;
        for (size_t k = 0; k < lines_.size(); ++k) {
            Stem s;
            s.id = int(k);
            for (const VertexRef& v : lines_[k].vertices) {
                if (v.index > long(vertices_.size()))
                    fail(v.line, v.col,
                         fmt::format("vertex {} does not exist: the file has {} vertices", v.index, vertices_.size()));
                s.points.push_back(vertices_[size_t(v.index - 1)]);
            }
            plant.stems.push_back(std::move(s));
        }
        linkStemsByGeometry(plant, samePointTolerance(plantSize(plant)));
        Skeleton skeleton;
        skeleton.source = file_;
        skeleton.plants.push_back(std::move(plant));
        return skeleton;
    }

private:
    const std::string& text_;
    const std::string& file_;
    std::vector<glm::dvec3> vertices_;
    std::vector<LineElement> lines_;

    [[noreturn]] void fail(int line, int col, const std::string& message) const {
        throw ir::InputError({file_, line, col}, message);
    }

    void statement(std::string_view text, int line) {
        std::vector<Token> w = words(text);
        if (w.empty()) return;
        if (w[0].text == "v")
            vertex(w, line);
        else if (w[0].text == "l")
            lineElement(w, line);
    }

    void vertex(const std::vector<Token>& w, int line) {
        if (w.size() < 4) fail(line, w[0].col, "a vertex needs three coordinates: 'v x y z'");
        glm::dvec3 p{number(w[1], line), number(w[2], line), number(w[3], line)};
        for (size_t k = 4; k < w.size(); ++k)
            number(w[k], line); // a weight or a colour: checked, not kept
        vertices_.push_back(p);
    }

    void lineElement(const std::vector<Token>& w, int line) {
        if (w.size() < 3) fail(line, w[0].col, "a line element needs two or more vertices: 'l i j ...'");
        LineElement element;
        for (size_t k = 1; k < w.size(); ++k)
            element.vertices.push_back(vertexRef(w[k], line));
        lines_.push_back(std::move(element));
    }

    double number(const Token& t, int line) const {
        std::string_view s = t.text;
        // from_chars takes no '+', which some exporters write
        if (s.size() > 1 && s[0] == '+' && s[1] != '-') s.remove_prefix(1);
        double v = 0.0;
        auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (error != std::errc() || end != s.data() + s.size() || !std::isfinite(v))
            fail(line, t.col, fmt::format("'{}' is not a finite number", t.text));
        return v;
    }

    VertexRef vertexRef(const Token& t, int line) const {
        std::string_view s = t.text.substr(0, t.text.find('/')); // `i/t`: the vertex index only
        long v = 0;
        auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
        if (s.empty() || error != std::errc() || end != s.data() + s.size())
            fail(line, t.col, fmt::format("'{}' is not a vertex index", t.text));
        if (v == 0) fail(line, t.col, "vertex index 0 does not exist: indices count from 1");
        if (v < 0) {
            long resolved = long(vertices_.size()) + v + 1;
            if (resolved < 1)
                fail(line, t.col,
                     fmt::format("vertex index {} counts back past the first vertex: {} vertices come "
                                 "before it",
                                 v, vertices_.size()));
            v = resolved;
        }
        return {v, line, t.col};
    }
};

} // namespace

Skeleton parseObjSkeleton(const std::string& text, const std::string& file) {
    return ObjReader(text, file).read();
}

Skeleton readObjSkeleton(const std::string& path) {
    return parseObjSkeleton(readWholeFile(path, "OBJ file"), path);
}

std::string skeletonObj(const Plant& plant, const std::string& comment) {
    std::string out = "# " + comment + "\n";
    for (const Stem& s : plant.stems)
        for (const glm::dvec3& p : s.points) out += fmt::format("v {:.9g} {:.9g} {:.9g}\n", p.x, p.y, p.z);
    size_t first = 1;
    for (const Stem& s : plant.stems) {
        out += "l";
        for (size_t k = 0; k < s.points.size(); ++k) out += fmt::format(" {}", first + k);
        out += "\n";
        first += s.points.size();
    }
    return out;
}

} // namespace simeco::skeleton
