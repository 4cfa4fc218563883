#include "lang/cpfg_view.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <sstream>

#include <fmt/format.h>
#include <unistd.h>

#include "lang/color_map.h"
#include "lang/cpfg_contour.h"
#include "lang/cpfg_cylinder_contour.h"
#include "lang/cpfg_surface.h"
#include "lang/source_text.h"

namespace simeco::lang {

namespace {

std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        lines.push_back(line);
    }
    return lines;
}

std::string trim(const std::string& s) {
    size_t a = s.find_first_not_of(" \t");
    if (a == std::string::npos) return {};
    size_t b = s.find_last_not_of(" \t");
    return s.substr(a, b - a + 1);
}

// `key: value` with the key compared case-insensitively; returns the value.
bool field(const std::string& line, const char* key, std::string& value) {
    size_t colon = line.find(':');
    if (colon == std::string::npos) return false;
    std::string k = trim(line.substr(0, colon));
    for (char& c : k) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (k != key) return false;
    value = trim(line.substr(colon + 1));
    return true;
}

float number(const std::string& text, const std::string& file, size_t line, const char* what) {
    try {
        size_t used = 0;
        float v = std::stof(text, &used);
        return v;
    } catch (...) {
        throw ir::InputError({file, static_cast<int>(line + 1), 1}, fmt::format("expected a number for {}", what));
    }
}

// Limits on the counts a view's files give: far above any model's, far below what exhausts memory.
constexpr long kMostSamples = 1 << 20;
constexpr long kMostControlPoints = 1 << 16;
// Sampling a function evaluates its curve up to 200 times a sample (a bisection that a curve doubling back on
// itself keeps from converging), and a contour curve once, each time over its control points: their product
// bounds the work (at most about a quarter of a second), which either bound alone does not. The corpus's largest
// product is 400.
constexpr uint64_t kMostSampledPoints = 1 << 17;
constexpr long kMostFunctions = 4096;
constexpr long kMostContourId = 1 << 16;
constexpr long kMostContourSides = 512;

// The file a view line names, in the view's folder; when it cannot be opened, the error points at that line.
std::string namedFile(const std::filesystem::path& dir, const std::string& name, const std::string& view,
                      const std::string& line, size_t index, const char* what) {
    std::filesystem::path file = dir / name;
    std::error_code error;
    if (name.empty() || !std::filesystem::is_regular_file(file, error) || ::access(file.c_str(), R_OK) != 0) {
        size_t at = name.empty() ? std::string::npos : line.find(name);
        int col = at == std::string::npos ? 1 : static_cast<int>(at) + 1;
        throw ir::InputError({view, static_cast<int>(index + 1), col},
                             fmt::format("cannot open the {} file '{}' named here", what, file.string()));
    }
    return file.string();
}

// A count read from a file: a whole number within [low, high], else a located error (so that a file cannot ask
// for billions of samples, or overflow an int, before anything is said).
int wholeNumber(const std::string& text, const std::string& file, size_t line, const char* what, long low, long high) {
    float v = number(text, file, line, what);
    if (!(v >= float(low) && v <= float(high)) || v != std::floor(v))
        throw ir::InputError({file, static_cast<int>(line + 1), 1},
                             fmt::format("{} is a whole number from {} to {}, found {}", what, low, high, trim(text)));
    return static_cast<int>(v);
}

// View settings only shape the picture: a value that is not a number keeps the default, with a warning,
// as cpfg reads it (exercise models ship placeholders such as `angle increment: ?`).
void viewNumber(const std::string& text, const std::string& file, size_t line, const char* what, float& value) {
    try {
        value = std::stof(text);
    } catch (...) {
        std::fprintf(stderr, "%s:%zu:1: warning: '%s' is not a number for %s; using %g\n", file.c_str(), line + 1,
                     text.c_str(), what, static_cast<double>(value));
    }
}

void readFunctionSet(const std::string& path, CpfgView& out) {
    std::vector<std::string> lines = splitLines(readSourceFile(path));
    size_t next = 0;
    if (lines.empty() || trim(lines[0]).rfind("funcgalleryver", 0) != 0)
        throw ir::InputError({path, 1, 1}, "expected 'funcgalleryver 1 1' at the start of a function set");
    next = 1;
    std::string value;
    if (next >= lines.size() || !field(lines[next], "items", value))
        throw ir::InputError({path, static_cast<int>(next + 1), 1}, "expected 'items: N'");
    int items = wholeNumber(value, path, next, "items", 0, kMostFunctions);
    ++next;
    for (int i = 0; i < items; ++i) {
        ir::FunctionCurve f = parseFunctionCurve(lines, next, path, -1);
        // cpfg defines NAME=id for each function of a set, so models can write func(NAME, x).
        std::string name = f.name;
        if (size_t dot = name.rfind('.'); dot != std::string::npos) name = name.substr(0, dot);
        out.functions.push_back(std::move(f));
        if (!name.empty()) out.macros[name] = std::to_string(out.functions.size());
    }
}

