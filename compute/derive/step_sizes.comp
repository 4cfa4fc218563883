// The sizes of a recorded step's dispatches, from counts only the device knows (GpuDeriver's recorded steps):
// before the step's match (mode 0) the workgroups of its plant hints, match and scan from the modules of its
// input; after its scan (mode 1) the step's total, and the workgroups of its write and plant starts. A step whose
// string outgrows the stream it is written to or the module budget stops the batch: its write and every later
// dispatch get no workgroups, so the string it reads stays as it was for the host to continue from.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/config.h"
#include "compute/shared/derive_layout.h"

layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) readonly buffer InputStarts { uint inputStarts[]; };
layout(set = 0, binding = 1, std430) readonly buffer ScanTotal { uint scanTotal; };
layout(set = 0, binding = 2, std430) buffer Words { uint words[]; };
// The bracket tree's levels (gpu::BracketTree): offset of level k at k, its size at kMaxDepthLevels + k.
layout(set = 0, binding = 3, std430) writeonly buffer LevelInfo { uint levelInfo[]; };
layout(push_constant) uniform Push { StepSizesPush pc; };

uint groupsOf(uint items, uint perGroup) { return (items + perGroup - 1u) / perGroup; }

// As vk::ComputePipeline::dispatch lays out `groups` workgroups: over y when x cannot hold them.
void setGroups(uint at, uint groups) {
    uint y = max((groups + pc.maxGroupsX - 1u) / pc.maxGroupsX, 1u);
    words[at] = (groups + y - 1u) / y;
    words[at + 1u] = y;
    words[at + 2u] = 1u;
}

// As gpu::BracketTree::record lays out the levels of n modules' depth minima: level k holds ceil(n / 2^k), up to
// the level of one.
void treeSizes(uint block, uint n, bool stopped) {
    uint offset = 0u, size = max(n, 1u);
    bool used = true;
    for (uint level = 0u; level < kMaxDepthLevels; ++level) {
        levelInfo[level] = used ? offset : 0u;
        levelInfo[kMaxDepthLevels + level] = used ? size : 0u;
        if (level > 0u) {
            uint groups = used && !stopped ? groupsOf(size, kDeriveWorkgroupSize) : 0u;
            setGroups(block + kArgsTreeLevels + 3u * (level - 1u), groups);
        }
        if (used) offset += size;
        used = used && size > 1u;
        size = (size + 1u) / 2u;
    }
    setGroups(block + kArgsModules, stopped ? 0u : groupsOf(max(n, 1u), kDeriveWorkgroupSize));
    setGroups(block + kArgsTreeScan, stopped ? 0u : groupsOf(max(n, 1u), kScanTileSize));
}

void main() {
    uint block = kStepBlocks + pc.step * kStepBlockWords;
    bool stopped = words[kStepStopped] != 0u;
    uint modules = min(inputStarts[pc.plants], pc.inputBound);
    uint tiles = groupsOf(modules, pc.tileSize);
    if (pc.mode == 0u) {
        uint scanned = stopped ? 0u : tiles;
        words[block + kScanCountWord] = scanned;
        setGroups(block + kArgsHints, stopped ? 0u : groupsOf(plantHintBlocks(modules) + 1u, kDeriveWorkgroupSize));
        setGroups(block + kArgsMatch, stopped ? 0u : groupsOf(pc.chunkedMatch != 0u ? tiles : modules,
                                                              kDeriveWorkgroupSize));
        setGroups(block + kArgsScan, groupsOf(scanned, kScanTileSize));
        if (pc.brackets != 0u) treeSizes(block, stopped ? 0u : modules, stopped);
        return;
    }
    bool writes = false;
    if (!stopped) {
        uint total = tiles == 0u ? 0u : scanTotal; // an empty scan writes no total
        words[kStepTotals + pc.step] = total;
        uint stop = total > pc.budget ? kStopBudget : total > pc.capacity ? kStopCapacity : 0u;
        if (stop != 0u) words[kStepStopped] = ((pc.step + 1u) << 2u) | stop;
        writes = stop == 0u;
    }
    setGroups(block + kArgsWrite, writes ? groupsOf(modules, kDeriveWorkgroupSize) : 0u);
    setGroups(block + kArgsPlantStarts, writes ? groupsOf(pc.plants + 1u, kDeriveWorkgroupSize) : 0u);
}
