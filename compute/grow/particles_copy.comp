// The tick's next states copied back into the string's particles, module by module, for a string whose modules
// only the device knows (compute/grow/tick_groups.comp sizes it): a buffer copy would need its size on the host.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/growth_layout.h"
#include "compute/shared/particle_layout.h"
layout(local_size_x = kGrowWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Starts { uint plantStart[]; };
layout(set = 0, binding = 1, std430) readonly buffer From { float from[]; };
layout(set = 0, binding = 2, std430) writeonly buffer To { float to[]; };
layout(push_constant) uniform Push { GrowGroupsPush pc; };

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= min(plantStart[pc.plants], pc.bound)) return;
    for (uint k = 0u; k < kParticleStateFloats; ++k)
        to[kParticleStateFloats * i + k] = from[kParticleStateFloats * i + k];
}
