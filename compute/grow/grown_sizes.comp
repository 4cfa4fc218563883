// The drawn string's sizes from its particles: each kGrownValue code a SimEco homomorphism wrote as a parameter
// is replaced, in place, with the value it names (compute/shared/growth_layout.h); a grammar's segments are
// shortened to the part of their first DeriveTime their particle has lived. The CPU reference is growSizesCpu in
// src/grow/tick_cpu.cpp.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/config.h"
#include "compute/shared/derive_layout.h"
#include "compute/shared/growth_layout.h"
#include "compute/shared/organ_layout.h"
#include "compute/shared/particle_layout.h"
#include "compute/shared/random.h"

layout(local_size_x = kGrowWorkgroupSize) in;
layout(set = 0, binding = 0, std430) buffer Symbols { uint symbols[]; };
layout(set = 0, binding = 1, std430) buffer Params { float params[]; };
layout(set = 0, binding = 2, std430) readonly buffer Starts { uint plantStart[]; };
layout(set = 0, binding = 3, std430) readonly buffer Particles { float particles[]; };
layout(set = 0, binding = 4, std430) readonly buffer SpeciesWords { uint speciesWords[]; };
layout(set = 0, binding = 5, std430) readonly buffer DeriveTimes { float deriveTimes[]; };
layout(set = 0, binding = 6, std430) readonly buffer Rows { float rows[]; };
layout(set = 0, binding = 7, std430) readonly buffer Classes { uint classes[]; };
layout(set = 0, binding = 8, std430) readonly buffer Placements { PlantPlacement placements[]; };
layout(push_constant) uniform Push { GrowPush pc; };

#include "compute/grow/growth.glsl"
#include "compute/grow/light_direction.glsl"
#include "compute/turtle/organ_bounds.glsl"

float particle(uint i, uint slot) { return particles[kParticleStateFloats * i + slot]; }

// The direction of most light at particle i, turned from the field's frame into its plant's own (the transpose of
// the plant's rotation).
vec3 lightInPlantFrame(uint i, uint plant) {
    return normalize(turnIntoPlant(placements[plant], unpackLightDirection(particle(i, kParticleLightDirection))));
}

// What every value of a module's particle starts from, found once per module.
struct Grown {
    uint i, plant, id, row;
    float age, living;
    bool rowed;
    bool lit;   // `light` holds the direction of most light
    vec3 light; // in the plant's frame
};

Grown grownOf(uint i, uint plant) {
    Grown g;
    g.i = i;
    g.plant = plant;
    g.age = particle(i, kParticleAge);
    uint klass = floatBitsToUint(particle(i, kParticleClass));
    uint species = plant % pc.species;
    g.rowed = klass < kGrowOrganKinds && hasRows(species, klass);
    g.row = g.rowed ? stageRow(species, klass, particle(i, kParticleStage)) : 0u;
    g.id = floatBitsToUint(particle(i, kParticleId));
    g.living = !g.rowed || alive(g.row, plant, g.id, g.age, particle(i, kParticleShade)) ? 1.0 : 0.0;
    g.lit = false;
    return g;
}

float grownValue(uint code, inout Grown g) {
    uint i = g.i, plant = g.plant, row = g.row, id = g.id;
    float age = g.age;
    if (code >= kGrownLeafColor) {
        float lifeTime = g.rowed ? property(row, kLifeTime, plant, id) : 0.0;
        uint shade = age < deriveTimes[plant]                                   ? kLeafYoungShade
                     : lifeTime > 0.0 && age >= (1.0 - kLeafOldAge) * lifeTime ? kLeafOldShade
                                                                               : 0u;
        return float(code - kGrownLeafColor + shade);
    }
    switch (code) {
    case kGrownLength: return g.living * particle(i, kParticleElongation);
    case kGrownWidth: return g.living * particle(i, kParticleBroadening);
    case kGrownLeafSize: // a leaf unfolds over its first DeriveTime
        return g.living * kLeafModelSize * (1.0 + particle(i, kParticleElongation)) *
               min(age / deriveTimes[plant], 1.0);
    case kGrownPitch: return particle(i, kParticlePitch);
    case kGrownRoll: return particle(i, kParticleRoll);
    case kGrownBend: {
        if (!g.rowed) return 0.0;
        float growTime = property(row, kGrowTime, plant, id);
        float grown = growTime > 0.0 ? min(age / growTime, 1.0) : 1.0;
        float strength = max(property(row, kStrength, plant, id), kMinStrength);
        float bend = property(row, kGeotropism, plant, id) * grown +
                     property(row, kWeightFactor, plant, id) * particle(i, kParticleElongation) / strength;
        return clamp(pc.gravity * bend, -kMaxBend, kMaxBend);
    }
    case kGrownLightBend: {
        if (!g.rowed) return 0.0;
        float growTime = property(row, kGrowTime, plant, id);
        float grown = growTime > 0.0 ? min(age / growTime, 1.0) : 1.0;
        return clamp(property(row, kPhototropism, plant, id) * grown, -kMaxBend, kMaxBend);
    }
    case kGrownLightX:
    case kGrownLightY:
    case kGrownLightZ:
        if (!g.lit) {
            g.light = lightInPlantFrame(i, plant);
            g.lit = true;
        }
        return g.light[code - kGrownLightX];
    default: return g.living;
    }
}

// A grammar's segment (not the letter of an `@` command) as long as the part of its first DeriveTime it has
// lived; a segment without a length gets the turtle's step. A sphere or disc's radius likewise.
void growSegment(uint i, uint plant, uint species) {
    uint sym = symbols[i] & kSymbolMask;
    bool afterAt = i > plantStart[plant] && (symbols[i - 1u] & kSymbolMask) == pc.atSymbol;
    if ((classes[species * pc.symbols + sym] & (afterAt ? kGrowRadius : kGrowSegment)) == 0u) return;
    float grown = min(particle(i, kParticleAge) / deriveTimes[plant], 1.0);
    if (grown >= 1.0) return;
    if (afterAt) { // a radius it has, or the line width's, which it keeps
        if ((symbols[i] >> kSymbolBits) > 0u) params[pc.stride * i] *= grown;
        return;
    }
    if ((symbols[i] >> kSymbolBits) > 0u) {
        params[pc.stride * i] *= grown;
    } else {
        float step = uintBitsToFloat(speciesWords[species * kSpeciesGrowthWords + kSpeciesSegmentStep]);
        params[pc.stride * i] = step * grown;
        symbols[i] = sym | (1u << kSymbolBits);
    }
}

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount()) return;
    uint plant = plantOf(i, pc.plants);
    uint species = plant % pc.species;
    uint flags = speciesWords[species * kSpeciesGrowthWords + kSpeciesFlags];
    if ((flags & kSpeciesGrowsSegments) != 0u) growSegment(i, plant, species);
    if ((flags & kSpeciesDrawsGrowth) == 0u) return;
    uint count = symbols[i] >> kSymbolBits;
    Grown g;
    bool found = false;
    for (uint k = 0u; k < count; ++k) {
        float code = kGrownValue - params[pc.stride * i + k];
        bool named = code < float(kGrownCodes) || (code >= float(kGrownLeafColor) && code < float(kGrownLeafColorEnd));
        if (code < 0.0 || !named || code != floor(code)) continue;
        if (!found) g = grownOf(i, plant);
        found = true;
        params[pc.stride * i + k] = grownValue(uint(code), g);
    }
}
