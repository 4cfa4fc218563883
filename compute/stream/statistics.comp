// Statistics of a module stream (compute/shared/statistics_layout.h): symbol counts and each chunk's bracket
// walk, summarised as four numbers that the host composes in order.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/statistics_layout.h"

layout(local_size_x = kStatisticsWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Symbols { uint symbols[]; };
layout(set = 0, binding = 1, std430) buffer SymbolCounts { uint symbolCounts[]; };
layout(set = 0, binding = 2, std430) writeonly buffer Summaries { ivec4 summaries[]; };
layout(push_constant) uniform Push { StatisticsPush pc; };

shared uint localCounts[kStatisticsSharedSymbols];

void main() {
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint chunk = group * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    bool local = pc.symbols <= kStatisticsSharedSymbols;
    if (local) {
        for (uint s = gl_LocalInvocationID.x; s < pc.symbols; s += gl_WorkGroupSize.x) localCounts[s] = 0u;
        barrier();
    }
    if (chunk < pc.chunks) {
        const int none = int(kStatisticsNoDepth);
        // The identity walk: v -> max(v + 0, none), nothing reached yet.
        int a = 0, b = none, c = none, e = none;
        uint end = min((chunk + 1u) * kStatisticsChunk, pc.count);
        for (uint i = chunk * kStatisticsChunk; i < end; ++i) {
            uint sym = symbols[i] & kSymbolMask;
            if (sym < pc.symbols) {
                if (local) atomicAdd(localCounts[sym], 1u);
                else atomicAdd(symbolCounts[sym], 1u);
            }
            int d = sym == 0u ? 1 : sym == 1u ? -1 : 0; // `[` and `]` (ir::kBranchOpen, kBranchClose)
            if (d == 0) continue;
            a += d;
            b = max(b == none ? none : b + d, 0);
            c = max(c, a);
            e = max(e, b);
        }
        summaries[chunk] = ivec4(a, b, c, e);
    }
    if (local) {
        barrier();
        for (uint s = gl_LocalInvocationID.x; s < pc.symbols; s += gl_WorkGroupSize.x)
            if (localCounts[s] != 0u) atomicAdd(symbolCounts[s], localCounts[s]);
    }
}
