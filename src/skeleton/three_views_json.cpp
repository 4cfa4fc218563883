// The JSON form of three views (three_views.h): writing it, and reading it into a plant.
#include <cmath>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

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

// A value of the document and its place in it (a JSON pointer), for errors.
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
    glm::dvec2 point() const {
        std::vector<Reader> uv = items();
        if (uv.size() != 2) fail("expected [u, v]");
        return {uv[0].number(), uv[1].number()};
    }

private:
    const json& value_;
    std::string pointer_;
    const std::string& file_;
};

View readView(const Reader& r, bool front) {
    View view;
    for (const Reader& item : r.at("stems").items()) {
        ViewStem s;
        s.id = item.at("id").integer();
        if (front && item.has("parent")) s.parent = item.at("parent").integer();
        if (front && item.has("width")) {
            s.width = item.at("width").number();
            if (s.width < 0.0) item.at("width").fail("a width is not negative");
        }
        for (const Reader& p : item.at("points").items())
            s.points.push_back(p.point());
        if (s.points.empty()) item.at("points").fail(fmt::format("stem {} has no points", s.id));
        view.stems.push_back(std::move(s));
    }
    return view;
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

std::string threeViewsJson(const ThreeViews& views) {
    return "{\n  \"format\": \"simeco three views\",\n  \"version\": 1,\n  \"views\": {\n" +
           viewJson(views.front, "front", true) + ",\n" + viewJson(views.side, "side", false) + ",\n" +
           viewJson(views.top, "top", false) + "\n  }\n}\n";
}

Skeleton parseThreeViewsJson(const std::string& text, const std::string& file) {
    json document;
    try {
        document = json::parse(text);
    } catch (const json::parse_error& e) {
        // "[json.exception.parse_error.101] parse error at line 3, column 7: syntax error ..." without its prefix
        std::string message = e.what();
        size_t colon = message.find(": ");
        if (colon != std::string::npos) message = message.substr(colon + 2);
        throw ir::InputError(locationOf(text, e.byte > 0 ? e.byte - 1 : 0, file), message);
    }
    Reader views = Reader(document, "", file).at("views");
    ThreeViews three{readView(views.at("front"), true), readView(views.at("side"), false),
                     readView(views.at("top"), false)};
    Skeleton skeleton;
    skeleton.source = file;
    skeleton.plants.push_back(plantFromThreeViews(three, file));
    return skeleton;
}

} // namespace simeco::skeleton
