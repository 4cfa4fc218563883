// The drawn string's sizes from its particles: each kGrownValue code a SimEco homomorphism wrote as a parameter
// is replaced, in place, with the value it names (compute/shared/growth_layout.h). The CPU reference is
// growSizesCpu in src/grow/tick_cpu.cpp.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/config.h"
#include "compute/shared/derive_layout.h"
#include "compute/shared/growth_layout.h"
#include "compute/shared/particle_layout.h"

layout(local_size_x = kGrowWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Symbols { uint symbols[]; };
layout(set = 0, binding = 1, std430) buffer Params { float params[]; };
layout(set = 0, binding = 2, std430) readonly buffer Starts { uint plantStart[]; };
layout(set = 0, binding = 3, std430) readonly buffer Particles { float particles[]; };
layout(set = 0, binding = 4, std430) readonly buffer SpeciesWords { uint speciesWords[]; };
layout(set = 0, binding = 5, std430) readonly buffer DeriveTimes { float deriveTimes[]; };
layout(push_constant) uniform Push { GrowPush pc; };

#include "compute/grow/growth.glsl"

float particle(uint i, uint slot) { return particles[kParticleStateFloats * i + slot]; }

float grownValue(uint code, uint i, float deriveTime) {
    switch (code) {
    case kGrownLength: return particle(i, kParticleElongation);
    case kGrownWidth: return particle(i, kParticleBroadening);
    case kGrownLeafSize: // a leaf unfolds over its first DeriveTime
        return kLeafModelSize * (1.0 + particle(i, kParticleElongation)) *
               min(particle(i, kParticleAge) / deriveTime, 1.0);
    case kGrownPitch: return particle(i, kParticlePitch);
    case kGrownRoll: return particle(i, kParticleRoll);
    default: return -particle(i, kParticleRoll);
    }
}

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= pc.count) return;
    uint plant = plantOf(i, pc.plants);
    if ((speciesWords[(plant % pc.species) * kSpeciesGrowthWords + kSpeciesFlags] & kSpeciesDrawsGrowth) == 0u) return;
    uint count = symbols[i] >> kSymbolBits;
    for (uint k = 0u; k < count; ++k) {
        float code = kGrownValue - params[pc.stride * i + k];
        if (code >= 0.0 && code < float(kGrownCodes) && code == floor(code))
            params[pc.stride * i + k] = grownValue(uint(code), i, deriveTimes[plant]);
    }
}
