#include "field/obstacles.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

#include "compute/shared/organ_layout.h"
#include "lang/color_map.h"

namespace simeco::field {

namespace {

// An obstacle's own axes in the world: x (a wall's length) turned by its yaw about y, y up, z across.
std::array<glm::vec3, 3> obstacleAxes(const ir::EcoObstacle& o) {
    return {glm::vec3(std::cos(o.yaw), 0.0f, -std::sin(o.yaw)), glm::vec3(0, 1, 0),
            glm::vec3(std::sin(o.yaw), 0.0f, std::cos(o.yaw))};
}

} // namespace

std::array<glm::vec3, 8> obstacleCorners(const ir::EcoObstacle& o) {
    const auto [x, y, z] = obstacleAxes(o);
    const glm::vec3 center(o.center[0], o.center[1], o.center[2]);
    std::array<glm::vec3, 8> corners;
    for (int k = 0; k < 8; ++k)
        corners[size_t(k)] = center + x * ((k & 1) ? o.halfSize[0] : -o.halfSize[0]) +
                             y * ((k & 2) ? o.halfSize[1] : -o.halfSize[1]) +
                             z * ((k & 4) ? o.halfSize[2] : -o.halfSize[2]);
    return corners;
}

std::vector<uint32_t> obstacleVoxels(const grow::LightGridSpec& grid, const std::vector<ir::EcoObstacle>& obstacles) {
    std::vector<uint32_t> mask(grid.voxels(), 0);
    for (const ir::EcoObstacle& o : obstacles) {
        const std::array<glm::vec3, 3> axes = obstacleAxes(o);
        const glm::vec3 center(o.center[0], o.center[1], o.center[2]);
        // An obstacle thinner than a voxel fills the layer of voxels it passes through, so that a thin wall casts its
        // shade however coarse the grid.
        std::array<float, 3> reach{};
        for (size_t k = 0; k < 3; ++k) reach[k] = std::max(o.halfSize[k], 0.5f * grid.side);
        for (uint64_t v = 0; v < grid.voxels(); ++v) {
            const glm::vec3 d = grid.centre(v) - center;
            bool inside = true;
            for (size_t k = 0; k < 3; ++k) inside = inside && std::abs(glm::dot(d, axes[k])) <= reach[k];
            if (inside) mask[v] = 1;
        }
    }
    return mask;
}

turtle::Interpretation obstacleOrgans(const std::vector<ir::EcoObstacle>& obstacles) {
    // Each face as two triangles, counter-clockwise seen from outside (corner bits: x 1, y 2, z 4).
    static constexpr int kFaces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                         {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    turtle::Interpretation result;
    for (uint32_t k = 0; k < obstacles.size(); ++k) {
        const ir::EcoObstacle& o = obstacles[k];
        const std::array<glm::vec3, 8> c = obstacleCorners(o);
        for (const glm::vec3& corner : c) result.bounds.add(corner);
        for (const auto& face : kFaces)
            for (const auto& tri : {std::array<int, 3>{face[0], face[1], face[2]},
                                    std::array<int, 3>{face[0], face[2], face[3]}}) {
                shared::OrganInstance organ{};
                organ.kind = shared::kOrganTriangle;
                organ.module = k;
                const glm::vec3 &a = c[size_t(tri[0])], &b = c[size_t(tri[1])], &d = c[size_t(tri[2])];
                organ.position = {a.x, a.y, a.z, 0.0f};
                organ.heading = {b.x, b.y, b.z, 0.0f};
                organ.up = {d.x, d.y, d.z, 0.0f};
                organ.color = {lang::srgbToLinear(o.color[0]), lang::srgbToLinear(o.color[1]),
                               lang::srgbToLinear(o.color[2]), 1.0f};
                result.organs.push_back(organ);
            }
    }
    result.count[shared::kOrganTriangle] = uint32_t(result.organs.size());
    for (uint32_t kind = 1; kind < shared::kOrganKinds; ++kind)
        result.first[kind] = result.first[kind - 1] + result.count[kind - 1];
    return result;
}

} // namespace simeco::field