std::string firstWord(const std::string& text) {
    std::istringstream in(text);
    std::string word;
    in >> word;
    return word;
}

// The style word after `initial line width: x`: pixels (`p`, `pixel`, `pixels`), shaded cylinders (`s`,
// `shaded`), else cpfg's polygons in world units.
ir::LineStyle lineWidthStyle(const std::string& value) {
    std::istringstream in(value);
    std::string number, style;
    in >> number >> style;
    if (style == "p" || style == "pixel" || style == "pixels") return ir::LineStyle::Pixel;
    if (style == "s" || style == "shaded") return ir::LineStyle::Cylinder;
    return ir::LineStyle::Polygon;
}

// `line style: pixel | polygon | cylinder` (cpfg's `wireframe` draws lines, as `pixel`); another word keeps `was`.
ir::LineStyle lineStyleNamed(const std::string& word, ir::LineStyle was) {
    if (word == "pixel" || word == "wireframe") return ir::LineStyle::Pixel;
    if (word == "polygon") return ir::LineStyle::Polygon;
    if (word == "cylinder") return ir::LineStyle::Cylinder;
    return was;
}

// `x,y,z` or `x y z`.
void readVector(std::string text, const std::string& file, size_t line, const char* what, std::array<float, 3>& v) {
    for (char& c : text)
        if (c == ',') c = ' ';
    std::istringstream in(text);
    std::array<float, 3> read{};
    if (!(in >> read[0] >> read[1] >> read[2])) {
        std::fprintf(stderr, "%s:%zu:1: warning: expected three numbers for %s; using the default\n", file.c_str(),
                     line + 1, what);
        return;
    }
    v = read;
}

// In a `tropism:` or `torque:` line, the text after `key` (such as `T:`) up to the next `X:` key.
std::string movementField(const std::string& text, const char* key) {
    size_t at = text.find(key);
    if (at == std::string::npos) return {};
    size_t end = at + 2;
    while (end < text.size() &&
           !(std::isupper(static_cast<unsigned char>(text[end])) && end + 1 < text.size() && text[end + 1] == ':'))
        ++end;
    return text.substr(at + 2, end - at - 2);
}

// `tropism: T: x,y,z [I: intensity] [A: degrees] [E: elasticity] [S: step]`. cpfg turns the heading toward the sum
// of its tropism lines' directions, each times its intensity, elasticity and the cosine of its angle A (a line's
// sine part, diatropism, is not drawn); `view` holds the sum so far as a direction and its length as elasticity.
void readTropism(const std::string& text, const std::string& file, size_t line, ir::ViewSettings& view) {
    auto after = [&](const char* key) { return movementField(text, key); };
    std::array<float, 3> direction = view.tropismDirection;
    float intensity = 1.0f, degrees = 0.0f, elasticity = 0.0f;
    if (std::string t = after("T:"); !t.empty()) readVector(t, file, line, "tropism direction", direction);
    if (std::string i = after("I:"); !i.empty()) viewNumber(i, file, line, "tropism intensity", intensity);
    if (std::string a = after("A:"); !a.empty()) viewNumber(a, file, line, "tropism angle", degrees);
    if (std::string e = after("E:"); !e.empty()) viewNumber(e, file, line, "tropism elasticity", elasticity);
    if (std::string s = after("S:"); !s.empty()) viewNumber(s, file, line, "elasticity step", view.elasticityIncrement);
    const float length = std::hypot(direction[0], direction[1], direction[2]);
    if (!(length > 0.0f)) throw ir::InputError({file, static_cast<int>(line + 1), 1}, "a tropism's T is not zero");
    const float weight = std::clamp(intensity, -1.0f, 1.0f) * elasticity *
                         static_cast<float>(std::cos(degrees * 3.14159265358979 / 180.0)) / length;
    std::array<float, 3> sum{};
    for (int k = 0; k < 3; ++k) sum[k] = weight * direction[k];
    if (view.tropismRule == ir::TropismRule::CpfgTropism) // an earlier tropism line's share
        for (int k = 0; k < 3; ++k) sum[k] += view.initialElasticity * view.tropismDirection[k];
    const float total = std::hypot(sum[0], sum[1], sum[2]);
    for (int k = 0; k < 3; ++k) view.tropismDirection[k] = total > 0.0f ? sum[k] / total : direction[k] / length;
    view.initialElasticity = total;
    view.tropismRule = ir::TropismRule::CpfgTropism;
}

