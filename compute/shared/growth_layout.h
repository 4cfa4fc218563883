// The growth tick's tables and push constants, shared by C++ (src/grow/) and GLSL (compute/grow/).
//
// Each tick every module of the derived string is a particle that ages and grows (compute/grow/tick.comp; the
// CPU reference is grow/tick_cpu.cpp). What it grows by comes from its species' stage table: a SimEco organ's
// module (A S L F T R, its first parameter the stage) reads the row of its stage, else its organ's Default row,
// each property a range [min, max] drawn once per particle. Other modules only age.
//
// Which modules continue a particle: a derivation step gives every module of a successor the state of the module
// it replaces, so the modules that share a particle's identity and stand together came from one module. The
// first of them of the particle's class (an organ kind, or for other modules their symbol) continues the
// particle, with its age, length and width (a stem rewritten into a stem of the next stage goes on growing);
// the others are born there: they start at zero with an identity of their own, at the tip of the module before
// them in the string (where the turtle puts them).
//
// The drawn string (the derived string under the homomorphism, each module with its origin's state) gets its
// sizes from the particles: SimEco's homomorphism writes kGrownValue codes as the parameters of the modules that
// draw an organ, and compute/grow/grown_sizes.comp replaces each code with the value it names.
#ifndef SIMECO_SHARED_GROWTH_LAYOUT_H
#define SIMECO_SHARED_GROWTH_LAYOUT_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kGrowWorkgroupSize = 128u;

// Module classes (per species and symbol): the six SimEco organ kinds (ir::EcoOrganKind's order), then every
// other module as kGrowPlainClass + its symbol (with kGrowSegment or kGrowRadius where a grammar's segment or round
// organ grows).
SIMECO_CONST kGrowOrganKinds = 6u;
SIMECO_CONST kGrowApex = 0u;
SIMECO_CONST kGrowStem = 1u;
SIMECO_CONST kGrowPlainClass = 8u;
// An apex draws nothing, so the light grid gives it no light of its own: where a grid runs it takes the light and
// the room to grow of the stem it stands on, the nearest stem before it on its own axis (passing over the branches
// between them and out of the branch it opens), looked for among the kApexLightReach modules before it.
SIMECO_CONST kApexLightReach = 64u;

// A species' words (kSpeciesGrowthWords per species): per organ kind its first stage row, its row count and its
// Default row (kGrowNoRow: none), then flags.
SIMECO_CONST kSpeciesGrowthWords = 20u;
SIMECO_CONST kSpeciesFirstRow = 0u;
SIMECO_CONST kSpeciesRowCount = 6u;
SIMECO_CONST kSpeciesDefaultRow = 12u;
SIMECO_CONST kSpeciesFlags = 18u;
SIMECO_CONST kSpeciesSegmentStep = 19u; // a float's bits: the turtle's step, the length of a segment `F`
SIMECO_CONST kGrowNoRow = 0xFFFFFFFFu;
// The species' drawn modules carry kGrownValue codes (SimEco's homomorphism).
SIMECO_CONST kSpeciesDrawsGrowth = 1u;
// A cpfg or quick grammar's species: each drawn segment (F f G g, its class marked kGrowSegment) grows to its
// length over the first DeriveTime of its particle, and so does the radius of each sphere or disc `@O(r)`,
// `@c(r)`, `@o(r)` (the letter after `@` marked kGrowRadius), as the thesis's clouds grow their spheres.
SIMECO_CONST kSpeciesGrowsSegments = 2u;
SIMECO_CONST kGrowSegment = 0x80000000u;
SIMECO_CONST kGrowRadius = 0x40000000u;

// A stage row: the stage number, then each property's min and max (padded to a multiple of four floats); rows of an
// organ sorted by stage.
SIMECO_CONST kStageRowFloats = 24u;
SIMECO_CONST kStageNumber = 0u;
SIMECO_CONST kGrowRate = 0u;
SIMECO_CONST kGrowTime = 1u;
SIMECO_CONST kLifeTime = 2u;
SIMECO_CONST kBroadenRate = 3u;
SIMECO_CONST kWeightFactor = 4u;
SIMECO_CONST kConeNoise = 5u;
SIMECO_CONST kNoiseTime = 6u;
SIMECO_CONST kStrength = 7u;
SIMECO_CONST kGeotropism = 8u;
SIMECO_CONST kPhototropism = 9u;
SIMECO_CONST kShadeTime = 10u;
SIMECO_CONST kStageProperties = 11u;
SIMECO_FN uint propertyMin(uint property) {
    return 1u + 2u * property;
}
SIMECO_FN uint propertyMax(uint property) {
    return 2u + 2u * property;
}

// The random streams of growth: passes far above any derivation step's, keyed by plant and particle identity.
SIMECO_CONST kGrowPropertyPass = 0xFFFFFF00u; // a property's draw in its range: draw = property
SIMECO_CONST kGrowNoisePass = 0xFFFFFF01u;    // a cone noise turn: draw = 2 x tick (+1)
SIMECO_CONST kGrowIdentityPass = 0xFFFFFF02u; // a newborn particle's identity: module index, draw = tick

