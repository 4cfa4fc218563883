#include "turtle/interpretation.h"

#include <algorithm>
#include <cmath>

namespace simeco::turtle {

glm::vec3 fieldCell(uint32_t plant, uint32_t plants) {
    uint32_t columns = uint32_t(std::ceil(std::sqrt(double(std::max(plants, 1u)))));
    uint32_t rows = (std::max(plants, 1u) + columns - 1) / columns;
    float x = float(plant % columns) - 0.5f * float(columns - 1);
    float z = float(plant / columns) - 0.5f * float(rows - 1);
    return {x, 0.0f, z};
}

float fieldSpacing(const FieldOptions& options, const std::vector<Bounds>& plantBounds) {
    if (options.spacing > 0) return options.spacing;
    float widest = 0;
    for (const Bounds& b : plantBounds)
        if (!b.empty()) widest = std::max({widest, b.max.x - b.min.x, b.max.z - b.min.z});
    return widest > 0 ? 1.2f * widest : 1.0f;
}

} // namespace simeco::turtle
