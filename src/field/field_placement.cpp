#include "field/field_placement.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>
#include <glm/vec3.hpp>

#include "field/ground_samples.h"
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

bool hasPopulations(const grow::GrowingSpecies& g) {
    return g.scene && !g.scene->populations.empty();
}

FieldLayout layoutPopulations(const grow::GrowingSpecies& g, uint32_t seed, std::vector<ir::EcoWarning>& warnings,
                              float density) {
    struct Stand {
        glm::vec2 at;
        float vigour = 1.0f;
        uint32_t draw = 0; // the key of its own draws
    };
    const ir::EcoScene& scene = *g.scene;
    const size_t species = scene.plants.size();
    std::vector<std::vector<Stand>> stands(species);
    auto speciesNamed = [&](const std::string& name) {
        for (size_t s = 0; s < species; ++s)
            if (scene.plants[s].name == name) return s;
        return species;
    };
    uint32_t key = 0;
    for (size_t s = 0; s < species; ++s) {
        const std::string& name = scene.plants[s].name;
        const bool inPopulation = std::any_of(scene.populations.begin(), scene.populations.end(),
                                              [&](const ir::EcoPopulation& p) { return p.plant == name; });
        if (!inPopulation) stands[s].push_back({glm::vec2(NAN), 1.0f, key++});
    }
    for (size_t k = 0; k < scene.populations.size(); ++k) {
        const ir::EcoPopulation& pop = scene.populations[k];
        const GroundRect rect{{pop.centerX, pop.centerZ}, {pop.width, pop.depth}};
        const double plants = pop.count ? double(*pop.count) : double(*pop.density) * rect.size.x * rect.size.y;
        const uint32_t count = uint32_t(std::max(1.0, std::round(plants * density)));
        const uint32_t stream = shared::randomBits(seed, pop.seed, shared::kGrowPropertyPass, 3, uint32_t(k));
        const std::vector<glm::vec2> points = pop.placement == ir::EcoPlacement::Poisson
                                                  ? poissonDiskPoints(rect, count, pop.spacing.value_or(0.0f), seed,
                                                                      stream)
                                                  : jitteredPoints(rect, count, seed, stream);
        if (points.size() < count)
            warnings.push_back({pop.loc, fmt::format("Population \"{}\" has room for {} of its {} plants {} apart",
                                                     pop.name, points.size(), count, pop.spacing.value_or(0.0f))});
        std::vector<Stand>& list = stands[speciesNamed(pop.plant)];
        for (size_t i = 0; i < points.size(); ++i) {
            const float u = shared::randomUnit(seed, stream, shared::kGrowPropertyPass, 4, uint32_t(i));
            list.push_back({points[i], 1.0f + pop.variation * (2.0f * u - 1.0f), key++});
        }
    }
    size_t rounds = 0;
    for (const std::vector<Stand>& list : stands) rounds = std::max(rounds, list.size());
    FieldLayout layout;
    const size_t slots = rounds * species;
    layout.placements.assign(slots, turtle::placementAt(glm::vec3(0), glm::vec3(0, 1, 0), 0.0f));
    layout.absent.assign(slots, 1);
    layout.vigour.assign(slots, 1.0f);
    for (size_t s = 0; s < species; ++s) {
        const ir::EcoPlant& plant = scene.plants[s];
        for (size_t j = 0; j < stands[s].size(); ++j) {
            const Stand& stand = stands[s][j];
            const size_t slot = s + j * species;
            const glm::vec3 direction = drawn(plant.direction, seed, stand.draw, 3);
            const glm::vec3 position = std::isnan(stand.at.x) ? drawn(plant.position, seed, stand.draw, 0)
                                                              : glm::vec3(stand.at.x, 0.0f, stand.at.y);
            layout.placements[slot] = turtle::placementAt(position, direction, kTwoPi * draw(seed, stand.draw, 6));
            layout.absent[slot] = 0;
            layout.vigour[slot] = stand.vigour;
        }
    }
    return layout;
}

} // namespace simeco::field
