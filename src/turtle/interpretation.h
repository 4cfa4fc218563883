// Turtle interpretation of a module stream into organ instances (compute/shared/organ_layout.h), and the field the
// plants stand in.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "compute/shared/organ_layout.h"
#include "stream/module_string.h"
#include "turtle/turtle_settings.h"

namespace simeco::turtle {

struct Bounds {
    glm::vec3 min{1e30f}, max{-1e30f};
    bool empty() const { return min.x > max.x; }
    void add(glm::vec3 p, float radius = 0.0f) {
        min = glm::min(min, p - radius);
        max = glm::max(max, p + radius);
    }
    void add(const Bounds& b) {
        if (b.empty()) return;
        add(b.min);
        add(b.max);
    }
};

struct Interpretation {
    std::vector<shared::OrganInstance> organs;         // grouped by kind, in module order within a kind
    std::array<uint32_t, shared::kOrganKinds> count{}; // instances of each kind
    std::array<uint32_t, shared::kOrganKinds> first{}; // where each kind starts
    Bounds bounds;                                     // of everything drawn, in the field
    std::vector<glm::vec3> plantOrigins;               // where each plant stands
    float spacing = 1.0f;                              // between neighbouring plants of the field's grid
    bool scattered = false;                            // its plants stand scattered about the grid
};

// How plants stand: each at its placement where there is one per plant; else in rows and columns on the ground
// (y = 0), `spacing` apart; 0 spaces them by the widest plant's horizontal extent (times 1.2), so that neighbours
// do not overlap. Without placements, `scattered` loosens the grid: each plant moved within its cell and turned
// about its own axis (compute/shared/field_scatter.h).
struct FieldOptions {
    float spacing = 0.0f;
    std::vector<shared::PlantPlacement> placements;
    bool scattered = false;
};

// Where a placement puts the plant's base, a direction of the plant's frame, and a point of it.
inline glm::vec3 plantOrigin(const shared::PlantPlacement& m) { return {m.x.w, m.y.w, m.z.w}; }
inline glm::vec3 turnDirection(const shared::PlantPlacement& m, glm::vec3 v) {
    return {m.x.x * v.x + m.x.y * v.y + m.x.z * v.z, m.y.x * v.x + m.y.y * v.y + m.y.z * v.z,
            m.z.x * v.x + m.z.y * v.y + m.z.z * v.z};
}
inline glm::vec3 placePoint(const shared::PlantPlacement& m, glm::vec3 p) {
    return turnDirection(m, p) + plantOrigin(m);
}
// A direction of the field turned into the plant's own frame (turnDirection's inverse: the rotation's transpose).
inline glm::vec3 turnIntoPlant(const shared::PlantPlacement& m, glm::vec3 v) {
    return {m.x.x * v.x + m.y.x * v.y + m.z.x * v.z, m.x.y * v.x + m.y.y * v.y + m.z.y * v.z,
            m.x.z * v.x + m.y.z * v.y + m.z.z * v.z};
}

// The placement of a plant standing at `position`, turned by `yaw` radians about its own axis, then tilted (by
// the shortest turn) from growing along +y to growing along `direction` (+y where it is zero).
shared::PlantPlacement placementAt(glm::vec3 position, glm::vec3 direction, float yaw);

// The grid position of plant p of `plants` in units of spacing: centred on the origin, x across, z along.
glm::vec3 fieldCell(uint32_t plant, uint32_t plants);

// Where plant p of `plants` stands in a scattered field `spacing` apart (FieldOptions::scattered).
shared::PlantPlacement scatteredPlacement(uint32_t plant, uint32_t plants, float spacing);

// The spacing FieldOptions asks for, given each plant's own bounds (drawn at the origin).
float fieldSpacing(const FieldOptions& options, const std::vector<Bounds>& plantBounds);

} // namespace simeco::turtle
