// Copy bandwidth probe for `simeco bench`: destination[i] = source[i] over a large buffer, so the derivation's
// bytes per second can be quoted against what this device moves when it does nothing but move bytes (bytes
// moved = bytes read + bytes written). Each invocation copies pc.perInvocation uvec4s, one workgroup size
// apart, so a workgroup streams one contiguous block and neighbouring invocations touch neighbouring words.
#version 450

layout(local_size_x = 256) in;

layout(set = 0, binding = 0, std430) readonly buffer Source { uvec4 source[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Destination { uvec4 destination[]; };
layout(push_constant) uniform Push {
    uint count;          // uvec4 elements to copy
    uint perInvocation;  // uvec4 elements each invocation copies
} pc;

void main() {
    // More workgroups than the device allows along x come as a 2D grid (see vk/pipeline.h).
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint base = group * gl_WorkGroupSize.x * pc.perInvocation + gl_LocalInvocationIndex;
    for (uint k = 0u; k < pc.perInvocation; ++k) {
        uint i = base + k * gl_WorkGroupSize.x;
        if (i < pc.count) {
            destination[i] = source[i];
        }
    }
}
