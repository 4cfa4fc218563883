// Where the plants of a growing field stand (turtle::FieldOptions::placements): a scene's plants where the scene
// puts them, or a field of many on a jittered grid, each turned about its own axis by an angle of its own.
#pragma once

#include <cstdint>
#include <vector>

#include "compute/shared/organ_layout.h"
#include "grow/growing_species.h"

namespace simeco::field {

// One plant of each species of a scene stands at its Position, growing along its Direction (each drawn per plant
// where the script gives a range). Otherwise plant p stands in cell p of a grid of rows and columns `spacing`
// apart (turtle::fieldCell), moved by up to 0.3 of the spacing, growing along its scene plant's Direction (up for
// a grammar file). Every plant is turned about its own axis by an angle drawn from `seed`.
std::vector<shared::PlantPlacement> placeField(const grow::GrowingSpecies& g, uint32_t plants, uint32_t seed,
                                               float spacing);

// Whether placeField puts the plants where the scene says: a scene with one plant of each species.
bool placedAsScene(const grow::GrowingSpecies& g, uint32_t plants);

// A field whose scene has populations (docs/SCENES.md): plant p is of species p mod the species' count, so the
// field has as many rounds of its species as its most numerous species has plants, and the slots of the others'
// rounds beyond their plants stand empty.
struct FieldLayout {
    std::vector<shared::PlantPlacement> placements; // per slot
    std::vector<uint8_t> absent;                    // per slot: 1 where no plant stands
    std::vector<float> vigour;                      // per slot: the factor on its growth rates (Variation)
};
bool hasPopulations(const grow::GrowingSpecies& g);
// Each population's plants over its region, its Count or Density times `density` (at least one plant), and each Plant
// block that no population names at its Position. A population that has no room for its plants is placed as far as
// it goes, with a warning.
FieldLayout layoutPopulations(const grow::GrowingSpecies& g, uint32_t seed, std::vector<ir::EcoWarning>& warnings,
                              float density = 1.0f);

} // namespace simeco::field
