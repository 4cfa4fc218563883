#include "skeleton/json_reader.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

#include "ir/source_loc.h"

namespace simeco::skeleton {

namespace {

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

// nlohmann's message without its "[json.exception.kind.N] " prefix (and a parse error's own "at line L, column C").
std::string messageOf(const nlohmann::json::exception& e, bool afterColon) {
    std::string message = e.what();
    size_t cut = afterColon ? message.find(": ") : message.find("] ");
    return cut == std::string::npos ? message : message.substr(cut + 2);
}

} // namespace

nlohmann::json parseJsonDocument(const std::string& text, const std::string& file) {
    try {
        return nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw ir::InputError(locationOf(text, e.byte > 0 ? e.byte - 1 : 0, file), messageOf(e, true));
    } catch (const nlohmann::json::exception& e) { // a number too large for a double
        throw ir::InputError({file, 0, 0}, messageOf(e, false));
    }
}

void JsonReader::fail(const std::string& message) const {
    throw ir::InputError({file_, 0, 0}, fmt::format("{}: {}", pointer_.empty() ? "/" : pointer_, message));
}

JsonReader JsonReader::at(const char* key) const {
    if (!value_.is_object()) fail("expected an object");
    if (!value_.contains(key)) fail(fmt::format("missing \"{}\"", key));
    return {value_.at(key), pointer_ + "/" + key, file_};
}

std::vector<JsonReader> JsonReader::items() const {
    if (!value_.is_array()) fail("expected an array");
    std::vector<JsonReader> out;
    for (size_t k = 0; k < value_.size(); ++k) out.push_back({value_[k], pointer_ + "/" + std::to_string(k), file_});
    return out;
}

double JsonReader::number() const {
    if (!value_.is_number()) fail("expected a number");
    double v = value_.get<double>();
    if (!std::isfinite(v)) fail("the number is not finite");
    return v;
}

int JsonReader::integer() const {
    double v = number();
    if (v != std::floor(v) || std::abs(v) > 1e9) fail("expected a whole number");
    return static_cast<int>(v);
}

std::string JsonReader::text() const {
    if (!value_.is_string()) fail("expected a string");
    return value_.get<std::string>();
}

glm::dvec2 JsonReader::point2() const {
    std::vector<JsonReader> uv = items();
    if (uv.size() != 2) fail("expected [u, v]");
    return {uv[0].number(), uv[1].number()};
}

glm::dvec3 JsonReader::point3() const {
    std::vector<JsonReader> xyz = items();
    if (xyz.size() != 3) fail("expected [x, y, z]");
    return {xyz[0].number(), xyz[1].number(), xyz[2].number()};
}

std::string readWholeFile(const std::string& path, const char* what) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ir::InputError({path, 0, 0}, fmt::format("cannot open the {}", what));
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

} // namespace simeco::skeleton
