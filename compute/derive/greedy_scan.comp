// Greedy walk, pass 2: each chunk's entry state, by composing the chunk functions in order. No invocation walks
// all chunks (drivers may end an invocation's loops after 65535 iterations): in phase 0 each invocation composes
// a block of kGreedyBlock chunks, in phase 1 one invocation walks the blocks, in phase 2 each invocation walks
// its block's chunks from the block's entry state. pc.level is the phase, pc.count the number of chunks, or
// kCountOnDevice: the chunks of the modules the plant table counts.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Functions { uint functions[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Entries { uint entries[]; };
layout(set = 0, binding = 2, std430) buffer BlockFunctions { uint blockFunctions[]; };
layout(set = 0, binding = 3, std430) buffer BlockEntries { uint blockEntries[]; };
layout(set = 0, binding = 4, std430) readonly buffer PlantStart { uint plantStart[]; };
layout(push_constant) uniform Push { DeriveHelperPush pc; };

const uint kStates = 8u;        // 4 bits per entry state in a uint

uint apply(uint function, uint state) { return (function >> (4u * state)) & 15u; }

// `first`, then `second`.
uint compose(uint first, uint second) {
    uint packed = 0u;
    for (uint state = 0u; state < kStates; ++state) packed |= apply(second, apply(first, state)) << (4u * state);
    return packed;
}

void main() {
    uint index = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    uint chunks = pc.count != kCountOnDevice ? pc.count : (plantStart[pc.plants] + kGreedyChunk - 1u) / kGreedyChunk;
    uint blocks = (chunks + kGreedyBlock - 1u) / kGreedyBlock;
    if (pc.level == 1u) {
        if (index != 0u) return;
        uint state = 0u;
        for (uint block = 0u; block < blocks; ++block) {
            blockEntries[block] = state;
            state = apply(blockFunctions[block], state);
        }
        return;
    }
    if (index >= blocks) return;
    uint first = index * kGreedyBlock, last = min(first + kGreedyBlock, chunks);
    if (pc.level == 0u) {
        uint function = 0x76543210u; // the identity
        for (uint chunk = first; chunk < last; ++chunk) function = compose(function, functions[chunk]);
        blockFunctions[index] = function;
    } else {
        uint state = blockEntries[index];
        for (uint chunk = first; chunk < last; ++chunk) {
            entries[chunk] = state;
            state = apply(functions[chunk], state);
        }
    }
}
