// After a step without decomposition: each module's particle state goes to every module of its successor (a copy
// is a successor of one module), at the positions the step's scan gave it. With the scan fused into the step's
// passes (pc.level, the tile size, above zero) a module's position is its tile's offset plus the counts before
// it in the tile, stored above its choice (kChoiceBits); otherwise `positions` holds the scanned counts. A module
// whose successor is empty, or that a cut dropped, takes its state away.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/config.h"
#include "compute/shared/derive_layout.h"
#include "compute/shared/particle_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Positions { uint positions[]; };
layout(set = 0, binding = 1, std430) readonly buffer TileOffsets { uint tileOffsets[]; };
layout(set = 0, binding = 2, std430) readonly buffer ParticlesIn { vec4 particlesIn[]; };
layout(set = 0, binding = 3, std430) writeonly buffer ParticlesOut { vec4 particlesOut[]; };
// For counts only the device knows (kCountOnDevice: steps recorded one after the other): the input's plant table,
// whose last entry is its modules, and the scan's total, the new stream's.
layout(set = 0, binding = 4, std430) readonly buffer InputStarts { uint inputStarts[]; };
layout(set = 0, binding = 5, std430) readonly buffer ScanTotal { uint scanTotal; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };
layout(constant_id = 0) const uint kChoiceBits = 0u; // GeneratedKernels::choiceBits

uint modules, total;

// Where module i's successor starts in the new stream; the stream's end past the last module.
uint positionOf(uint i) {
    if (i >= modules) return total;
    if (pc.level == 0u) return positions[i];
    return tileOffsets[i / pc.level] + (positions[i] >> kChoiceBits);
}

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    modules = pc.count != kCountOnDevice ? pc.count : inputStarts[pc.plants];
    total = pc.total != kCountOnDevice ? pc.total : scanTotal;
    if (i >= modules) return;
    uint first = positionOf(i), end = positionOf(i + 1u);
    vec4 state[kParticleStateVec4s];
    for (uint v = 0u; v < kParticleStateVec4s; ++v) state[v] = particlesIn[kParticleStateVec4s * i + v];
    for (uint j = first; j < end; ++j)
        for (uint v = 0u; v < kParticleStateVec4s; ++v) particlesOut[kParticleStateVec4s * j + v] = state[v];
}
