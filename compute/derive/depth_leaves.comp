// Bracket depth, pass 2: the inclusive depth D[i] (exclusive scan plus the module's own delta) as the leaves of
// the min tree that derivation kernels match brackets with.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Deltas { uint deltas[]; };
layout(set = 0, binding = 1, std430) readonly buffer Before { uint before[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Tree { int tree[]; };
layout(set = 0, binding = 3, std430) readonly buffer LevelInfo { uint levelInfo[]; }; // level 0's size: n
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= (pc.count != kCountOnDevice ? pc.count : levelInfo[kMaxDepthLevels])) return;
    tree[i] = int(before[i] + deltas[i]);
}
