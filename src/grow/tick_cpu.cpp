#include "grow/tick_cpu.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "compute/shared/growth_layout.h"
#include "compute/shared/particle_layout.h"
#include "compute/shared/random.h"
#include "grow/light_grid.h"
#include "ir/species.h"
#include "turtle/interpretation.h"

namespace simeco::grow {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;

uint32_t idOf(const shared::ParticleState& p) {
    return std::bit_cast<uint32_t>(p.value[shared::kParticleId]);
}

// The row of `organ`'s stage in species `species`: the stage's own, else the organ's Default row.
const float* stageRow(const GrowthTables& t, uint32_t species, uint32_t organ, float stage) {
    const uint32_t* words = t.species.data() + size_t(species) * shared::kSpeciesGrowthWords;
    const uint32_t first = words[shared::kSpeciesFirstRow + organ];
    if (first == shared::kGrowNoRow) return nullptr;
    for (uint32_t r = first; r < first + words[shared::kSpeciesRowCount + organ]; ++r)
        if (t.rows[size_t(r) * shared::kStageRowFloats + shared::kStageNumber] == stage)
            return &t.rows[size_t(r) * shared::kStageRowFloats];
    return &t.rows[size_t(words[shared::kSpeciesDefaultRow + organ]) * shared::kStageRowFloats];
}

// Property k of a stage row, as particle `id` of plant `plant` draws it in its range.
float property(const TickSettings& ts, const float* row, uint32_t plant, uint32_t id, uint32_t k) {
    const float lo = row[shared::propertyMin(k)], hi = row[shared::propertyMax(k)];
    return lo + (hi - lo) * shared::randomUnit(ts.seed, ts.firstPlant + plant, shared::kGrowPropertyPass, id, k);
}

// Whether a particle lives: its age within its row's LifeTime (none: 0), and not shed in the shade.
bool alive(const TickSettings& ts, const float* row, uint32_t plant, uint32_t id, const float* p) {
    const float lifeTime = property(ts, row, plant, id, shared::kLifeTime);
    return (lifeTime <= 0.0f || p[shared::kParticleAge] < lifeTime) &&
           !shared::shedInShade(property(ts, row, plant, id, shared::kShadeTime), p[shared::kParticleShade]);
}

// The direction of most light at a particle, turned from the field's frame into its plant's own.
glm::vec3 lightInPlantFrame(const TickSettings& ts, const float* p, uint32_t plant) {
    const glm::vec3 d = unpackLightDirection(p[shared::kParticleLightDirection]);
    if (!ts.placements || plant >= ts.placements->size()) return d;
    return glm::normalize(turtle::turnIntoPlant((*ts.placements)[plant], d));
}

// An organ's growth over one tick, by its stage's row; a dead organ grows no more.
void growOrgan(const TickSettings& ts, const float* row, uint32_t plant, float* p) {
    const uint32_t id = std::bit_cast<uint32_t>(p[shared::kParticleId]);
    auto property = [&](uint32_t k) { return grow::property(ts, row, plant, id, k); };
    const bool living = alive(ts, row, plant, id, p);
    const float growing =
        living ? std::clamp(property(shared::kGrowTime) - p[shared::kParticleStageAge], 0.0f, ts.dt) : 0.0f;
    const float vigour = ts.vigour ? (*ts.vigour)[plant] : 1.0f;
    const float room = ts.openLight > 0.0f ? p[shared::kParticleSpace] : 1.0f;
    const float rate = vigour * shared::lightResponse(p[shared::kParticleLight], ts.openLight) * room * growing;
    p[shared::kParticleElongation] += property(shared::kGrowRate) * rate;
    p[shared::kParticleBroadening] += property(shared::kBroadenRate) * rate;
    const float noiseTime = property(shared::kNoiseTime), cone = property(shared::kConeNoise);
    const float age = p[shared::kParticleAge];
    if (growing > 0.0f && noiseTime > 0.0f && cone > 0.0f &&
        shared::periodsUpTo(age + ts.dt, noiseTime) > shared::periodsUpTo(age, noiseTime)) {
        const float u = shared::randomUnit(ts.seed, ts.firstPlant + plant, shared::kGrowNoisePass, id, 2 * ts.tick);
        const float v = shared::randomUnit(ts.seed, ts.firstPlant + plant, shared::kGrowNoisePass, id, 2 * ts.tick + 1);
        p[shared::kParticlePitch] = cone * std::sqrt(u);
        p[shared::kParticleRoll] = kTwoPi * v;
    }
    if (living && ts.openLight > 0.0f)
        p[shared::kParticleShade] =
            p[shared::kParticleLight] < shared::kDeepShade * ts.openLight ? p[shared::kParticleShade] + ts.dt : 0.0f;
}

// The state, as the tick found it, of the stem apex i of `s` stands on (growth_layout.h, kApexLightReach), or
// null.
const shared::ParticleState* stemBelow(const std::vector<shared::ParticleState>& before, const stream::ModuleString& s,
                                       const uint32_t* classes, size_t start, size_t i) {
    uint32_t depth = 0; // branches passed over
    for (size_t j = i; j > start && i - j < shared::kApexLightReach; --j) {
        const uint32_t sym = s.sym[j - 1];
        if (sym == ir::kBranchClose) {
            ++depth;
        } else if (sym == ir::kBranchOpen) {
            if (depth > 0) --depth;
        } else if (depth == 0 && classes[sym] == shared::kGrowStem) {
            return &before[j - 1];
        }
    }
    return nullptr;
}

// The value kGrownValue code `code` names for a module of `plant` whose particle is `p`.
float grownValue(const TickSettings& ts, uint32_t code, const float* p, uint32_t plant, float deriveTime) {
    const float age = p[shared::kParticleAge];
    const uint32_t klass = std::bit_cast<uint32_t>(p[shared::kParticleClass]);
    const uint32_t id = std::bit_cast<uint32_t>(p[shared::kParticleId]);
    const uint32_t species = ir::speciesOfPlant(plant, ts.species);
    const float* row =
        klass < shared::kGrowOrganKinds ? stageRow(*ts.tables, species, klass, p[shared::kParticleStage]) : nullptr;
    const float living = !row || alive(ts, row, plant, id, p) ? 1.0f : 0.0f;
    if (code >= shared::kGrownLeafColor) {
        const float lifeTime = row ? property(ts, row, plant, id, shared::kLifeTime) : 0.0f;
        const uint32_t shade = age < deriveTime ? shared::kLeafYoungShade
                               : lifeTime > 0.0f && age >= (1.0f - shared::kLeafOldAge) * lifeTime
                                   ? shared::kLeafOldShade
                                   : 0u;
        return float(code - shared::kGrownLeafColor + shade);
    }
    switch (code) {
    case shared::kGrownLength:
        return living * p[shared::kParticleElongation];
    case shared::kGrownWidth:
        return living * p[shared::kParticleBroadening];
    case shared::kGrownLeafSize: // a leaf unfolds over its first DeriveTime
        return living * shared::kLeafModelSize * (1.0f + p[shared::kParticleElongation]) *
               std::min(age / deriveTime, 1.0f);
    case shared::kGrownPitch:
        return p[shared::kParticlePitch];
    case shared::kGrownRoll:
        return p[shared::kParticleRoll];
    case shared::kGrownBend: {
        if (!row) return 0.0f;
        const float growTime = property(ts, row, plant, id, shared::kGrowTime);
        const float grown = growTime > 0.0f ? std::min(age / growTime, 1.0f) : 1.0f;
        const float strength = std::max(property(ts, row, plant, id, shared::kStrength), shared::kMinStrength);
        const float bend = property(ts, row, plant, id, shared::kGeotropism) * grown +
                           property(ts, row, plant, id, shared::kWeightFactor) * p[shared::kParticleElongation] /
                               strength;
        return std::clamp(ts.gravity * bend, -shared::kMaxBend, shared::kMaxBend);
    }
    case shared::kGrownLightBend: {
        if (!row) return 0.0f;
        const float growTime = property(ts, row, plant, id, shared::kGrowTime);
        const float grown = growTime > 0.0f ? std::min(age / growTime, 1.0f) : 1.0f;
        return std::clamp(property(ts, row, plant, id, shared::kPhototropism) * grown, -shared::kMaxBend,
                          shared::kMaxBend);
    }
    case shared::kGrownLightX:
    case shared::kGrownLightY:
    case shared::kGrownLightZ:
        return lightInPlantFrame(ts, p, plant)[int(code - shared::kGrownLightX)];
    default:
        return living;
    }
}

} // namespace

