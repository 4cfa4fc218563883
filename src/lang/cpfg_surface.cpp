#include "lang/cpfg_surface.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "ir/source_loc.h"
#include "lang/source_text.h"

namespace simeco::lang {

namespace {

using Point = std::array<double, 3>;

Point operator-(const Point& a, const Point& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
Point operator+(const Point& a, const Point& b) { return {a[0] + b[0], a[1] + b[1], a[2] + b[2]}; }
Point operator*(double s, const Point& a) { return {s * a[0], s * a[1], s * a[2]}; }
Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
double length(const Point& a) { return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]); }

// Far above any model's patches (cpfg allows 64 per surface), far below what exhausts memory.
constexpr size_t kMostPatches = 4096;

struct Token {
    std::string text;
    int line = 0, col = 0;
};

// Words separated by white space, a word also ending after a colon (`X:0.5` is `X:` and `0.5`).
std::vector<Token> tokenize(const std::string& text) {
    std::vector<Token> tokens;
    int line = 1, col = 1;
    Token current;
    auto finish = [&] {
        if (!current.text.empty()) tokens.push_back(current);
        current = {};
    };
    for (char c : text) {
        if (c == '\n' || c == ' ' || c == '\t' || c == '\r') {
            finish();
        } else {
            if (current.text.empty()) current.line = line, current.col = col;
            current.text += c;
            if (c == ':') finish();
        }
        if (c == '\n') ++line, col = 1;
        else ++col;
    }
    finish();
    return tokens;
}

class SurfaceReader {
public:
    SurfaceReader(const std::string& text, const std::string& file) : tokens_(tokenize(text)), file_(file) {}

    bool atEnd() const { return next_ >= tokens_.size(); }
    bool peekIs(std::string_view word) const { return !atEnd() && tokens_[next_].text == word; }

    [[noreturn]] void fail(const std::string& message) const {
        if (atEnd()) {
            const int line = tokens_.empty() ? 1 : tokens_.back().line + 1;
            throw ir::InputError({file_, line, 1}, message + ", found the end of the file");
        }
        const Token& t = tokens_[next_];
        throw ir::InputError({file_, t.line, t.col}, fmt::format("{}, found '{}'", message, t.text));
    }

    void expect(std::string_view word, const char* context) {
        if (!peekIs(word)) fail(fmt::format("expected '{}' {}", word, context));
        ++next_;
    }

    std::string word(const char* what) {
        if (atEnd()) fail(fmt::format("expected {}", what));
        return tokens_[next_++].text;
    }

    double number(const char* what) {
        if (atEnd()) fail(fmt::format("expected a number for {}", what));
        const std::string& text = tokens_[next_].text;
        try {
            size_t used = 0;
            const double v = std::stod(text, &used);
            if (used == text.size() && std::isfinite(v)) {
                ++next_;
                return v;
            }
        } catch (...) {
        }
        fail(fmt::format("expected a finite number for {}", what));
    }

    // `LABEL X: x Y: y Z: z` after the label's words.
    Point labelledPoint(const char* what) {
        Point p{};
        static constexpr const char* kAxes[] = {"X:", "Y:", "Z:"};
        for (int k = 0; k < 3; ++k) {
            expect(kAxes[k], fmt::format("in the {}", what).c_str());
            p[k] = number(what);
        }
        return p;
    }

private:
    std::vector<Token> tokens_;
    std::string file_;
    size_t next_ = 0;
};

using ControlPoints = std::array<std::array<Point, 4>, 4>; // [row i: s][column j: t]

// The four cubic Bernstein polynomials at u, and their derivatives.
std::array<double, 4> bernstein(double u) {
    const double v = 1.0 - u;
    return {v * v * v, 3.0 * u * v * v, 3.0 * u * u * v, u * u * u};
}
std::array<double, 4> bernsteinSlope(double u) {
    const double v = 1.0 - u;
    return {-3.0 * v * v, 3.0 * v * v - 6.0 * u * v, 6.0 * u * v - 3.0 * u * u, 3.0 * u * u};
}

Point patchPoint(const ControlPoints& p, const std::array<double, 4>& bs, const std::array<double, 4>& bt) {
    Point out{};
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) out = out + (bs[i] * bt[j]) * p[i][j];
    return out;
}

// cpfg's surface frame (x its left, y its heading, z its up) to the turtle's leaf frame (x heading, y left, z up,
// simeco's up being cpfg's reversed).
std::array<float, 3> leafFrame(const Point& p) {
    return {static_cast<float>(p[1]), static_cast<float>(p[0]), static_cast<float>(-p[2])};
}

} // namespace

