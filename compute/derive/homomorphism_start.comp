// Before the homomorphism: every module of the derived string is examined at depth 0, and its contexts are
// read around itself (origin = its own index in the derived string).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) writeonly buffer Live { uint live[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Origin { uint origin[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= pc.count) return;
    live[i] = 1u;
    origin[i] = i;
}