// Parameter codes of drawn modules: kGrownValue - code, replaced by the particle's value. An organ whose
// LifeTime has passed is dead: its sizes are 0 and a dead stem's `alive` is 0, which scales everything after it
// in its branch to nothing (the branch is shed).
SIMECO_CONST_FLOAT kGrownValue = -65536.0f;
SIMECO_CONST kGrownLength = 0u;   // its elongation
SIMECO_CONST kGrownWidth = 1u;    // its broadening
SIMECO_CONST kGrownLeafSize = 2u; // the leaf model's size x (1 + its growth), unfolding over its first DeriveTime
SIMECO_CONST kGrownPitch = 3u;    // its pitch, in radians
SIMECO_CONST kGrownRoll = 4u;     // its roll, in radians
SIMECO_CONST kGrownBend = 5u;     // its tropism elasticity: geotropism and bending under its weight
SIMECO_CONST kGrownAlive = 6u;    // 1 while it lives, 0 once its LifeTime has passed or it is shed in the shade
SIMECO_CONST kGrownLightBend = 7u; // its phototropism: how far it turns toward the light (Phototropism x its growth)
SIMECO_CONST kGrownLightX = 8u;    // the direction of most light at it, in its plant's own frame
SIMECO_CONST kGrownLightY = 9u;
SIMECO_CONST kGrownLightZ = 10u;
SIMECO_CONST kGrownCodes = 11u;
// A leaf's colour: code kGrownLeafColor + c names palette colour c while the leaf is mature, c + 1 while it is
// young (unfolding, its first DeriveTime) and c + 2 once it is old (the last kLeafOldAge of its LifeTime).
SIMECO_CONST kGrownLeafColor = 16u;
SIMECO_CONST kGrownLeafColorEnd = kGrownLeafColor + 256u;
SIMECO_CONST kLeafYoungShade = 1u;
SIMECO_CONST kLeafOldShade = 2u;
SIMECO_CONST_FLOAT kLeafOldAge = 0.3f;
// Bending: a stem's elasticity is gravity (as a multiple of Earth's) x (Geotropism x its growth so far, up to
// one GrowTime, + WeightFactor x its length / Strength), within +-kMaxBend. Strength below kMinStrength counts
// as kMinStrength.
SIMECO_CONST_FLOAT kMaxBend = 1.0f;
SIMECO_CONST_FLOAT kMinStrength = 0.05f;
// Phototropism: a stem turns toward the direction of most light at it by Phototropism x its growth so far (up to
// one GrowTime) x |H x light| (the turtle's `phototropism`), within kMaxBend.

// Shedding in the shade (where a light grid runs): an organ whose light stays below kDeepShade of the open's for its
// stage's ShadeTime without a break is shed (dead, as at the end of its LifeTime; a stem takes its branch with it).
// kParticleShade counts the seconds; once it reaches ShadeTime it counts no more, so the organ stays shed.
SIMECO_CONST_FLOAT kDeepShade = 0.15f;
SIMECO_FN bool shedInShade(float shadeTime, float shadeSeconds) {
    return shadeTime > 0.0f && shadeSeconds >= shadeTime;
}

// Cone noise turns an organ whenever its age passes a multiple of NoiseTime while it grows: the multiples of
// `period` up to `age`, found with products (exact on every device) rather than a quotient (which a device may round
// differently).
SIMECO_FN uint periodsUpTo(float age, float period) {
    uint k = uint(age / period);
    while (k > 0u && float(k) * period > age) k -= 1u;
    while (float(k + 1u) * period <= age) k += 1u;
    return k;
}
// A leaf model's size before it grows, in the scripts' units: the seed plants' leaves are about as long as an
// internode grows in its first stages (GrowRate 0.5 for GrowTime 3 s).
SIMECO_CONST_FLOAT kLeafModelSize = 3.0f;

// Push constants of tick.comp and grown_sizes.comp. The plant table's last entry counts the modules, `count` bounds
// them (compute/grow/growth.glsl, moduleCount()).
struct GrowPush {
    float dt;  // seconds this tick advances
    uint tick; // ticks before this one
    uint seed;
    uint plants;
    uint species;
    uint symbols; // alphabet size: the class table's row length
    uint count;
    uint stride;   // parameters per module
    float gravity; // the scene's gravity, as a multiple of Earth's (9.81)
    uint atSymbol; // the alphabet's `@` (a segment letter after it is a command's prefix), else 0xFFFFFFFF
    float openLight; // the light in the open where a light grid runs (organs grow by their light), else 0
    uint firstPlant; // the random stream of plant 0 (grow::TickSettings::firstPlant)
};

// Push constants of tick_groups.comp and particles_copy.comp: the modules are the plant table's last entry, at most
// `bound`.
struct GrowGroupsPush {
    uint plants;
    uint bound;
    uint maxGroupsX; // the device's maxComputeWorkGroupCount[0]
};

// How an organ's growth follows its light (kParticleLight) where a light grid runs: a saturating response,
// light / (light + K), K (half saturation) a quarter of the open's light, scaled so that an organ in the open
// grows at its stage's rates; 0.36 of them in a tenth of the open's light, nothing in the dark.
SIMECO_CONST_FLOAT kLightHalfSaturation = 0.25f;
SIMECO_FN float lightResponse(float light, float openLight) {
    if (openLight <= 0.0f) return 1.0f;
    float halfLight = kLightHalfSaturation * openLight;
    float lit = light > 0.0f ? light : 0.0f;
    return lit / (lit + halfLight) * (openLight + halfLight) / openLight;
}

SIMECO_SHARED_END

#endif
