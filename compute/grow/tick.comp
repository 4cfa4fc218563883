// One growth tick of every particle of the derived string (compute/shared/growth_layout.h): which modules continue
// a particle and which are born, aging, each living organ's growth by its stage row for its GrowTime (times its
// light's response and its room to grow where a light grid runs), its cone noise every NoiseTime while it grows,
// its seconds in deep shade, and an apex's light and room from the stem it stands on. Reads the particles as the
// last tick left them and writes the next states into particlesOut, since a module's birth depends on the states
// of the modules before it. The CPU reference is src/grow/tick_cpu.cpp.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/config.h"
#include "compute/shared/derive_layout.h"
#include "compute/shared/growth_layout.h"
#include "compute/shared/particle_layout.h"
#include "compute/shared/random.h"

layout(local_size_x = kGrowWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Symbols { uint symbols[]; };
layout(set = 0, binding = 1, std430) readonly buffer Params { float params[]; };
layout(set = 0, binding = 2, std430) readonly buffer Starts { uint plantStart[]; };
layout(set = 0, binding = 3, std430) readonly buffer ParticlesIn { float particlesIn[]; };
layout(set = 0, binding = 4, std430) writeonly buffer ParticlesOut { float particlesOut[]; };
layout(set = 0, binding = 5, std430) readonly buffer Classes { uint classes[]; };
layout(set = 0, binding = 6, std430) readonly buffer SpeciesWords { uint speciesWords[]; };
layout(set = 0, binding = 7, std430) readonly buffer Rows { float rows[]; };
layout(set = 0, binding = 8, std430) readonly buffer Vigour { float vigour[]; };
layout(push_constant) uniform Push { GrowPush pc; };

#include "compute/grow/growth.glsl"

const float kTwoPi = 6.28318530717958647692;

uint idOf(uint i) { return floatBitsToUint(particlesIn[kParticleStateFloats * i + kParticleId]); }
uint classOf(uint species, uint i) { return classes[species * pc.symbols + (symbols[i] & kSymbolMask)]; }

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount()) return;
    uint plant = plantOf(i, pc.plants);
    uint species = plant % pc.species;
    uint start = plantStart[plant];
    float p[kParticleStateFloats];
    for (uint k = 0u; k < kParticleStateFloats; ++k) p[k] = particlesIn[kParticleStateFloats * i + k];
    uint klass = classOf(species, i);
    bool organ = klass < kGrowOrganKinds;
    float stage = organ && (symbols[i] >> kSymbolBits) > 0u ? params[pc.stride * i] : 0.0;

    // Continues the particle it shares with the modules before it when it is of the particle's class, unless one
    // of them of that class does.
    uint id = idOf(i);
    bool born = id == 0u || floatBitsToUint(p[kParticleClass]) != klass;
    for (uint j = i; !born && j > start && idOf(j - 1u) == id; --j) born = classOf(species, j - 1u) == klass;
    if (born) {
        // An organ is born with the light and room of the organ it comes from (an apex's: those of the stem it
        // stands on), else in the open with room to grow, until the light grid says otherwise.
        bool fromOrgan = id != 0u && floatBitsToUint(p[kParticleClass]) < kGrowOrganKinds;
        float light = fromOrgan ? p[kParticleLight] : pc.openLight, space = fromOrgan ? p[kParticleSpace] : 1.0;
        for (uint k = 0u; k < kParticleStateFloats; ++k) p[k] = 0.0;
        p[kParticleStage] = stage;
        p[kParticleClass] = uintBitsToFloat(klass);
        uint identity = randomBits(pc.seed, pc.firstPlant + plant, kGrowIdentityPass, i - start, pc.tick) | 1u;
        p[kParticleId] = uintBitsToFloat(identity);
        if (organ) {
            p[kParticleLight] = light;
            p[kParticleSpace] = space;
        }
    } else if (p[kParticleStage] != stage) {
        p[kParticleStage] = stage;
        p[kParticleStageAge] = 0.0;
    }

    if (klass == kGrowApex && pc.openLight > 0.0) {
        uint depth = 0u; // branches passed over
        for (uint j = i; j > start && i - j < kApexLightReach; --j) {
            uint sym = symbols[j - 1u] & kSymbolMask;
            if (sym == 1u) { // `]`
                ++depth;
            } else if (sym == 0u) { // `[`
                if (depth > 0u) --depth;
            } else if (depth == 0u && classOf(species, j - 1u) == kGrowStem) {
                p[kParticleLight] = particlesIn[kParticleStateFloats * (j - 1u) + kParticleLight];
                p[kParticleSpace] = particlesIn[kParticleStateFloats * (j - 1u) + kParticleSpace];
                break;
            }
        }
    }
    if (organ && hasRows(species, klass)) {
        uint row = stageRow(species, klass, stage);
        uint self = floatBitsToUint(p[kParticleId]);
        // A dead organ grows no more.
        bool living = alive(row, plant, self, p[kParticleAge], p[kParticleShade]);
        float growing = living ? clamp(property(row, kGrowTime, plant, self) - p[kParticleStageAge], 0.0, pc.dt) : 0.0;
        float room = pc.openLight > 0.0 ? p[kParticleSpace] : 1.0;
        float rate = vigour[plant] * lightResponse(p[kParticleLight], pc.openLight) * room * growing;
        p[kParticleElongation] += property(row, kGrowRate, plant, self) * rate;
        p[kParticleBroadening] += property(row, kBroadenRate, plant, self) * rate;
        float noiseTime = property(row, kNoiseTime, plant, self), cone = property(row, kConeNoise, plant, self);
        if (growing > 0.0 && noiseTime > 0.0 && cone > 0.0 &&
            periodsUpTo(p[kParticleAge] + pc.dt, noiseTime) > periodsUpTo(p[kParticleAge], noiseTime)) {
            float u = randomUnit(pc.seed, pc.firstPlant + plant, kGrowNoisePass, self, 2u * pc.tick);
            float v = randomUnit(pc.seed, pc.firstPlant + plant, kGrowNoisePass, self, 2u * pc.tick + 1u);
            p[kParticlePitch] = cone * sqrt(u);
            p[kParticleRoll] = kTwoPi * v;
        }
        if (living && pc.openLight > 0.0)
            p[kParticleShade] = p[kParticleLight] < kDeepShade * pc.openLight ? p[kParticleShade] + pc.dt : 0.0;
    }
    p[kParticleAge] += pc.dt;
    p[kParticleStageAge] += pc.dt;
    for (uint k = 0u; k < kParticleStateFloats; ++k) particlesOut[kParticleStateFloats * i + k] = p[k];
}
