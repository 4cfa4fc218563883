// The workgroups of a recording's passes, which interpret() sizes from what it reads back: the passes over every
// module and chunk from the module count, and the searches and levels only where their marks occur (setup.comp
// gathered them). One invocation.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer Status { uint status[]; };
layout(set = 0, binding = 1, std430) readonly buffer Present { uint presentMarks; };
// Gate g's passes over chunks at g * kGateWords, over modules 3 words on.
layout(set = 0, binding = 2, std430) writeonly buffer Arguments { uint arguments[]; };
layout(push_constant) uniform Push { TurtlePush pc; };

// As vk::ComputePipeline::dispatch lays out its workgroups: over y when x cannot hold them.
void setGroups(uint at, uint items) {
    uint groups = (items + kTurtleWorkgroupSize - 1u) / kTurtleWorkgroupSize;
    uint y = max((groups + pc.maxGroupsX - 1u) / pc.maxGroupsX, 1u);
    arguments[at] = (groups + y - 1u) / y;
    arguments[at + 1u] = y;
    arguments[at + 2u] = 1u;
}

void main() {
    const uint gateMarks[kGates] = uint[](0xFFFFFFFFu, kMarkStem, kMarkCylinderStart | kMarkCylinderPoint,
                                          kMarkCylinderStart, kMarkNonlinear);
    uint modules = min(status[kTurtleStatusModules], pc.count);
    uint chunks = (modules + kTurtleChunk - 1u) / kTurtleChunk;
    for (uint gate = 0u; gate < kGates; ++gate) {
        bool open = gate == kGateModules || (presentMarks & gateMarks[gate]) != 0u;
        setGroups(gate * kGateWords, open ? chunks : 0u);
        setGroups(gate * kGateWords + 3u, open ? modules : 0u);
    }
}
