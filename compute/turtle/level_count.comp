// Counts the non-linear modules of each level (level_layout.comp lays the levels out one after another) and
// the deepest level, in counts[0].
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer Levels { uvec2 levels[]; };
layout(set = 0, binding = 2, std430) buffer Counts { uint counts[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 3
#include "compute/turtle/module_count.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount() || (marks[i] & kMarkNonlinear) == 0u) return;
    uint level = levels[i].x;
    atomicAdd(counts[level], 1u);
    atomicMax(counts[0], level);
}
