// Greedy walk, pass 1: each chunk's state function (see greedy_chunks.glsl).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Choices { uint choices[]; };
layout(set = 0, binding = 1, std430) readonly buffer PlantStart { uint plantStart[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Functions { uint functions[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

#include "compute/derive/greedy_chunks.glsl"

void main() {
    uint chunk = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    uint first = chunk * kGreedyChunk, count = greedyModules();
    if (first >= count) return;
    uint last = min(first + kGreedyChunk, count);
    uint packed = 0u;
    for (uint entry = 0u; entry < pc.level; ++entry) { // pc.level: the number of states (longest predecessor)
        uint state = entry;
        bool starts;
        for (uint i = first; i < last; ++i) state = walkStep(i, state, starts);
        packed |= state << (4u * entry);
    }
    functions[chunk] = packed;
}
