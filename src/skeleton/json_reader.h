// Reading the skeleton's JSON files: the document parsed with its syntax errors at their line and column, and each
// value looked up through a JsonReader that knows its place in the document (a JSON pointer), for errors such as
// `/plants/0/stems/3/points/2: expected [x, y, z]`.
#pragma once

#include <string>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

namespace simeco::skeleton {

// The document of `text`; refuses text that is not JSON (ir::InputError at its line and column) and numbers too
// large for a double.
nlohmann::json parseJsonDocument(const std::string& text, const std::string& file);

class JsonReader {
public:
    JsonReader(const nlohmann::json& value, std::string pointer, const std::string& file)
        : value_(value), pointer_(std::move(pointer)), file_(file) {}

    [[noreturn]] void fail(const std::string& message) const;
    bool has(const char* key) const { return value_.is_object() && value_.contains(key); }
    JsonReader at(const char* key) const;
    std::vector<JsonReader> items() const;
    double number() const; // finite
    int integer() const;
    std::string text() const;
    glm::dvec2 point2() const; // [u, v]
    glm::dvec3 point3() const; // [x, y, z]

private:
    const nlohmann::json& value_;
    std::string pointer_;
    const std::string& file_;
};

// The whole of the file at `path` (ir::InputError "cannot open the <what>" where it cannot be read).
std::string readWholeFile(const std::string& path, const char* what);

} // namespace simeco::skeleton
