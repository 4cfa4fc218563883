// One plant of each species of a growing field grown to the end on the CPU, before the field starts: how large a
// grown plant is (what a field of many spaces its plants by, and what a camera that stays put frames) and how many
// modules it draws (what the field's batches of plants are sized by).
#pragma once

#include <cstdint>
#include <vector>

#include "grow/growing_species.h"
#include "grow/growth_tables.h"
#include "stream/derive_options.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_settings.h"

namespace simeco::field {

// The steps of a field's plants that its derivation makes room for from the start (firstStepsModules).
inline constexpr size_t kFirstSteps = 4;

struct GrownPlants {
    std::vector<turtle::Bounds> bounds; // per species, in the plant's own frame (its base at the origin)
    std::vector<uint64_t> drawnModules; // per species: the modules of its drawn string
    // Per species: the modules of its derived string after its first kFirstSteps steps (all it derives where
    // fewer), or of its drawn string where that grows larger, as the grown plant's drawn string is to its derived.
    std::vector<uint64_t> firstStepsModules;
};

// The plants derive as `derive` says (its plant count is replaced by one of each species) with the given
// DeriveTimes (the field's first plants'), grown until `until` seconds in ticks of half the shortest DeriveTime.
GrownPlants growOneOfEach(const grow::GrowingSpecies& g, const grow::GrowthTables& tables,
                          const stream::DeriveOptions& derive, uint32_t seed, const std::vector<float>& deriveTimes,
                          double until, const turtle::TurtleCommands& commands,
                          const std::vector<turtle::TurtleSettings>& turtles);

// The latest a field's plants are done: each its steps, one DeriveTime each, then the longest growth of any stage.
double latestGrowth(const std::vector<ir::Grammar>& species, const grow::GrowthTables& tables,
                    const std::vector<float>& deriveTimes, int fixedSteps);

} // namespace simeco::field
