// Each plant's first module in the new stream when the step's scan is fused into its passes (derive_codegen):
// the offset of the plant's first old module is its tile's offset plus the counts before it in the tile, which
// the match pass stored above the module's choice (kChoiceBits bits). pc.level is the tile size (the subgroup
// size).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"

layout(local_size_x = kDeriveWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer OldStarts { uint oldStarts[]; };
layout(set = 0, binding = 1, std430) readonly buffer MatchWords { uint matchWords[]; };
layout(set = 0, binding = 2, std430) readonly buffer TileOffsets { uint tileOffsets[]; };
layout(set = 0, binding = 3, std430) writeonly buffer NewStarts { uint newStarts[]; };
layout(set = 0, binding = 4, std430) readonly buffer ScanTotal { uint scanTotal; }; // the step's scan
layout(push_constant) uniform Push { DeriveHelperPush pc; };
layout(constant_id = 0) const uint kChoiceBits = 0u; // GeneratedKernels::choiceBits

void main() {
    uint p = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (p > pc.plants) return;
    uint count = pc.count != kCountOnDevice ? pc.count : oldStarts[pc.plants];
    uint start = oldStarts[p];
    if (start >= count) {
        newStarts[p] = pc.total != kCountOnDevice ? pc.total : count == 0u ? 0u : scanTotal;
        return;
    }
    newStarts[p] = tileOffsets[start / pc.level] + (matchWords[start] >> kChoiceBits);
}
