// Turtle, pass 3: each invocation composes the steps of kTurtleChunk consecutive modules in order. A module
// whose parent lies in the chunk (and is linear) takes over the parent's composition and pointer; one whose
// parent lies before the chunk points at it, and that parent becomes a target: only targets take part in the
// pointer jumping that follows (jump_steps.comp), which walks the list of them this pass appends. A target's own
// pointer again leaves its chunk or ends at an anchor, so the targets are closed under their pointers.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer Parents { uint parents[]; };
layout(set = 0, binding = 2, std430) buffer Steps { TurtleStep steps[]; };
layout(set = 0, binding = 3, std430) buffer Pointers { uint pointers[]; };
layout(set = 0, binding = 4, std430) buffer Targets { uint targets[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 5
#include "compute/turtle/module_count.glsl"
#define JUMP_LIST_OUT_BINDING 6
#include "compute/turtle/jump_list.glsl"
#include "compute/turtle/turtle_math.glsl"

void main() {
    uint c = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    uint begin = c * kTurtleChunk;
    if (begin >= moduleCount()) return;
    uint end = min(begin + kTurtleChunk, moduleCount());
    for (uint i = begin; i < end; ++i) {
        if ((marks[i] & kMarkNonlinear) != 0u) continue; // identity step, pointing at itself (setup.comp)
        uint p = parents[i];
        if (p == kNoModule || (marks[p] & kMarkNonlinear) != 0u) continue; // at its anchor already
        if (p >= begin) {
            steps[i] = composeSteps(steps[p], steps[i]);
            pointers[i] = pointers[p];
        }
        uint q = pointers[i];
        if (q != kNoModule && q < begin && (marks[q] & kMarkNonlinear) == 0u) markTarget(q);
    }
}
