// Greedy walk, pass 3: each chunk walks from its entry state; modules consumed by a production that started
// before them produce nothing.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) buffer Choices { uint choices[]; };
layout(set = 0, binding = 1, std430) readonly buffer PlantStart { uint plantStart[]; };
layout(set = 0, binding = 2, std430) readonly buffer Entries { uint entries[]; };
layout(set = 0, binding = 3, std430) buffer Counts { uint counts[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

#include "compute/derive/greedy_chunks.glsl"

void main() {
    uint chunk = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    uint first = chunk * kGreedyChunk, count = greedyModules();
    if (first >= count) return;
    uint last = min(first + kGreedyChunk, count);
    uint state = entries[chunk];
    for (uint i = first; i < last; ++i) {
        bool starts;
        uint next = walkStep(i, state, starts);
        if (!starts && choices[i] != kChoiceDropped) {
            counts[i] = 0u;
            choices[i] = kChoiceDropped;
        }
        state = next;
    }
}