// `torque: T: x,y,z [I: intensity] [E: elasticity] [S: step]`: cpfg rolls the turtle before every move by the sum of
// its torque lines' directions, each times its elasticity; an intensity I makes the direction's length I, at most
// the length T is written with (movements.c).
void readTorque(const std::string& text, const std::string& file, size_t line, ir::ViewSettings& view) {
    std::array<float, 3> direction{};
    float intensity = 0.0f, elasticity = 0.0f;
    if (std::string t = movementField(text, "T:"); !t.empty()) readVector(t, file, line, "torque direction", direction);
    const std::string i = movementField(text, "I:");
    if (!i.empty()) viewNumber(i, file, line, "torque intensity", intensity);
    if (std::string e = movementField(text, "E:"); !e.empty()) viewNumber(e, file, line, "torque elasticity", elasticity);
    const float length = std::hypot(direction[0], direction[1], direction[2]);
    if (!(length > 0.0f)) throw ir::InputError({file, static_cast<int>(line + 1), 1}, "a torque's T is zero");
    const float scale = i.empty() ? 1.0f / length : std::clamp(intensity / length, -1.0f, 1.0f);
    for (int k = 0; k < 3; ++k) view.torque[k] += elasticity * scale * direction[k];
}

} // namespace

ir::FunctionCurve parseFunctionCurve(const std::vector<std::string>& lines, size_t& next, const std::string& file,
                                     int defaultSamples) {
    ir::FunctionCurve f;
    auto fail = [&](const std::string& message) -> void {
        throw ir::InputError({file, static_cast<int>(std::min(next, lines.size()) + 1), 1}, message);
    };
    while (next < lines.size() && trim(lines[next]).empty()) ++next;
    if (next >= lines.size()) fail("expected a function");
    std::string first = trim(lines[next]);
    std::string value;
    if (first.rfind("fver", 0) == 0) {
        ++next;
        while (next < lines.size()) {
            std::string line = trim(lines[next]);
            if (field(line, "name", value)) f.name = value;
            else if (field(line, "samples", value)) f.samples = wholeNumber(value, file, next, "samples", 0, kMostSamples);
            else if (field(line, "points", value)) break;
            ++next; // flip, markers and background lines do not change the values
        }
    } else if (field(first, "range", value)) {
        f.samples = defaultSamples;
        ++next;
    } else {
        fail("expected 'fver 1 1' or 'range:' at the start of a function");
    }
    if (next >= lines.size() || !field(trim(lines[next]), "points", value)) fail("expected 'points: N'");
    int count = wholeNumber(value, file, next, "points", 0, kMostControlPoints);
    if (static_cast<uint64_t>(std::max(f.samples, 0)) * static_cast<uint64_t>(count) > kMostSampledPoints)
        fail(fmt::format("{} samples of {} control points: their product may be at most {}", f.samples, count,
                         kMostSampledPoints));
    ++next;
    if (count < 4) fail("a function needs at least 4 control points");
    for (int i = 0; i < count; ++i, ++next) {
        if (next >= lines.size()) fail("missing control points");
        std::istringstream in(lines[next]);
        float x = 0, y = 0, multiplicity = 1;
        if (!(in >> x >> y)) fail("expected 'x y [multiplicity]'");
        if (!(in >> multiplicity)) multiplicity = 1;
        // Checked as a float first: converting one outside int's range is undefined.
        if (!(multiplicity >= 1 && multiplicity < 17)) fail("multiplicity out of range (1 to 16)");
        int m = static_cast<int>(multiplicity);
        for (int k = 0; k < m; ++k) {
            f.xs.push_back(x);
            f.ys.push_back(y);
        }
    }
    ir::precomputeCurve(f);
    return f;
}

ir::ViewSettings cpfgDefaultView() {
    ir::ViewSettings view;
    view.taperedLines = true;
    view.lineStyle = ir::LineStyle::Pixel;
    view.dollarRolls = false;
    view.undefinedSurfacesDrawn = false;
    view.cpfgCylinders = true;
    return view;
}

