// Bracket depth, pass 4: every bracket's partner, found once per string on the finished min tree, so that
// kernels walking contexts jump over a branch with one load instead of a search of the tree. partners[i] is the
// `]` closing the `[` at i, or the `[` opening the `]` at i: the module after the last position before it whose
// depth is below its own, when that module is a `[`; kNoModule when there is none. Readers check plant bounds.
// Other modules' entries are not written.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Symbols { uint symbols[]; };
layout(set = 0, binding = 1, std430) readonly buffer Tree { int depthTree[]; };
layout(set = 0, binding = 2, std430) readonly buffer LevelInfo { uint levelInfo[]; };
layout(set = 0, binding = 3, std430) writeonly buffer Partners { uint partners[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

uint symOf(uint i) { return symbols[i] & kSymbolMask; }

#include "compute/derive/depth_tree.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= (pc.count != kCountOnDevice ? pc.count : levelInfo[kMaxDepthLevels])) return;
    uint sym = symOf(i);
    if (sym == kOpen) {
        partners[i] = firstBelow(i + 1u, depthAt(0u, i));
    } else if (sym == kClose) {
        int k = lastBelow(int(i) - 1, depthAt(0u, i) + 1);
        partners[i] = k == kNoneBelow || symOf(uint(k + 1)) != kOpen ? kNoModule : uint(k + 1);
    }
}
