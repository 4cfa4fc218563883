// The JSON form of three views (three_views.h): writing it, and reading it into a plant.
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "skeleton/json_reader.h"
#include "skeleton/three_views.h"

namespace simeco::skeleton {

namespace {

using nlohmann::json;

std::string number(double v) {
    return fmt::format("{:.9g}", v);
}

std::string viewJson(const View& view, const char* name, bool withParents) {
    std::string out = fmt::format("    \"{}\": {{\"stems\": [\n", name);
    for (size_t k = 0; k < view.stems.size(); ++k) {
        const ViewStem& s = view.stems[k];
        out += fmt::format("      {{\"id\": {}", s.id);
        if (withParents) out += fmt::format(", \"parent\": {}, \"width\": {}", s.parent.value_or(-1), number(s.width));
        out += ",\n       \"points\": [";
        for (size_t p = 0; p < s.points.size(); ++p)
            out += fmt::format("{}[{}, {}]", p ? ", " : "", number(s.points[p].x), number(s.points[p].y));
        out += k + 1 < view.stems.size() ? "]},\n" : "]}\n";
    }
    return out + "    ]}";
}


View readView(const JsonReader& r, bool front) {
    View view;
    for (const JsonReader& item : r.at("stems").items()) {
        ViewStem s;
        s.id = item.at("id").integer();
        if (front && item.has("parent")) s.parent = item.at("parent").integer();
        if (front && item.has("width")) {
            s.width = item.at("width").number();
            if (s.width < 0.0) item.at("width").fail("a width is not negative");
        }
        for (const JsonReader& p : item.at("points").items())
            s.points.push_back(p.point2());
        if (s.points.empty()) item.at("points").fail(fmt::format("stem {} has no points", s.id));
        view.stems.push_back(std::move(s));
    }
    return view;
}

} // namespace

std::string threeViewsJson(const ThreeViews& views) {
    return "{\n  \"format\": \"simeco three views\",\n  \"version\": 1,\n  \"views\": {\n" +
           viewJson(views.front, "front", true) + ",\n" + viewJson(views.side, "side", false) + ",\n" +
           viewJson(views.top, "top", false) + "\n  }\n}\n";
}

Skeleton parseThreeViewsJson(const std::string& text, const std::string& file) {
    const json document = parseJsonDocument(text, file);
    JsonReader views = JsonReader(document, "", file).at("views");
    ThreeViews three{readView(views.at("front"), true), readView(views.at("side"), false),
                     readView(views.at("top"), false)};
    Skeleton skeleton;
    skeleton.source = file;
    skeleton.plants.push_back(plantFromThreeViews(three, file));
    return skeleton;
}

} // namespace simeco::skeleton