namespace {

// A value of one of simeco's own picture lines that is none of those it may take.
[[noreturn]] void lookError(const std::string& file, const std::string& line, size_t index, const char* key,
                            const char* expected) {
    const size_t colon = line.find(':');
    const size_t value = line.find_first_not_of(" \t", colon + 1);
    const size_t column = value == std::string::npos ? colon + 2 : value + 1;
    throw ir::InputError({file, static_cast<int>(index + 1), static_cast<int>(column)},
                         fmt::format("{}: expected {}", key, expected));
}

} // namespace

CpfgView readCpfgView(const std::string& path) {
    CpfgView out;
    std::vector<std::string> lines = splitLines(readSourceFile(path));
    std::filesystem::path dir = std::filesystem::path(path).parent_path();
    for (size_t i = 0; i < lines.size(); ++i) {
        std::string line = trim(lines[i]), value;
        if (field(line, "function", value)) {
            std::istringstream in(value);
            std::string name, count;
            in >> name >> count;
            int samples = count.empty() ? -1 : wholeNumber(count, path, i, "samples", 0, kMostSamples);
            std::string funcPath = namedFile(dir, name, path, lines[i], i, "function");
            std::vector<std::string> funcLines = splitLines(readSourceFile(funcPath));
            size_t next = 0;
            out.functions.push_back(parseFunctionCurve(funcLines, next, funcPath, samples));
        } else if (field(line, "function set", value)) {
            readFunctionSet(namedFile(dir, value, path, lines[i], i, "function set"), out);
        } else if (field(line, "curve", value)) {
            std::istringstream in(value);
            std::string name, count;
            in >> name >> count;
            int samples = count.empty() ? 0 : wholeNumber(count, path, i, "samples", 0, kMostSamples);
            out.curves.push_back(parseContourFile(namedFile(dir, name, path, lines[i], i, "curve")));
            uint64_t points = out.curves.back().xs.size();
            if (samples > 1 && static_cast<uint64_t>(samples) * points > kMostSampledPoints)
                throw ir::InputError({path, static_cast<int>(i + 1), 1},
                                     fmt::format("{} samples of a curve of {} points: their product may be at most {}",
                                                 samples, points, kMostSampledPoints));
            if (samples > 1) ir::sampleContourCurve(out.curves.back(), samples);
        } else if (field(line, "contour", value)) {
            std::istringstream in(value);
            std::string id, name;
            in >> id >> name;
            ir::CylinderContour contour =
                readCylinderContour(namedFile(dir, name, path, lines[i], i, "contour"));
            contour.id = wholeNumber(id, path, i, "contour id", 1, kMostContourId);
            out.view.contours.push_back(std::move(contour));
        } else if (field(line, "contour sides", value)) {
            out.view.cylinderSides = wholeNumber(firstWord(value), path, i, "contour sides", 3, kMostContourSides);
        } else if (field(line, "polygonization level", value)) {
            // cpfg's sides: 2 to the power of the level plus one.
            const int level = wholeNumber(firstWord(value), path, i, "polygonization level", 0, 8);
            out.view.cylinderSides = std::max(3, 1 << (level + 1));
        } else if (field(line, "twist of cylinders", value)) {
            out.view.cylinderTwist = firstWord(value) == "on";
        } else if (field(line, "angle increment", value)) {
            viewNumber(value, path, i, "angle increment", out.view.angleIncrement);
            out.view.present = true;
        } else if (field(line, "angle factor", value)) {
            float factor = 0;
            viewNumber(value, path, i, "angle factor", factor);
            if (factor != 0) out.view.angleIncrement = 360.0f / factor;
            out.view.present = true;
        } else if (field(line, "initial line width", value)) {
            viewNumber(value, path, i, "initial line width", out.view.lineWidth);
            out.view.lineStyle = lineWidthStyle(value);
        } else if (field(line, "line style", value)) {
            out.view.lineStyle = lineStyleNamed(firstWord(value), out.view.lineStyle);
        } else if (field(line, "line width increment", value)) {
            viewNumber(value, path, i, "line width increment", out.view.widthIncrement);
        } else if (field(line, "color increment", value)) {
            viewNumber(value, path, i, "color increment", out.view.colorIncrement);
        } else if (field(line, "initial color", value)) {
            viewNumber(firstWord(value), path, i, "initial color", out.view.initialColor);
        } else if (field(line, "tapered lines", value)) {
            out.view.taperedLines = firstWord(value) != "off";
        } else if (field(line, "tropism direction", value)) {
            readVector(value, path, i, "tropism direction", out.view.tropismDirection);
            out.view.tropismRule = ir::TropismRule::CpfgDirection;
        } else if (field(line, "initial elasticity", value)) {
            viewNumber(value, path, i, "initial elasticity", out.view.initialElasticity);
            out.view.tropismRule = ir::TropismRule::CpfgDirection;
        } else if (field(line, "light", value) || field(line, "light direction", value)) {
            // The first directional light, `light: V: x,y,z ...` or the older `light direction: x,y,z`.
            const size_t v = value.find("V:");
            const bool older = value.find(':') == std::string::npos;
            if (!out.view.look.sunDirection && (older || v != std::string::npos)) {
                std::string vector = older ? value : value.substr(v + 2);
                if (const size_t next = vector.find_first_of("AODSTC"); next != std::string::npos) vector.resize(next);
                std::array<float, 3> d{};
                readVector(vector, path, i, "light direction", d);
                const float length = std::hypot(d[0], d[1], d[2]);
                if (length > 0.0f) out.view.look.sunDirection = std::array{d[0] / length, d[1] / length, d[2] / length};
            }
        } else if (field(line, "initial scale", value)) {
            viewNumber(value, path, i, "initial scale", out.view.initialScale);
            if (out.view.initialScale == 0.0f) out.view.initialScale = 1.0f; // as cpfg: a scale of 0 is taken as 1
        } else if (field(line, "elasticity increment", value)) {
            viewNumber(value, path, i, "elasticity increment", out.view.elasticityIncrement);
        } else if (field(line, "tropism", value)) {
            readTropism(value, path, i, out.view);
        } else if (field(line, "torque", value)) {
            readTorque(value, path, i, out.view);
        } else if (field(line, "viewpoint", value)) {
            std::array<float, 3> point{0, 0, 1};
            readVector(value, path, i, "viewpoint", point);
            out.view.look.viewpoint = point;
        } else if (field(line, "view reference point", value)) {
            std::array<float, 3> point{};
            readVector(value, path, i, "view reference point", point);
            out.view.look.viewReferencePoint = point;
        } else if (field(line, "projection", value)) {
            const std::string word = firstWord(value);
            if (word != "parallel" && word != "perspective")
                lookError(path, lines[i], i, "projection", "parallel or perspective");
            out.view.look.parallel = word == "parallel";
        } else if (field(line, "render style", value)) {
            out.view.look.style = ir::pictureStyleNamed(firstWord(value));
            if (!out.view.look.style) lookError(path, lines[i], i, "render style", "lit, toon, outline or paper-cut");
        } else if (field(line, "shadows", value)) {
            const std::string word = firstWord(value);
            if (word != "volume" && word != "none") lookError(path, lines[i], i, "shadows", "volume or none");
            out.view.look.shadows = word == "volume";
        } else if (field(line, "ground", value)) {
            const std::string word = firstWord(value);
            if (word != "on" && word != "off") lookError(path, lines[i], i, "ground", "on or off");
            out.view.look.ground = word == "on";
        } else if (field(line, "background", value)) {
            out.view.look.background = backgroundNamed(firstWord(value));
            if (!out.view.look.background)
                lookError(path, lines[i], i, "background", "sky, paper, colormap or a colour #rrggbb");
        } else if (field(line, "surface", value)) {
            // `surface: id file.s size [s-steps t-steps [texture]]`, or `id file.s size texture`.
            std::istringstream in(value);
            ir::ViewSettings::Surface surface;
            in >> surface.name >> surface.file;
            if (!(in >> surface.scale) || !(surface.scale > 0.0f)) surface.scale = 1.0f;
            int sSteps = 0, tSteps = 0;
            if (!(in >> sSteps >> tSteps)) sSteps = tSteps = 0;
            if (surface.name.empty()) continue;
            if (std::filesystem::path(surface.file).extension() == ".s")
                surface.model = std::make_shared<const ir::SurfaceModel>(
                    readCpfgSurface(namedFile(dir, surface.file, path, lines[i], i, "surface"), surface.scale,
                                    sSteps, tSteps));
            out.view.surfaces.push_back(surface);
        }
    }
    return out;
}

} // namespace simeco::lang
