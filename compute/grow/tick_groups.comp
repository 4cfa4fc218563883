// The workgroups of a tick over a string a derivation recorded in the same submission: its modules are the plant
// table's last entry, known only on the device, and at most the bound the push gives (a step that outgrew its room
// leaves a table not to be trusted). Laid out as vk::ComputePipeline::dispatch lays them: over y when x cannot hold
// them. One invocation.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/growth_layout.h"
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer Starts { uint plantStart[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Arguments { uint arguments[]; };
layout(push_constant) uniform Push { GrowGroupsPush pc; };

void main() {
    uint modules = min(plantStart[pc.plants], pc.bound);
    uint groups = (modules + kGrowWorkgroupSize - 1u) / kGrowWorkgroupSize;
    uint y = max((groups + pc.maxGroupsX - 1u) / pc.maxGroupsX, 1u);
    arguments[0] = (groups + y - 1u) / y;
    arguments[1] = y;
    arguments[2] = 1u;
}
