// Searches up the module tree, first pass: each invocation walks kTurtleChunk consecutive modules in order and
// finds each one's nearest strict ancestor with a mark of hitMask | stopMask when it lies in the chunk. Where
// the search leaves the chunk at an unmarked module, that module becomes a target, appended to the list that
// jump_search.comp walks: it resolves the targets among themselves and search_finish.comp gives every module its answer.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer Parents { uint parents[]; };
layout(set = 0, binding = 2, std430) buffer Pointers { uint pointers[]; };
layout(set = 0, binding = 3, std430) buffer Targets { uint targets[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 4
#include "compute/turtle/module_count.glsl"
#define JUMP_LIST_OUT_BINDING 5
#include "compute/turtle/jump_list.glsl"

bool ends(uint j) { return j == kNoModule || (marks[j] & (pc.hitMask | pc.stopMask)) != 0u; }

void main() {
    uint c = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    uint begin = c * kTurtleChunk;
    if (begin >= moduleCount()) return;
    uint end = min(begin + kTurtleChunk, moduleCount());
    for (uint i = begin; i < end; ++i) {
        uint p = parents[i];
        uint q = (ends(p) || p < begin) ? p : pointers[p];
        pointers[i] = q;
        if (!ends(q)) markTarget(q);
    }
}
