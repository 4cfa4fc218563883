// Searches up the module tree (rounds of pointer jumping over the targets of chunk_search.comp): each target's
// nearest strict ancestor carrying one of the marks hitMask | stopMask, or kNoModule.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer Targets { uint targets[]; };
layout(set = 0, binding = 2, std430) readonly buffer PointersIn { uint pointersIn[]; };
layout(set = 0, binding = 3, std430) writeonly buffer PointersOut { uint pointersOut[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 4
#include "compute/turtle/module_count.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount() || targets[i] == 0u) return;
    uint p = pointersIn[i];
    bool done = p == kNoModule || (marks[p] & (pc.hitMask | pc.stopMask)) != 0u;
    pointersOut[i] = done ? p : pointersIn[p];
}