void tickCpu(const TickSettings& ts, stream::ModuleString& s) {
    const GrowthTables& t = *ts.tables;
    if (s.particles.size() != s.size()) throw std::invalid_argument("tickCpu: the string carries no particle state");
    const std::vector<shared::ParticleState> before = s.particles;
    for (uint32_t plant = 0; plant + 1 < s.plantStart.size(); ++plant) {
        const uint32_t species = ir::speciesOfPlant(plant, ts.species);
        const uint32_t* classes = t.classes.data() + size_t(species) * t.symbols;
        const size_t start = s.plantStart[plant], end = s.plantStart[plant + 1];
        for (size_t i = start; i < end; ++i) {
            float* p = s.particles[i].value;
            const uint32_t klass = classes[s.sym[i]];
            const bool organ = klass < shared::kGrowOrganKinds;
            const float stage = organ && s.paramCount[i] > 0 ? s.paramsOf(i)[0] : 0.0f;
            // Continues the particle it shares with the modules before it when it is of the particle's class,
            // unless one of them of that class does.
            const uint32_t id = idOf(before[i]);
            bool born = id == 0 || std::bit_cast<uint32_t>(before[i].value[shared::kParticleClass]) != klass;
            for (size_t j = i; !born && j > start && idOf(before[j - 1]) == id; --j)
                born = classes[s.sym[j - 1]] == klass;
            if (born) {
                // An organ is born with the light and room of the organ it comes from (an apex's: those of the stem
                // it stands on), else in the open with room to grow, until the light grid says otherwise.
                const bool fromOrgan =
                    id != 0 && std::bit_cast<uint32_t>(p[shared::kParticleClass]) < shared::kGrowOrganKinds;
                const float light = fromOrgan ? p[shared::kParticleLight] : ts.openLight;
                const float space = fromOrgan ? p[shared::kParticleSpace] : 1.0f;
                s.particles[i] = {};
                p[shared::kParticleStage] = stage;
                p[shared::kParticleClass] = std::bit_cast<float>(klass);
                const uint32_t fresh = shared::randomBits(ts.seed, ts.firstPlant + plant, shared::kGrowIdentityPass,
                                                          uint32_t(i - start), ts.tick) |
                                       1u;
                p[shared::kParticleId] = std::bit_cast<float>(fresh);
                if (organ) {
                    p[shared::kParticleLight] = light;
                    p[shared::kParticleSpace] = space;
                }
            } else if (p[shared::kParticleStage] != stage) {
                p[shared::kParticleStage] = stage;
                p[shared::kParticleStageAge] = 0.0f;
            }
            if (klass == shared::kGrowApex && ts.openLight > 0.0f)
                if (const shared::ParticleState* stem = stemBelow(before, s, classes, start, i)) {
                    p[shared::kParticleLight] = stem->value[shared::kParticleLight];
                    p[shared::kParticleSpace] = stem->value[shared::kParticleSpace];
                }
            if (organ) {
                if (const float* row = stageRow(t, species, klass, stage)) growOrgan(ts, row, plant, p);
            }
            p[shared::kParticleAge] += ts.dt;
            p[shared::kParticleStageAge] += ts.dt;
        }
    }
}

