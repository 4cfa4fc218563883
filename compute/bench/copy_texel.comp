// The copy bandwidth probe of bench/copy.comp reading its source through a uniform texel buffer: CPU
// implementations (lavapipe) gather texels several times faster than they load from storage buffers, so the
// faster of the two kernels is the device's copy bandwidth. Four 32-bit texels make each uvec4 written.
#version 450

layout(local_size_x = 256) in;

layout(set = 0, binding = 0) uniform usamplerBuffer source;
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
            int t = int(4u * i);
            destination[i] = uvec4(texelFetch(source, t).x, texelFetch(source, t + 1).x, texelFetch(source, t + 2).x,
                                   texelFetch(source, t + 3).x);
        }
    }
}
