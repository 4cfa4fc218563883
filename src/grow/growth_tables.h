// What each species grows by, as the growth tick reads it (compute/shared/growth_layout.h): which class each
// module is, the stage rows of a SimEco plant's organs with every property resolved (the stage's own, else its
// organ's Default stage's, else simeco's default), and each plant's DeriveTime drawn from its range.
#pragma once

#include <cstdint>
#include <vector>

#include "ir/eco_scene.h"
#include "ir/grammar.h"

namespace simeco::grow {

// Simulated seconds between a plant's derivation steps where its grammar names none (every seed script says 3).
inline constexpr float kDefaultDeriveTime = 3.0f;

struct GrowthTables {
    uint32_t symbols = 0;          // the alphabet's size
    std::vector<uint32_t> classes; // per species and symbol: its module class
    std::vector<uint32_t> species; // kSpeciesGrowthWords per species
    std::vector<float> rows;       // kStageRowFloats per stage row
    uint32_t atSymbol = 0xFFFFFFFFu; // the alphabet's `@`, if it has one
    // Whether any species' drawn modules carry kGrownValue codes, or grow their segments.
    bool drawsGrowth() const;
    bool growsSegments() const;
};

// `ecoPlants[s]`: the scene's plant species s was compiled from with EcoDrawing::Grown, or null (or a plant
// that names a Grammar file) for a cpfg or quick grammar, whose modules age and whose segments grow to their
// length over their first DeriveTime. The species share one alphabet.
GrowthTables growthTables(const std::vector<ir::Grammar>& species, const std::vector<const ir::EcoPlant*>& ecoPlants);

// Species `s`'s stage rows with property `property` (shared::kGrowRate, ...) times `factor`, min and max: a
// viewer's slider on the running field. A species without stage rows (a grammar file's) is left as it is.
void scaleSpeciesProperty(GrowthTables& tables, uint32_t s, uint32_t property, float factor);

// Each of `plants` plants' DeriveTime (plant p is of species p mod the species' count), drawn from its range
// with the field's seed.
std::vector<float> plantDeriveTimes(const std::vector<const ir::EcoPlant*>& ecoPlants, uint32_t plants, uint32_t seed);

// The simeco default of a property a SimEco stage leaves unset, for an organ kind (shared::kGrowRate, ...).
float defaultProperty(ir::EcoOrganKind kind, uint32_t property);

} // namespace simeco::grow
