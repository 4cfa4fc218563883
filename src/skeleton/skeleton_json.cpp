#include "skeleton/skeleton_json.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "ir/source_loc.h"

namespace simeco::skeleton {

namespace {

using nlohmann::json;

std::string number(double v) { return fmt::format("{:.9g}", v); }

std::string point(const glm::dvec3& p) { return fmt::format("[{}, {}, {}]", number(p.x), number(p.y), number(p.z)); }

std::string stemJson(const Stem& s) {
    std::string out = fmt::format("        {{\"id\": {}, \"parent\": {}, \"attach\": {}, \"width\": {}", s.id, s.parent,
                                  s.attach, number(s.width));
    if (!s.widths.empty()) {
        out += ", \"widths\": [";
        for (size_t k = 0; k < s.widths.size(); ++k) out += (k ? ", " : "") + number(s.widths[k]);
        out += "]";
    }
    out += ",\n         \"points\": [";
    for (size_t k = 0; k < s.points.size(); ++k) out += (k ? ",\n                    " : "") + point(s.points[k]);
    return out + "]}";
}

std::string organJson(const Organ& o) {
    return fmt::format("        {{\"kind\": \"{}\", \"stem\": {}, \"point\": {}, \"position\": {}, \"heading\": {}, "
                       "\"size\": {}}}",
                       organKindName(o.kind), o.stem, o.point, point(o.position), point(o.heading), number(o.size));
}

// Reading: every value is looked up through a Reader that knows its place in the document.
class Reader {
public:
    Reader(const json& value, std::string pointer, const std::string& file)
        : value_(value), pointer_(std::move(pointer)), file_(file) {}

    [[noreturn]] void fail(const std::string& message) const {
        throw ir::InputError({file_, 0, 0}, fmt::format("{}: {}", pointer_.empty() ? "/" : pointer_, message));
    }
    bool has(const char* key) const { return value_.is_object() && value_.contains(key); }
    Reader at(const char* key) const {
        if (!value_.is_object()) fail("expected an object");
        if (!value_.contains(key)) fail(fmt::format("missing \"{}\"", key));
        return {value_.at(key), pointer_ + "/" + key, file_};
    }
    std::vector<Reader> items() const {
        if (!value_.is_array()) fail("expected an array");
        std::vector<Reader> out;
        for (size_t k = 0; k < value_.size(); ++k)
            out.push_back({value_[k], pointer_ + "/" + std::to_string(k), file_});
        return out;
    }
    double number() const {
        if (!value_.is_number()) fail("expected a number");
        double v = value_.get<double>();
        if (!std::isfinite(v)) fail("the number is not finite");
        return v;
    }
    int integer() const {
        double v = number();
        if (v != std::floor(v) || std::abs(v) > 1e9) fail("expected a whole number");
        return static_cast<int>(v);
    }
    std::string text() const {
        if (!value_.is_string()) fail("expected a string");
        return value_.get<std::string>();
    }
    glm::dvec3 vector() const {
        std::vector<Reader> xyz = items();
        if (xyz.size() != 3) fail("expected [x, y, z]");
        return {xyz[0].number(), xyz[1].number(), xyz[2].number()};
    }

private:
    const json& value_;
    std::string pointer_;
    const std::string& file_;
};

Stem readStem(const Reader& r) {
    Stem s;
    s.id = r.at("id").integer();
    s.parent = r.has("parent") ? r.at("parent").integer() : -1;
    s.attach = r.has("attach") ? r.at("attach").integer() : -1;
    s.width = r.has("width") ? r.at("width").number() : 0.0;
    if (s.width < 0.0) r.at("width").fail("a width is not negative");
    for (const Reader& p : r.at("points").items()) s.points.push_back(p.vector());
    if (r.has("widths")) {
        for (const Reader& w : r.at("widths").items()) s.widths.push_back(w.number());
        if (s.widths.size() + 1 != s.points.size())
            r.at("widths").fail(fmt::format("expected one width per segment ({})", s.points.size() - 1));
    }
    return s;
}

Organ readOrgan(const Reader& r) {
    Organ o;
    std::string kind = r.at("kind").text();
    if (kind == "leaf") o.kind = OrganKind::Leaf;
    else if (kind == "flower") o.kind = OrganKind::Flower;
    else if (kind == "fruit") o.kind = OrganKind::Fruit;
    else r.at("kind").fail(fmt::format("unknown organ '{}' (expected leaf, flower or fruit)", kind));
    o.stem = r.at("stem").integer();
    o.point = r.at("point").integer();
    o.position = r.at("position").vector();
    if (r.has("heading")) o.heading = r.at("heading").vector();
    if (r.has("size")) o.size = r.at("size").number();
    return o;
}

// The line and column of byte `offset` of `text` (both from 1).
ir::SourceLoc locationOf(const std::string& text, size_t offset, const std::string& file) {
    ir::SourceLoc loc{file, 1, 1};
    for (size_t k = 0; k < offset && k < text.size(); ++k) {
        if (text[k] == '\n') {
            ++loc.line;
            loc.col = 1;
        } else {
            ++loc.col;
        }
    }
    return loc;
}

} // namespace

std::string skeletonJson(const Skeleton& skeleton) {
    std::string out = "{\n  \"format\": \"simeco skeleton\",\n  \"version\": 1,\n";
    out += "  \"source\": " + json(skeleton.source).dump() + ",\n  \"plants\": [\n";
    for (size_t p = 0; p < skeleton.plants.size(); ++p) {
        const Plant& plant = skeleton.plants[p];
        out += "    {\n      \"stems\": [\n";
        for (size_t k = 0; k < plant.stems.size(); ++k) out += (k ? ",\n" : "") + stemJson(plant.stems[k]);
        out += "\n      ],\n      \"organs\": [\n";
        for (size_t k = 0; k < plant.organs.size(); ++k) out += (k ? ",\n" : "") + organJson(plant.organs[k]);
        out += fmt::format("\n      ]\n    }}{}\n", p + 1 < skeleton.plants.size() ? "," : "");
    }
    return out + "  ]\n}\n";
}

Skeleton parseSkeletonJson(const std::string& text, const std::string& file) {
    json document;
    try {
        document = json::parse(text);
    } catch (const json::parse_error& e) {
        // "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error ..." without its prefix
        std::string message = e.what();
        size_t colon = message.find(": ");
        if (colon != std::string::npos) message = message.substr(colon + 2);
        throw ir::InputError(locationOf(text, e.byte > 0 ? e.byte - 1 : 0, file), message);
    } catch (const json::exception& e) { // a number too large for a double
        std::string message = e.what();
        size_t end = message.find("] ");
        throw ir::InputError({file, 0, 0}, end == std::string::npos ? message : message.substr(end + 2));
    }
    Reader root(document, "", file);
    Skeleton skeleton;
    if (root.has("source")) skeleton.source = root.at("source").text();
    for (const Reader& p : root.at("plants").items()) {
        Plant plant;
        for (const Reader& s : p.at("stems").items()) plant.stems.push_back(readStem(s));
        if (p.has("organs"))
            for (const Reader& o : p.at("organs").items()) plant.organs.push_back(readOrgan(o));
        skeleton.plants.push_back(std::move(plant));
    }
    return skeleton;
}

Skeleton readSkeletonJson(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ir::InputError({path, 0, 0}, "cannot open the skeleton file");
    std::stringstream text;
    text << in.rdbuf();
    return parseSkeletonJson(text.str(), path);
}

} // namespace simeco::skeleton
