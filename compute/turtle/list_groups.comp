// Before a round of pointer jumping: the workgroups that walk the round's list (jump_list.glsl), from the count
// the pass before it left, and the next round's list emptied for the items this round hands on. One invocation.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) buffer ListIn { uint inHeader[kJumpListHeader]; };
layout(set = 0, binding = 1, std430) buffer ListOut { uint outHeader[kJumpListHeader]; };
layout(push_constant) uniform Push { TurtlePush pc; };

void main() {
    // As vk::ComputePipeline::dispatch lays out its workgroups: over y when x cannot hold them.
    uint groups = (inHeader[kJumpListCount] + kTurtleWorkgroupSize - 1u) / kTurtleWorkgroupSize;
    uint y = max((groups + pc.maxGroupsX - 1u) / pc.maxGroupsX, 1u);
    inHeader[0] = (groups + y - 1u) / y;
    inHeader[1] = y;
    inHeader[2] = 1u;
    outHeader[kJumpListCount] = 0u;
}
