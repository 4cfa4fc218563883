#include "lang/obj_leaf_model.h"

#include <algorithm>
#include <cmath>

#include <tiny_obj_loader.h>

namespace simeco::lang {

namespace {

using Point = std::array<float, 3>;

Point minus(const Point& a, const Point& b) {
    return {a[0] - b[0], a[1] - b[1], a[2] - b[2]};
}

Point cross(const Point& a, const Point& b) {
    return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

float length(const Point& a) {
    return std::sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

} // namespace

std::optional<ir::LeafModel> readObjLeafModel(const std::string& path, std::string& why) {
    tinyobj::ObjReaderConfig config;
    config.triangulate = true;
    config.vertex_color = false;
    config.mtl_search_path = ""; // materials are not read: the stage's Color colours the leaf
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(path, config)) {
        why = reader.Error().empty() ? "it cannot be read" : reader.Error();
        while (!why.empty() && (why.back() == '\n' || why.back() == ' ')) why.pop_back();
        return std::nullopt;
    }
    const std::vector<float>& xyz = reader.GetAttrib().vertices;
    std::vector<Point> corners;
    for (const tinyobj::shape_t& shape : reader.GetShapes())
        for (const tinyobj::index_t& index : shape.mesh.indices) {
            if (index.vertex_index < 0 || size_t(index.vertex_index) * 3 + 2 >= xyz.size()) {
                why = "a face names a vertex the file does not have";
                return std::nullopt;
            }
            const size_t v = size_t(index.vertex_index) * 3;
            corners.push_back({xyz[v], xyz[v + 1], xyz[v + 2]});
        }
    float lo = INFINITY, hi = -INFINITY;
    for (const Point& p : corners) {
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
            why = "a vertex is not a finite number";
            return std::nullopt;
        }
        lo = std::min(lo, p[0]);
        hi = std::max(hi, p[0]);
    }
    if (corners.size() < 3 || !(hi > lo)) {
        why = "it has no face with an extent along x";
        return std::nullopt;
    }
    ir::LeafModel model;
    model.file = path;
    const float scale = 1.0f / (hi - lo);
    for (size_t t = 0; t + 2 < corners.size(); t += 3) {
        std::array<Point, 3> tri;
        for (size_t k = 0; k < 3; ++k)
            tri[k] = {(corners[t + k][0] - lo) * scale, corners[t + k][1] * scale, corners[t + k][2] * scale};
        const Point n = cross(minus(tri[1], tri[0]), minus(tri[2], tri[0]));
        const float twice = length(n);
        if (!(twice > 0.0f)) continue; // no area: nothing to draw
        model.corners.insert(model.corners.end(), tri.begin(), tri.end());
        model.normals.push_back({n[0] / twice, n[1] / twice, n[2] / twice});
        model.area += 0.5f * twice;
    }
    if (model.corners.empty()) {
        why = "its faces have no area";
        return std::nullopt;
    }
    return model;
}

} // namespace simeco::lang
