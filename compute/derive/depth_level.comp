// Bracket depth, pass 3 (once per level): each node of the min tree is the smaller of its two children.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) buffer Tree { int tree[]; };
layout(set = 0, binding = 1, std430) readonly buffer LevelInfo { uint levelInfo[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint k = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (k >= (pc.count != kCountOnDevice ? pc.count : levelInfo[kMaxDepthLevels + pc.level])) return;
    uint below = levelInfo[pc.level - 1u];
    uint belowSize = levelInfo[kMaxDepthLevels + pc.level - 1u];
    int left = tree[below + 2u * k];
    int value = 2u * k + 1u < belowSize ? min(left, tree[below + 2u * k + 1u]) : left;
    tree[levelInfo[pc.level] + k] = value;
}
