// cpfg's drawn geometry as its rayshade exporter writes it (`cpfg -ray`, the corpus' geometry/*.ray.xz): the
// segments, spheres, discs and polygons a model draws, in the order cpfg drew them.
#pragma once

#include <filesystem>
#include <map>
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

// A polygon `{ ... }` as a fan of triangles from its first vertex, as simeco draws it; or a generalized
// cylinder's triangle.
struct RayTriangle {
    glm::vec3 corners[3];
};

// A `~` surface placed by the turtle: its id, its scales across, along and out of it, the turtle's frame (cpfg's
// left, heading and up) and position.
struct RaySurface {
    std::string id;
    glm::vec3 scale{1.0f};
    glm::vec3 left{1, 0, 0}, heading{0, 1, 0}, up{0, 0, 1};
    glm::vec3 position{0.0f};
};

struct RayGeometry {
    std::vector<RaySegment> segments;
    std::vector<RaySphere> spheres;
    std::vector<RayDisc> discs;
    std::vector<RayTriangle> polygonFans;
    std::vector<RaySurface> surfaces;
    // The triangles of each surface the file defines (`name id grid ... end`), in the surface's own frame.
    std::map<std::string, std::vector<RayTriangle>> surfaceMeshes;
    // The plant's own triangles: its generalized cylinders' meshes, strip after strip.
    std::vector<RayTriangle> cylinderTriangles;
    glm::vec3 min{1e30f}, max{-1e30f}; // of every point the plant draws (not the surfaces' own frames)
    float size() const;                // the largest side of the box
};

// Reads an xz-compressed .ray file; throws std::runtime_error where it cannot.
RayGeometry readRayGeometry(const std::filesystem::path& xzFile);

} // namespace simeco::test
