// Levels of the non-linear modules (rounds of pointer jumping over their own tree): how many non-linear
// modules lie on the path from the plant's root to each, itself included. Entry i holds (levels counted so
// far, the next non-linear ancestor not yet counted); the first round starts from (1, the anchor of the
// module's parent). The first round walks every module and lists the non-linear ones; the later rounds walk the
// list and drop the items whose count is final (jump_list.glsl).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "compute/turtle/turtle_buffers.glsl"
layout(set = 0, binding = 5, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 6, std430) readonly buffer Parents { uint parents[]; };
layout(set = 0, binding = 7, std430) readonly buffer Targets { uint targets[]; };
layout(set = 0, binding = 8, std430) readonly buffer ChunkSteps { TurtleStep chunkSteps[]; };
layout(set = 0, binding = 9, std430) readonly buffer ChunkPointers { uint chunkPointers[]; };
layout(set = 0, binding = 10, std430) readonly buffer JumpedSteps { TurtleStep jumpedSteps[]; };
layout(set = 0, binding = 11, std430) readonly buffer JumpedPointers { uint jumpedPointers[]; };
layout(set = 0, binding = 12, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 13, std430) readonly buffer States { TurtleState states[]; };
layout(set = 0, binding = 14, std430) readonly buffer LevelsIn { uvec2 levelsIn[]; };
layout(set = 0, binding = 15, std430) writeonly buffer LevelsOut { uvec2 levelsOut[]; };
#define TURTLE_STATUS_BINDING 16
#include "compute/turtle/module_count.glsl"
#define JUMP_LIST_IN_BINDING 17
#define JUMP_LIST_OUT_BINDING 18
#include "compute/turtle/jump_list.glsl"

#include "compute/turtle/turtle_math.glsl"
#include "compute/turtle/turtle_modules.glsl"
#include "compute/turtle/turtle_anchors.glsl"

void main() {
    if (pc.first == 0u) { // round 0: the anchors of the modules' parents
        uint i = invocationIndex();
        if (i >= moduleCount() || (marks[i] & kMarkNonlinear) == 0u) return;
        uint parent = parents[i];
        levelsOut[i] = uvec2(1u, parent == kNoModule ? kNoModule : anchorOf(parent));
        passOn(i); // written to one buffer of the pair only: the next round copies it to the other
        return;
    }
    uint i = listItem(invocationIndex());
    if (i == kNoModule) return;
    uvec2 own = levelsIn[i];
    if (own.y == kNoModule) {
        levelsOut[i] = own;
        return;
    }
    uvec2 up = levelsIn[own.y];
    levelsOut[i] = uvec2(own.x + up.x, up.y);
    passOn(i);
}
