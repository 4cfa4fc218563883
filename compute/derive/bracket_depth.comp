// Bracket depth, pass 1: +1 for `[`, -1 (two's complement) for `]`, 0 otherwise; an exclusive scan of these
// gives the depth before each module.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Symbols { uint symbols[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Deltas { uint deltas[]; };
layout(set = 0, binding = 2, std430) readonly buffer LevelInfo { uint levelInfo[]; }; // level 0's size: n
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= (pc.count != kCountOnDevice ? pc.count : levelInfo[kMaxDepthLevels])) return;
    uint sym = symbols[i] & kSymbolMask;
    deltas[i] = sym == 0u ? 1u : sym == 1u ? 0xFFFFFFFFu : 0u;
}
