// The bounding box of everything drawn, as the turtle kernels reduce it into the OrganTable: each float as an
// order-preserving int (key = bits >= 0 ? bits : bits ^ 0x7FFFFFFF), so that integer min/max atomics order
// them as floats.
#pragma once

#include <cmath>
#include <cstdint>

#include <glm/vec3.hpp>

#include "compute/shared/organ_layout.h"

namespace simeco::draw {

struct Bounds {
    glm::vec3 min{0.0f};
    glm::vec3 max{0.0f};

    // Nothing was drawn: the reductions' identities are still in place (min above max).
    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    glm::vec3 centre() const { return 0.5f * (min + max); }
    glm::vec3 extent() const { return max - min; }
    // Every coordinate is a finite number: the turtles make a non-finite organ's bounds infinite
    // (turtle/finite_organs.h).
    bool finite() const {
        for (int axis = 0; axis < 3; ++axis)
            if (!std::isfinite(min[axis]) || !std::isfinite(max[axis])) return false;
        return true;
    }
};

std::int32_t boundsKey(float value);
float boundsValue(std::int32_t key);

// The box of a table's boundsMin/boundsMax (only x, y, z; w is unused).
Bounds decodeBounds(const shared::OrganTable& table);

// Writes `bounds` into a table the way the turtle kernels do, for tests and hand-made tables.
void encodeBounds(const Bounds& bounds, shared::OrganTable& table);

} // namespace simeco::draw
