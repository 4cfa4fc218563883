// Where to look up a module's plant: hints[b] is the plant holding module b * kPlantHintBlock (the last plant
// starting at or before it). A module's plant lies between its block's hint and the next block's, usually the
// same plant, so the derivation kernels search a range of one or two plants instead of the whole table.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Starts { uint plantStart[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Hints { uint hints[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint b = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    uint count = pc.count != kCountOnDevice ? pc.count : plantStart[pc.plants];
    if (b > plantHintBlocks(count)) return;
    uint i = min(b * kPlantHintBlock, count);
    uint low = 0u, high = pc.plants - 1u;
    while (low < high) {
        uint mid = (low + high + 1u) / 2u;
        if (plantStart[mid] <= i) low = mid; else high = mid - 1u;
    }
    hints[b] = low;
}