void growSizesCpu(const TickSettings& ts, const std::vector<float>& deriveTimes, stream::ModuleString& drawn) {
    const GrowthTables& t = *ts.tables;
    for (uint32_t plant = 0; plant + 1 < drawn.plantStart.size(); ++plant) {
        const uint32_t species = ir::speciesOfPlant(plant, ts.species);
        const uint32_t* words = t.species.data() + size_t(species) * shared::kSpeciesGrowthWords;
        if (words[shared::kSpeciesFlags] & shared::kSpeciesGrowsSegments)
            for (size_t i = drawn.plantStart[plant]; i < drawn.plantStart[plant + 1]; ++i) {
                // A segment (not the letter of an `@` command) as long as the part of its first DeriveTime it
                // has lived; one without a length gets the turtle's step. A sphere or disc's radius likewise.
                const uint32_t klass = t.classes[size_t(species) * t.symbols + drawn.sym[i]];
                const bool afterAt = i > drawn.plantStart[plant] && drawn.sym[i - 1] == t.atSymbol;
                if (!(klass & (afterAt ? shared::kGrowRadius : shared::kGrowSegment))) continue;
                const float grown = std::min(drawn.particles[i].value[shared::kParticleAge] / deriveTimes[plant], 1.0f);
                if (grown >= 1.0f) continue;
                float& length = drawn.params[i * size_t(drawn.stride)];
                if (afterAt) { // a radius it has, or the line width's, which it keeps
                    if (drawn.paramCount[i] > 0) length *= grown;
                    continue;
                }
                if (drawn.paramCount[i] > 0) {
                    length *= grown;
                } else {
                    length = std::bit_cast<float>(words[shared::kSpeciesSegmentStep]) * grown;
                    drawn.paramCount[i] = 1;
                }
            }
        if (!(words[shared::kSpeciesFlags] & shared::kSpeciesDrawsGrowth)) continue;
        for (size_t i = drawn.plantStart[plant]; i < drawn.plantStart[plant + 1]; ++i) {
            float* params = drawn.params.data() + i * size_t(drawn.stride);
            for (uint32_t k = 0; k < drawn.paramCount[i]; ++k) {
                const float code = shared::kGrownValue - params[k];
                const bool named = code < float(shared::kGrownCodes) ||
                                   (code >= float(shared::kGrownLeafColor) && code < float(shared::kGrownLeafColorEnd));
                if (code >= 0.0f && named && code == std::floor(code))
                    params[k] = grownValue(ts, uint32_t(code), drawn.particles[i].value, plant, deriveTimes[plant]);
            }
        }
    }
}

} // namespace simeco::grow
