#include "draw/bounds.h"

#include <bit>

namespace simeco::draw {

std::int32_t boundsKey(float value) {
    auto bits = std::bit_cast<std::int32_t>(value);
    return bits >= 0 ? bits : bits ^ 0x7FFFFFFF;
}

float boundsValue(std::int32_t key) {
    // The mapping is its own inverse: it keeps the sign bit, so it knows which way to go back.
    return std::bit_cast<float>(key >= 0 ? key : key ^ 0x7FFFFFFF);
}

Bounds decodeBounds(const shared::OrganTable& table) {
    Bounds b;
    for (int axis = 0; axis < 3; ++axis) {
        b.min[axis] = boundsValue(table.boundsMin[axis]);
        b.max[axis] = boundsValue(table.boundsMax[axis]);
    }
    return b;
}

void encodeBounds(const Bounds& bounds, shared::OrganTable& table) {
    for (int axis = 0; axis < 3; ++axis) {
        table.boundsMin[axis] = boundsKey(bounds.min[axis]);
        table.boundsMax[axis] = boundsKey(bounds.max[axis]);
    }
    table.boundsMin[3] = boundsKey(0.0f);
    table.boundsMax[3] = boundsKey(0.0f);
}

} // namespace simeco::draw
