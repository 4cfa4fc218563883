#include "turtle/interpretation.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include "compute/shared/field_scatter.h"

namespace simeco::turtle {

glm::vec3 fieldCell(uint32_t plant, uint32_t plants) {
    uint32_t columns = uint32_t(std::ceil(std::sqrt(double(std::max(plants, 1u)))));
    uint32_t rows = (std::max(plants, 1u) + columns - 1) / columns;
    float x = float(plant % columns) - 0.5f * float(columns - 1);
    float z = float(plant / columns) - 0.5f * float(rows - 1);
    return {x, 0.0f, z};
}

shared::PlantPlacement scatteredPlacement(uint32_t plant, uint32_t plants, float spacing) {
    // As compute/turtle/place.comp builds it, a turn about y and a move.
    const glm::vec3 cell = fieldCell(plant, plants);
    const float x = (cell.x + shared::fieldScatterOffset(plant, 0)) * spacing;
    const float z = (cell.z + shared::fieldScatterOffset(plant, 1)) * spacing;
    const float c = std::cos(shared::fieldScatterYaw(plant)), s = std::sin(shared::fieldScatterYaw(plant));
    return {{c, 0.0f, s, x}, {0.0f, 1.0f, 0.0f, 0.0f}, {-s, 0.0f, c, z}};
}

float fieldSpacing(const FieldOptions& options, const std::vector<Bounds>& plantBounds) {
    if (options.spacing > 0) return options.spacing;
    float widest = 0;
    for (const Bounds& b : plantBounds)
        if (!b.empty()) widest = std::max({widest, b.max.x - b.min.x, b.max.z - b.min.z});
    return widest > 0 ? 1.2f * widest : 1.0f;
}

shared::PlantPlacement placementAt(glm::vec3 position, glm::vec3 direction, float yaw) {
    const float length = glm::length(direction);
    const glm::vec3 up = length > 0.0f && std::isfinite(length) ? direction / length : glm::vec3(0, 1, 0);
    // The shortest turn from +y to `up`: about their common normal, or half a turn about x when they are opposite.
    const glm::vec3 normal = glm::cross(glm::vec3(0, 1, 0), up);
    const float angle = std::acos(std::clamp(up.y, -1.0f, 1.0f));
    const glm::quat tilt = glm::length(normal) > 1e-6f ? glm::angleAxis(angle, glm::normalize(normal))
                                                       : glm::angleAxis(up.y < 0.0f ? angle : 0.0f, glm::vec3(1, 0, 0));
    const glm::mat3 r = glm::mat3_cast(tilt * glm::angleAxis(yaw, glm::vec3(0, 1, 0)));
    // glm's matrices are by column: row i of the map is (r[0][i], r[1][i], r[2][i]).
    auto row = [&](int i, float w) { return shared::vec4{r[0][i], r[1][i], r[2][i], w}; };
    return {row(0, position.x), row(1, position.y), row(2, position.z)};
}

} // namespace simeco::turtle
