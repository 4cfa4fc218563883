// Each plant's first module in the new stream: the write offset of its first module in the old one.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer OldStarts { uint oldStarts[]; };
layout(set = 0, binding = 1, std430) readonly buffer Offsets { uint offsets[]; };
layout(set = 0, binding = 2, std430) writeonly buffer NewStarts { uint newStarts[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint p = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (p > pc.plants) return;
    uint start = oldStarts[p];
    newStarts[p] = start < pc.count ? offsets[start] : pc.total;
}
