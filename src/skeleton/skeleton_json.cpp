#include "skeleton/skeleton_json.h"

#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "ir/source_loc.h"
#include "skeleton/json_reader.h"

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


Stem readStem(const JsonReader& r) {
    Stem s;
    s.id = r.at("id").integer();
    s.parent = r.has("parent") ? r.at("parent").integer() : -1;
    s.attach = r.has("attach") ? r.at("attach").integer() : -1;
    s.width = r.has("width") ? r.at("width").number() : 0.0;
    if (s.width < 0.0) r.at("width").fail("a width is not negative");
    for (const JsonReader& p : r.at("points").items()) s.points.push_back(p.point3());
    if (r.has("widths")) {
        for (const JsonReader& w : r.at("widths").items()) s.widths.push_back(w.number());
        if (s.widths.size() + 1 != s.points.size())
            r.at("widths").fail(fmt::format("expected one width per segment ({})", s.points.size() - 1));
    }
    return s;
}

Organ readOrgan(const JsonReader& r) {
    Organ o;
    std::string kind = r.at("kind").text();
    if (kind == "leaf") o.kind = OrganKind::Leaf;
    else if (kind == "flower") o.kind = OrganKind::Flower;
    else if (kind == "fruit") o.kind = OrganKind::Fruit;
    else r.at("kind").fail(fmt::format("unknown organ '{}' (expected leaf, flower or fruit)", kind));
    o.stem = r.at("stem").integer();
    o.point = r.at("point").integer();
    o.position = r.at("position").point3();
    if (r.has("heading")) o.heading = r.at("heading").point3();
    if (r.has("size")) o.size = r.at("size").number();
    return o;
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
    const json document = parseJsonDocument(text, file);
    JsonReader root(document, "", file);
    Skeleton skeleton;
    if (root.has("source")) skeleton.source = root.at("source").text();
    for (const JsonReader& p : root.at("plants").items()) {
        Plant plant;
        for (const JsonReader& s : p.at("stems").items()) plant.stems.push_back(readStem(s));
        if (p.has("organs"))
            for (const JsonReader& o : p.at("organs").items()) plant.organs.push_back(readOrgan(o));
        skeleton.plants.push_back(std::move(plant));
    }
    return skeleton;
}

Skeleton readSkeletonJson(const std::string& path) {
    return parseSkeletonJson(readWholeFile(path, "skeleton file"), path);
}

} // namespace simeco::skeleton
