// Places each non-linear module in its level's slice of the resolution order (any order within a level).
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

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= pc.count || (marks[i] & kMarkNonlinear) == 0u) return;
    order[atomicAdd(cursors[levels[i].x], 1u)] = i;
}
