// Exclusive prefix sum over uint32, reduce-then-scan (the portable variant).
//
// This work is based on:
//   G. E. Blelloch, "Prefix Sums and Their Applications", CMU-CS-90-190, 1990.
//   D. Merrill, A. Grimshaw, "Parallel Scan for Stream Architectures", UVA CS2009-14, 2009
//   (reduce-then-scan: reduce tiles, scan the tile sums, rescan tiles seeded with their offsets).
//
// Pass 1 (reduce.comp) writes each tile's sum; the host scans those sums with the same passes, recursively,
// until one tile holds them; this pass then scans every tile and adds the tile's offset. No workgroup ever
// waits for another, so it is correct under any scheduling, lavapipe's included. Input and output may be the
// same buffer: each invocation reads its elements before writing them and no two invocations share one.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "compute/shared/config.h"

layout(local_size_x = kScanWorkgroupSize) in;

layout(set = 0, binding = 0, std430) buffer Input { uint values[]; };
layout(set = 0, binding = 1, std430) buffer Output { uint prefix[]; };
layout(set = 0, binding = 2, std430) readonly buffer TileOffsets { uint tileOffsets[]; };
layout(set = 0, binding = 3, std430) writeonly buffer Total { uint total; };
layout(push_constant) uniform Push { ScanDownsweepPush pc; };

#include "compute/scan/workgroup_scan.glsl"
#include "compute/scan/workgroup_index.glsl"

void main() {
    uint tile = linearWorkgroupIndex();
    if (tile >= pc.tileCount) {
        return;  // padding of a 2D dispatch; uniform over the workgroup
    }
    uint carry = pc.hasTileOffsets != 0u ? tileOffsets[tile] : 0u;
    for (uint round = 0u; round < kScanRounds; ++round) {
        uint base = tileElementBase(tile, round);
        uint v[kScanValuesPerInvocation];
        uint sum = 0u;
        for (uint k = 0u; k < kScanValuesPerInvocation; ++k) {
            v[k] = base + k < pc.count ? values[base + k] : 0u;
            sum += v[k];
        }
        uint roundTotal;
        uint running = carry + workgroupExclusiveAdd(sum, round & 1u, roundTotal);
        for (uint k = 0u; k < kScanValuesPerInvocation; ++k) {
            if (base + k < pc.count) {
                prefix[base + k] = running;
            }
            running += v[k];
        }
        carry += roundTotal;
    }
    if (pc.writeTotal != 0u && gl_LocalInvocationIndex == 0u) {
        total = carry;  // the host only asks this of a single-tile dispatch, where carry covers everything
    }
}
