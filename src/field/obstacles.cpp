#include "field/obstacles.h"

#include <cmath>

#include "compute/shared/organ_layout.h"
#include "lang/color_map.h"

namespace simeco::field {

std::array<glm::vec3, 8> obstacleCorners(const ir::EcoObstacle& o) {
    const glm::vec3 x(std::cos(o.yaw), 0.0f, -std::sin(o.yaw)), y(0, 1, 0), z(std::sin(o.yaw), 0.0f, std::cos(o.yaw));
    const glm::vec3 center(o.center[0], o.center[1], o.center[2]);
    std::array<glm::vec3, 8> corners;
    for (int k = 0; k < 8; ++k)
        corners[size_t(k)] = center + x * ((k & 1) ? o.halfSize[0] : -o.halfSize[0]) +
                             y * ((k & 2) ? o.halfSize[1] : -o.halfSize[1]) +
                             z * ((k & 4) ? o.halfSize[2] : -o.halfSize[2]);
    return corners;
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
