// Searches up the module tree (rounds of pointer jumping over the targets of chunk_search.comp, from the list it
// appended): each target's nearest strict ancestor carrying one of the marks hitMask | stopMask, or kNoModule.
// A target whose answer is final is copied and dropped from the list (jump_list.glsl), but for the first round:
// its input is the chunk pass's buffer, not one of the pair the later rounds read.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer PointersIn { uint pointersIn[]; };
layout(set = 0, binding = 2, std430) writeonly buffer PointersOut { uint pointersOut[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define JUMP_LIST_IN_BINDING 3
#define JUMP_LIST_OUT_BINDING 4
#include "compute/turtle/jump_list.glsl"

void main() {
    uint i = listItem((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x +
                      gl_LocalInvocationID.x);
    if (i == kNoModule) return;
    uint p = pointersIn[i];
    bool done = p == kNoModule || (marks[p] & (pc.hitMask | pc.stopMask)) != 0u;
    pointersOut[i] = done ? p : pointersIn[p];
    if (!done || pc.first == 0u) passOn(i);
}
