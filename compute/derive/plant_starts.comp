// Each plant's first module in the new stream: the write offset of its first module in the old one. Counts only
// the device knows (kCountOnDevice) are the old table's last entry and the scan's total.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer OldStarts { uint oldStarts[]; };
layout(set = 0, binding = 1, std430) readonly buffer Offsets { uint offsets[]; };
layout(set = 0, binding = 2, std430) writeonly buffer NewStarts { uint newStarts[]; };
layout(set = 0, binding = 3, std430) readonly buffer ScanTotal { uint scanTotal; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint p = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (p > pc.plants) return;
    uint count = pc.count != kCountOnDevice ? pc.count : oldStarts[pc.plants];
    uint start = oldStarts[p];
    // An empty scan writes no total.
    uint total = pc.total != kCountOnDevice ? pc.total : count == 0u ? 0u : scanTotal;
    newStarts[p] = start < count ? offsets[start] : total;
}
