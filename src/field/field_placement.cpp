#include "field/field_placement.h"

#include <glm/vec3.hpp>

#include "compute/shared/growth_layout.h"
#include "compute/shared/random.h"
#include "ir/species.h"
#include "turtle/interpretation.h"

namespace simeco::field {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;
// The random draws of a plant's placement: module key 1 of the growth property pass, one draw per number.
constexpr uint32_t kPlacementKey = 1;

float draw(uint32_t seed, uint32_t plant, uint32_t number) {
    return shared::randomUnit(seed, plant, shared::kGrowPropertyPass, kPlacementKey, number);
}

float drawn(const ir::EcoNumber& n, uint32_t seed, uint32_t plant, uint32_t number) {
    return n.random ? n.min + (n.max - n.min) * draw(seed, plant, number) : n.min;
}

glm::vec3 drawn(const ir::EcoVector& v, uint32_t seed, uint32_t plant, uint32_t firstNumber) {
    return {drawn(v.x, seed, plant, firstNumber), drawn(v.y, seed, plant, firstNumber + 1),
            drawn(v.z, seed, plant, firstNumber + 2)};
}

} // namespace

bool placedAsScene(const grow::GrowingSpecies& g, uint32_t plants) {
    return g.scene && plants == g.species.size();
}

std::vector<shared::PlantPlacement> placeField(const grow::GrowingSpecies& g, uint32_t plants, uint32_t seed,
                                               float spacing) {
    std::vector<shared::PlantPlacement> placements;
    const bool asScene = placedAsScene(g, plants);
    for (uint32_t p = 0; p < plants; ++p) {
        const ir::EcoPlant* eco = g.ecoPlants[ir::speciesOfPlant(p, g.species.size())];
        const float yaw = kTwoPi * draw(seed, p, 6);
        const glm::vec3 direction = eco ? drawn(eco->direction, seed, p, 3) : glm::vec3(0, 1, 0);
        glm::vec3 position = eco ? drawn(eco->position, seed, p, 0) : glm::vec3(0);
        if (!asScene) {
            const glm::vec3 cell = turtle::fieldCell(p, plants);
            position =
                glm::vec3(cell.x + 0.6f * (draw(seed, p, 7) - 0.5f), 0.0f, cell.z + 0.6f * (draw(seed, p, 8) - 0.5f)) *
                spacing;
        }
        placements.push_back(turtle::placementAt(position, direction, yaw));
    }
    return placements;
}

} // namespace simeco::field
