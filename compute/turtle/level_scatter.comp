// Places each non-linear module in its level's slice of the resolution order (any order within a level),
// advancing its level's cursor from the slice's start to its end.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer Levels { uvec2 levels[]; };
layout(set = 0, binding = 2, std430) buffer Cursors { uint cursors[]; };
layout(set = 0, binding = 3, std430) writeonly buffer Order { uint order[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 4
#include "compute/turtle/module_count.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount() || (marks[i] & kMarkNonlinear) == 0u) return;
    uint level = levels[i].x;
    if (level > pc.items) return; // deeper than the levels laid out (level_layout.comp tells)
    order[atomicAdd(cursors[level], 1u)] = i;
}
