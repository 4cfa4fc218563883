// Greedy walk, pass 2: one invocation composes the chunk functions in order, giving each chunk's entry state.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/derive_layout.h"

layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer Functions { uint functions[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Entries { uint entries[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

void main() {
    uint state = 0u;
    for (uint chunk = 0u; chunk < pc.count; ++chunk) { // pc.count: chunks
        entries[chunk] = state;
        state = (functions[chunk] >> (4u * state)) & 15u;
    }
}
