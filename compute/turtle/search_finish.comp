// Searches up the module tree, last pass: a module whose chunk pass ended at a target takes the target's
// answer. Readers then check whether the found module carries a hit mark.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 1, std430) readonly buffer ChunkPointers { uint chunkPointers[]; };
layout(set = 0, binding = 2, std430) readonly buffer JumpedPointers { uint jumpedPointers[]; };
layout(set = 0, binding = 3, std430) writeonly buffer Found { uint found[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 4
#include "compute/turtle/module_count.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount()) return;
    uint q = chunkPointers[i];
    bool done = q == kNoModule || (marks[q] & (pc.hitMask | pc.stopMask)) != 0u;
    found[i] = done ? q : jumpedPointers[q];
}
