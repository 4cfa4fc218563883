// cpfg's drawn geometry as its rayshade exporter writes it (`cpfg -ray`, the corpus' geometry/*.ray.xz): the
// segments, spheres, discs and polygons a model draws, in the order cpfg drew them.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace simeco::test {

// A drawn segment, `F` or `G`: from the turtle's position before the move to after it; the radius at each end
// (equal unless cpfg tapered it: a `cone`).
struct RaySegment {
    glm::vec3 from{0.0f}, to{0.0f};
    float fromRadius = 0.0f, toRadius = 0.0f;
};

struct RaySphere {
    glm::vec3 centre{0.0f};
    float radius = 0.0f;
};

// A disc (`@c`, `@o`): its centre and radius (its normal, for `@o` turned to cpfg's viewer, is not kept).
using RayDisc = RaySphere;

// A polygon `{ ... }` as a fan of triangles from its first vertex, as simeco draws it.
struct RayTriangle {
    glm::vec3 corners[3];
};

struct RayGeometry {
    std::vector<RaySegment> segments;
    std::vector<RaySphere> spheres;
    std::vector<RayDisc> discs;
    std::vector<RayTriangle> polygonFans;
    size_t triangles = 0, objects = 0; // counted, not compared yet
    glm::vec3 min{1e30f}, max{-1e30f};                          // of every point read
    float size() const;                                         // the largest side of the box
};

// Reads an xz-compressed .ray file; throws std::runtime_error where it cannot.
RayGeometry readRayGeometry(const std::filesystem::path& xzFile);

} // namespace simeco::test