ir::SurfaceModel parseCpfgSurface(const std::string& text, const std::string& file, float size, int sSteps,
                                  int tSteps) {
    SurfaceReader in(text, file);
    for (int k = 0; k < 6; ++k) in.number("the surface's extent"); // its bounds, which cpfg reads and ignores
    int fileSteps = kSurfaceDefaultSteps;
    if (in.peekIs("PRECISION")) {
        in.expect("PRECISION", "");
        in.expect("S:", "in the precision");
        // Held within the range before the cast: a precision past int's range is a file's, not undefined.
        fileSteps = static_cast<int>(std::clamp(in.number("the S precision"), 0.0, double{kSurfaceMostSteps}));
        in.expect("T:", "in the precision");
        in.number("the T precision"); // cpfg takes the S precision for both
    }
    // cpfg's order: the view's steps, else the file's S steps for both, held within 1..10.
    auto steps = [&](int given) { return std::clamp(given != 0 ? given : fileSteps, 1, kSurfaceMostSteps); };
    const int sCount = steps(sSteps), tCount = steps(tSteps);

    in.expect("CONTACT", "(the surface's CONTACT POINT)");
    in.expect("POINT", "after CONTACT");
    const Point contact = in.labelledPoint("contact point");
    in.expect("END", "(the surface's END POINT)");
    in.expect("POINT", "after END");
    const Point end = in.labelledPoint("end point");
    in.expect("HEADING", "(the surface's HEADING)");
    Point heading = in.labelledPoint("heading");
    in.expect("UP", "(the surface's UP)");
    Point up = in.labelledPoint("up vector");
    in.expect("SIZE:", "(the surface's SIZE)");
    const double largest = in.number("the surface's size");
    if (!(largest > 0.0)) in.fail("a surface's SIZE is positive");
    if (!(length(heading) > 0.0) || !(length(up) > 0.0)) in.fail("a surface's HEADING and UP are not zero");
    heading = (1.0 / length(heading)) * heading;
    up = (1.0 / length(up)) * up;
    // As cpfg: left = heading x up, then up = left x heading, neither normalized again.
    const Point left = cross(heading, up);
    up = cross(left, heading);
    const double scale = static_cast<double>(size) / largest;
    auto place = [&](const Point& p) {
        const Point q = scale * (p - contact);
        return q[0] * left + q[1] * heading + q[2] * up;
    };

    ir::SurfaceModel model;
    model.mesh.file = file;
    const Point endPoint = place(end);
    model.endPoint = leafFrame(endPoint);
    while (!in.atEnd()) {
        if (model.mesh.normals.size() / (2u * sCount * tCount) >= kMostPatches)
            in.fail(fmt::format("a surface has at most {} patches", kMostPatches));
        in.word("a patch name");
        in.expect("TOP", "(the patch's TOP COLOR)");
        in.expect("COLOR:", "after TOP");
        in.number("the top colour");
        in.expect("DIFFUSE:", "after the top colour");
        in.number("the top diffuse");
        in.expect("BOTTOM", "(the patch's BOTTOM COLOR)");
        in.expect("COLOR:", "after BOTTOM");
        in.number("the bottom colour");
        in.expect("DIFFUSE:", "after the bottom colour");
        in.number("the bottom diffuse");
        // The neighbours, whose only use in cpfg is smoothing normals across the patches' shared edges.
        for (const char* label : {"AL:", "A:", "AR:", "L:", "R:", "BL:", "B:", "BR:"}) {
            in.expect(label, "among the patch's neighbours");
            in.word("a neighbour's name or ~");
        }
        ControlPoints points{};
        for (auto& row : points)
            for (Point& p : row) {
                Point raw{};
                for (double& c : raw) c = in.number("a control point");
                p = place(raw);
            }
        // The grid of points and normals, s along the rows of control points and t along each row.
        std::vector<Point> grid, normals;
        for (int s = 0; s <= sCount; ++s)
            for (int t = 0; t <= tCount; ++t) {
                const double u = double(s) / sCount, v = double(t) / tCount;
                grid.push_back(patchPoint(points, bernstein(u), bernstein(v)));
                normals.push_back(cross(patchPoint(points, bernsteinSlope(u), bernstein(v)),
                                        patchPoint(points, bernstein(u), bernsteinSlope(v))));
            }
        auto at = [&](int s, int t) { return size_t(s) * size_t(tCount + 1) + size_t(t); };
        for (int s = 0; s < sCount; ++s)
            for (int t = 0; t < tCount; ++t)
                for (const std::array<size_t, 3>& tri : {std::array{at(s, t), at(s + 1, t), at(s + 1, t + 1)},
                                                         std::array{at(s, t), at(s + 1, t + 1), at(s, t + 1)}}) {
                    const Point n = cross(grid[tri[1]] - grid[tri[0]], grid[tri[2]] - grid[tri[0]]);
                    const double twice = length(n);
                    const Point face = twice > 0.0 ? (1.0 / twice) * n : Point{0, 0, 1};
                    for (size_t corner : tri) {
                        model.mesh.corners.push_back(leafFrame(grid[corner]));
                        // A corner where the patch folds to a point has no normal of its own: its face's.
                        const Point& smooth = normals[corner];
                        const double l = length(smooth);
                        Point unit = l > 1e-12 ? (1.0 / l) * smooth : face;
                        if (unit[0] * face[0] + unit[1] * face[1] + unit[2] * face[2] < 0.0) unit = -1.0 * unit;
                        model.mesh.cornerNormals.push_back(leafFrame(unit));
                    }
                    model.mesh.normals.push_back(leafFrame(face));
                    model.mesh.area += static_cast<float>(0.5 * twice);
                }
    }
    if (model.mesh.normals.empty()) in.fail("a surface has at least one patch");
    // In units of its reach, as the renderer's bounds of a model take it.
    float reach = 0.0f;
    for (const auto& c : model.mesh.corners) reach = std::max(reach, std::hypot(c[0], c[1], c[2]));
    model.reach = reach > 0.0f ? reach : 1.0f;
    for (auto& c : model.mesh.corners)
        for (float& x : c) x /= model.reach;
    model.mesh.area /= model.reach * model.reach;
    return model;
}

ir::SurfaceModel readCpfgSurface(const std::string& path, float size, int sSteps, int tSteps) {
    return parseCpfgSurface(readSourceFile(path), path, size, sSteps, tSteps);
}

} // namespace simeco::lang
