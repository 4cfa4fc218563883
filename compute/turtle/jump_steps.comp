// Turtle, pass 4 (rounds of pointer jumping over the targets of chunk_steps.comp): each target's step becomes
// the composition of the steps from its anchor (the nearest non-linear ancestor, or the plant's root) down to
// it. A round composes with what the pointed-at target has composed so far and takes over its pointer,
// doubling the path each round covers. Other modules are left alone.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer Targets { uint targets[]; };
layout(set = 0, binding = 2, std430) readonly buffer StepsIn { TurtleStep stepsIn[]; };
layout(set = 0, binding = 3, std430) readonly buffer PointersIn { uint pointersIn[]; };
layout(set = 0, binding = 4, std430) writeonly buffer StepsOut { TurtleStep stepsOut[]; };
layout(set = 0, binding = 5, std430) writeonly buffer PointersOut { uint pointersOut[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 6
#include "compute/turtle/module_count.glsl"
#include "compute/turtle/turtle_math.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount() || targets[i] == 0u) return;
    uint p = pointersIn[i];
    if (p == kNoModule || (marks[p] & kMarkNonlinear) != 0u) {
        stepsOut[i] = stepsIn[i];
        pointersOut[i] = p;
        return;
    }
    stepsOut[i] = composeSteps(stepsIn[p], stepsIn[i]);
    pointersOut[i] = pointersIn[p];
}
