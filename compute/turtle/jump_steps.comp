// Turtle, pass 4 (rounds of pointer jumping over the targets of chunk_steps.comp, from the list it appended):
// each target's step becomes the composition of the steps from its anchor (the nearest non-linear ancestor, or
// the plant's root) down to it. A round composes with what the pointed-at target has composed so far and takes
// over its pointer, doubling the path each round covers; a target already at its anchor is copied and dropped
// from the list (jump_list.glsl).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer StepsIn { TurtleStep stepsIn[]; };
layout(set = 0, binding = 2, std430) readonly buffer PointersIn { uint pointersIn[]; };
layout(set = 0, binding = 3, std430) writeonly buffer StepsOut { TurtleStep stepsOut[]; };
layout(set = 0, binding = 4, std430) writeonly buffer PointersOut { uint pointersOut[]; };
#define JUMP_LIST_IN_BINDING 5
#define JUMP_LIST_OUT_BINDING 6
#include "compute/turtle/jump_list.glsl"
#include "compute/turtle/turtle_math.glsl"

void main() {
    uint i = listItem((gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x +
                      gl_LocalInvocationID.x);
    if (i == kNoModule) return;
    uint p = pointersIn[i];
    if (p == kNoModule || (marks[p] & kMarkNonlinear) != 0u) {
        stepsOut[i] = stepsIn[i];
        pointersOut[i] = p;
        return;
    }
    stepsOut[i] = composeSteps(stepsIn[p], stepsIn[i]);
    pointersOut[i] = pointersIn[p];
    passOn(i);
}
