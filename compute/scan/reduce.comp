// Reduce-then-scan, pass 1: the sum of each tile. See scan/downsweep.comp for the algorithm.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "compute/shared/config.h"

layout(local_size_x = kScanWorkgroupSize) in;

layout(set = 0, binding = 0, std430) readonly buffer Input { uint values[]; };
layout(set = 0, binding = 1, std430) writeonly buffer TileSums { uint tileSums[]; };
layout(push_constant) uniform Push { ScanReducePush pc; };

#include "compute/scan/workgroup_scan.glsl"
#include "compute/scan/workgroup_index.glsl"

void main() {
    uint tile = linearWorkgroupIndex();
    if (tile >= pc.tileCount) {
        return;  // padding of a 2D dispatch; uniform over the workgroup
    }
    uint sum = 0u;
    for (uint round = 0u; round < kScanRounds; ++round) {
        uint base = tileElementBase(tile, round);
        for (uint k = 0u; k < kScanValuesPerInvocation; ++k) {
            if (base + k < pc.count) {
                sum += values[base + k];
            }
        }
    }
    uint tileSum;
    workgroupExclusiveAdd(sum, 0u, tileSum);
    if (gl_LocalInvocationIndex == 0u) {
        tileSums[tile] = tileSum;
    }
}
