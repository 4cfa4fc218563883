// After a step with decomposition, the homomorphism or a sequential step: each module of the new stream takes the
// particle state of the module of the rewritten string it descends from (its origin, which those passes write).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/particle_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Origin { uint origin[]; };
layout(set = 0, binding = 1, std430) readonly buffer ParticlesIn { vec4 particlesIn[]; };
layout(set = 0, binding = 2, std430) writeonly buffer ParticlesOut { vec4 particlesOut[]; };
// The new stream's plant table, whose last entry counts its modules when pc.count is kCountOnDevice.
layout(set = 0, binding = 3, std430) readonly buffer Starts { uint plantStart[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint j = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (j >= (pc.count != kCountOnDevice ? pc.count : plantStart[pc.plants])) return;
    uint from = origin[j];
    for (uint v = 0u; v < kParticleStateVec4s; ++v)
        particlesOut[kParticleStateVec4s * j + v] = particlesIn[kParticleStateVec4s * from + v];
}
