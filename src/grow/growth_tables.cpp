#include "grow/growth_tables.h"

#include <algorithm>
#include <bit>
#include <optional>

#include "compute/shared/growth_layout.h"
#include "compute/shared/random.h"
#include "ir/species.h"
#include "compute/shared/turtle_layout.h"
#include "lang/eco_geometry.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_settings.h"

namespace simeco::grow {

namespace {

using ir::EcoOrganKind;

// The script's number for a property of a stage, in shared::kGrowRate's order.
const std::optional<ir::EcoNumber>& scriptProperty(const ir::EcoStage& stage, uint32_t property) {
    switch (property) {
    case shared::kGrowRate:
        return stage.growRate;
    case shared::kGrowTime:
        return stage.growTime;
    case shared::kLifeTime:
        return stage.lifeTime;
    case shared::kBroadenRate:
        return stage.broadenRate;
    case shared::kWeightFactor:
        return stage.weightFactor;
    case shared::kConeNoise:
        return stage.coneNoise;
    case shared::kNoiseTime:
        return stage.noiseTime;
    case shared::kStrength:
        return stage.strength;
    case shared::kGeotropism:
        return stage.geotropism;
    case shared::kPhototropism:
        return stage.phototropism;
    default:
        return stage.shadeTime;
    }
}

// One row: the stage's properties, else the organ's Default stage's, else simeco's defaults.
void appendRow(std::vector<float>& rows, EcoOrganKind kind, const ir::EcoOrgan& organ, const ir::EcoStage* stage,
               float stageNumber) {
    const size_t at = rows.size();
    rows.resize(at + shared::kStageRowFloats, 0.0f);
    rows[at + shared::kStageNumber] = stageNumber;
    for (uint32_t p = 0; p < shared::kStageProperties; ++p) {
        const ir::EcoNumber* number = nullptr;
        if (stage && scriptProperty(*stage, p))
            number = &*scriptProperty(*stage, p);
        else if (organ.defaultStage && scriptProperty(*organ.defaultStage, p))
            number = &*scriptProperty(*organ.defaultStage, p);
        const float fallback = defaultProperty(kind, p);
        rows[at + shared::propertyMin(p)] = number ? number->min : fallback;
        rows[at + shared::propertyMax(p)] = number ? number->max : fallback;
    }
}

} // namespace

float defaultProperty(EcoOrganKind kind, uint32_t property) {
    const bool stem = kind == EcoOrganKind::Stem || kind == EcoOrganKind::Root;
    const bool bloom = kind == EcoOrganKind::Flower || kind == EcoOrganKind::Fruit;
    switch (property) {
    // Unset growth draws what a derivation alone draws (lang/eco_geometry.h) by the end of the default GrowTime.
    case shared::kGrowRate:
        return stem    ? lang::kEcoDefaultStemLength / lang::kEcoDefaultGrowTime
               : bloom ? lang::kEcoDefaultFlowerSize / lang::kEcoDefaultGrowTime
                       : 0.0f;
    case shared::kGrowTime:
        return lang::kEcoDefaultGrowTime;
    case shared::kBroadenRate:
        return stem ? lang::kEcoDefaultStemWidth / lang::kEcoDefaultGrowTime : 0.0f;
    case shared::kStrength:
        return 1.0f;
    default:
        return 0.0f; // no life time limit, weight, noise, tropism or shedding in the shade
    }
}

bool GrowthTables::drawsGrowth() const {
    for (size_t s = 0; s < species.size(); s += shared::kSpeciesGrowthWords)
        if (species[s + shared::kSpeciesFlags] & shared::kSpeciesDrawsGrowth) return true;
    return false;
}

bool GrowthTables::growsSegments() const {
    for (size_t s = 0; s < species.size(); s += shared::kSpeciesGrowthWords)
        if (species[s + shared::kSpeciesFlags] & shared::kSpeciesGrowsSegments) return true;
    return false;
}

void scaleSpeciesProperty(GrowthTables& tables, uint32_t s, uint32_t property, float factor) {
    const uint32_t* words = tables.species.data() + size_t(s) * shared::kSpeciesGrowthWords;
    for (uint32_t k = 0; k < shared::kGrowOrganKinds; ++k) {
        if (words[shared::kSpeciesFirstRow + k] == shared::kGrowNoRow) continue;
        // The organ's stage rows and its Default row after them.
        const uint32_t first = words[shared::kSpeciesFirstRow + k];
        for (uint32_t row = first; row <= first + words[shared::kSpeciesRowCount + k]; ++row) {
            float* at = tables.rows.data() + size_t(row) * shared::kStageRowFloats;
            at[shared::propertyMin(property)] *= factor;
            at[shared::propertyMax(property)] *= factor;
        }
    }
}

GrowthTables growthTables(const std::vector<ir::Grammar>& species, const std::vector<const ir::EcoPlant*>& ecoPlants) {
    GrowthTables t;
    t.symbols = species.empty() ? 0u : uint32_t(species.front().alphabet.size());
    t.classes.assign(species.size() * t.symbols, 0);
    const turtle::TurtleCommands commands =
        species.empty() ? turtle::TurtleCommands{} : turtle::turtleCommands(species.front().alphabet);
    t.atSymbol = commands.at;
    t.species.assign(species.size() * shared::kSpeciesGrowthWords, shared::kGrowNoRow);
    for (size_t s = 0; s < species.size(); ++s) {
        uint32_t* classes = t.classes.data() + s * t.symbols;
        for (uint32_t sym = 0; sym < t.symbols; ++sym)
            classes[sym] = shared::kGrowPlainClass + sym;
        uint32_t* words = t.species.data() + s * shared::kSpeciesGrowthWords;
        words[shared::kSpeciesFlags] = 0;
        const ir::EcoPlant* plant = s < ecoPlants.size() ? ecoPlants[s] : nullptr;
        if (!plant || !plant->grammar.empty()) { // a grammar file's modules age, its segments grow
            words[shared::kSpeciesFlags] = shared::kSpeciesGrowsSegments;
            words[shared::kSpeciesSegmentStep] =
                std::bit_cast<uint32_t>(turtle::turtleSettings(species[s], species[s].alphabet).step);
            for (uint32_t sym = 0; sym < t.symbols; ++sym) {
                if (shared::turtleDraws(commands.plain[sym]) || shared::turtleMovesOnly(commands.plain[sym]))
                    classes[sym] |= shared::kGrowSegment;
                const uint32_t afterAt = commands.afterAt[sym];
                if (afterAt == shared::kTurtleSphere || afterAt == shared::kTurtleDisc ||
                    afterAt == shared::kTurtleDiscFacing)
                    classes[sym] |= shared::kGrowRadius;
            }
            continue;
        }
        words[shared::kSpeciesFlags] = shared::kSpeciesDrawsGrowth;
        for (uint32_t k = 0; k < shared::kGrowOrganKinds; ++k) {
            const auto kind = static_cast<EcoOrganKind>(k);
            if (std::optional<ir::SymbolId> sym = species[s].alphabet.find(std::string(1, ir::kEcoSegmentLetters[k])))
                classes[*sym] = k;
            const ir::EcoOrgan& organ = plant->organ(kind);
            words[shared::kSpeciesFirstRow + k] = uint32_t(t.rows.size() / shared::kStageRowFloats);
            words[shared::kSpeciesRowCount + k] = uint32_t(organ.stages.size());
            for (const auto& [number, stage] : organ.stages)
                appendRow(t.rows, kind, organ, &stage, float(number));
            words[shared::kSpeciesDefaultRow + k] = uint32_t(t.rows.size() / shared::kStageRowFloats);
            appendRow(t.rows, kind, organ, nullptr, -1.0f);
        }
    }
    return t;
}

// The draw of the growth's property pass that a plant's DeriveTime takes, as identity 0 (no particle's: theirs are
// odd, so no stage property draws it).
constexpr uint32_t kDeriveTimeDraw = 9;

std::vector<float> plantDeriveTimes(const std::vector<const ir::EcoPlant*>& ecoPlants, uint32_t plants, uint32_t seed) {
    std::vector<float> times(plants, kDefaultDeriveTime);
    if (ecoPlants.empty()) return times;
    for (uint32_t plant = 0; plant < plants; ++plant) {
        const ir::EcoPlant* eco = ecoPlants[ir::speciesOfPlant(plant, ecoPlants.size())];
        if (!eco) continue;
        const float u = shared::randomUnit(seed, plant, shared::kGrowPropertyPass, 0, kDeriveTimeDraw);
        times[plant] = std::max(eco->deriveTime.min + (eco->deriveTime.max - eco->deriveTime.min) * u, 1e-3f);
    }
    return times;
}

} // namespace simeco::grow
