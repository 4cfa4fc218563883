// Levels of the non-linear modules (rounds of pointer jumping over their own tree): how many non-linear
// modules lie on the path from the plant's root to each, itself included. Entry i holds (levels counted so
// far, the next non-linear ancestor not yet counted); the first round starts from (1, the anchor of the
// module's parent).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/derive_layout.h"
#include "shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer LevelsIn { uvec2 levelsIn[]; };
layout(set = 0, binding = 2, std430) writeonly buffer LevelsOut { uvec2 levelsOut[]; };
layout(set = 0, binding = 3, std430) readonly buffer Parents { uint parents[]; };
layout(set = 0, binding = 4, std430) readonly buffer Anchors { uint anchors[]; };
layout(push_constant) uniform Push { TurtlePush pc; };

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= pc.count || (marks[i] & kMarkNonlinear) == 0u) return;
    if (pc.first == 0u) { // round 0: the anchors of the modules' parents
        uint parent = parents[i];
        levelsOut[i] = uvec2(1u, parent == kNoModule ? kNoModule : anchors[parent]);
        return;
    }
    uvec2 own = levelsIn[i];
    if (own.y == kNoModule) {
        levelsOut[i] = own;
        return;
    }
    uvec2 up = levelsIn[own.y];
    levelsOut[i] = uvec2(own.x + up.x, up.y);
}
