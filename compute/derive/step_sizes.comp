// The sizes of a recorded step's dispatches, from counts only the device knows (GpuDeriver's recorded steps):
// before the step's match (kSizeStep) the workgroups of its plant hints, match and scan (and of its cuts and
// greedy walk) from the modules of its input; after its scan (kSizeStepWrite) the step's total, and the
// workgroups of its write and plant starts. A step whose string outgrows the stream it is written to or the
// module budget stops the batch: its write and every later dispatch get no workgroups, so the string it reads
// stays as it was for the host to continue from. A step that rewrites by depths (decomposition, the
// homomorphism) sizes each depth the same way: its live modules (kSizeDepth), its match (kSizeDepthMatch; none
// once no module is live, and every later depth gets no workgroups), its write (kSizeDepthWrite); then the copy
// of the result into the step's output stream when the last depth wrote the other one (kSizeDepthsEnd). A step
// whose depths an earlier batch stopped for want of depths goes on from the last depth written (kSizeResume).
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
// the level of one. Once the batch has stopped, the levels stay those of the tree built last: a step stopped for
// want of depths goes on reading it in the next batch.
void treeSizes(uint block, uint n, bool stopped) {
    uint offset = 0u, size = max(n, 1u);
    bool used = true;
    for (uint level = 0u; level < kMaxDepthLevels; ++level) {
        if (!stopped) {
            levelInfo[level] = used ? offset : 0u;
            levelInfo[kMaxDepthLevels + level] = used ? size : 0u;
        }
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

void stop(uint reason) { words[kStepStopped] = ((pc.step + 1u) << 2u) | reason; }

// A total past the budget or the room of the stream it is written to stops the batch.
void stopIfOutgrown(uint total) {
    if (total > pc.budget) stop(kStopBudget);
    else if (total > pc.capacity) stop(kStopCapacity);
}

void sizeStep(uint block, bool stopped) {
    uint modules = min(inputStarts[pc.plants], pc.inputBound);
    uint tiles = groupsOf(modules, pc.tileSize);
    if (pc.mode == kSizeStep) {
        uint scanned = stopped ? 0u : tiles;
        words[block + kScanCountWord] = scanned;
        setGroups(block + kArgsHints, stopped ? 0u : groupsOf(plantHintBlocks(modules) + 1u, kDeriveWorkgroupSize));
        setGroups(block + kArgsMatch, stopped ? 0u : groupsOf(pc.chunkedMatch != 0u ? tiles : modules,
                                                              kDeriveWorkgroupSize));
        setGroups(block + kArgsScan, groupsOf(scanned, kScanTileSize));
        if (pc.brackets != 0u) treeSizes(block, stopped ? 0u : modules, stopped);
        // Cuts and the greedy walk, where the match does not scan its counts itself.
        uint counted = stopped ? 0u : modules, chunks = groupsOf(counted, kGreedyChunk);
        setGroups(block + kArgsCut, groupsOf(counted, kDeriveWorkgroupSize));
        setGroups(block + kArgsChunks, groupsOf(chunks, kDeriveWorkgroupSize));
        setGroups(block + kArgsBlocks, groupsOf(groupsOf(chunks, kGreedyBlock), kDeriveWorkgroupSize));
        setGroups(block + kArgsOne, counted == 0u ? 0u : 1u);
        return;
    }
    bool writes = false;
    if (!stopped) {
        uint total = tiles == 0u ? 0u : scanTotal; // an empty scan writes no total
        words[kStepTotals + pc.step] = total;
        words[block + kResultModules] = total;
        words[block + kStepWritten] = total;
        stopIfOutgrown(total);
        writes = words[kStepStopped] == 0u;
    }
    setGroups(block + kArgsWrite, writes ? groupsOf(modules, kDeriveWorkgroupSize) : 0u);
    setGroups(block + kArgsPlantStarts, writes ? groupsOf(pc.plants + 1u, kDeriveWorkgroupSize) : 0u);
}

// One depth of a step's rewriting by depths: its input is the stream whose table inputStarts is.
void sizeDepth(uint block, bool stopped) {
    uint at = pc.depthBlock; // the depth's block
    bool idle = stopped || words[block + kDepthsEnded] != 0u;
    if (pc.mode == kSizeDepth) {
        uint modules = idle ? 0u : min(inputStarts[pc.plants], pc.inputBound);
        if (!idle && modules == 0u) words[block + kDepthsEnded] = 1u;
        words[at + kDepthModules] = modules;
        uint hints = modules == 0u ? 0u : plantHintBlocks(modules) + 1u;
        setGroups(at + kDepthArgsHints, groupsOf(hints, kDeriveWorkgroupSize));
        setGroups(at + kDepthArgsScan, groupsOf(modules, kScanTileSize));
        return;
    }
    uint modules = words[at + kDepthModules];
    if (pc.mode == kSizeDepthMatch) {
        bool live = !idle && modules > 0u && scanTotal > 0u;
        if (!idle && !live) words[block + kDepthsEnded] = 1u;
        if (live && pc.lastDepth != 0u) { // modules left to rewrite past the depths recorded
            stop(kStopDepths);
            live = false;
        }
        if (!live) { // the scan of the counts adds up nothing
            words[at + kDepthModules] = 0u;
            setGroups(at + kDepthArgsScan, 0u);
        }
        setGroups(at + kDepthArgsMatch, live ? groupsOf(modules, kDeriveWorkgroupSize) : 0u);
        return;
    }
    bool writes = false;
    if (!idle && modules > 0u) {
        uint total = scanTotal;
        words[kStepTotals + pc.step] = total;
        stopIfOutgrown(total);
        writes = words[kStepStopped] == 0u;
        if (writes) {
            words[block + kResultModules] = total;
            words[block + kResultDepth] = pc.depth + 1u;
            words[block + kDepthsRead] += modules;
            words[block + kDepthsWritten] += total;
        }
    }
    setGroups(at + kDepthArgsWrite, writes ? groupsOf(modules, kDeriveWorkgroupSize) : 0u);
    setGroups(at + kDepthArgsPlantStarts, writes ? groupsOf(pc.plants + 1u, kDeriveWorkgroupSize) : 0u);
}

void main() {
    uint block = kStepBlocks + pc.step * kStepBlockWords;
    bool stopped = words[kStepStopped] != 0u;
    if (pc.mode <= kSizeStepWrite) {
        sizeStep(block, stopped);
    } else if (pc.mode <= kSizeDepthWrite) {
        sizeDepth(block, stopped);
    } else if (pc.mode == kSizeDepthsEnd) {
        uint modules = stopped ? 0u : words[block + kResultModules];
        bool elsewhere = (words[block + kResultDepth] & 1u) != 0u;
        uint copied = stopped || !elsewhere ? 0u : max(modules, pc.plants + 1u);
        setGroups(block + kArgsSettle, groupsOf(copied, kDeriveWorkgroupSize));
        setGroups(block + kArgsGather, groupsOf(modules, kDeriveWorkgroupSize));
        if (!stopped) words[kStepTotals + pc.step] = modules;
    } else if (pc.mode == kSizeResume) { // the depths go on from the string depth pc.depth wrote
        if (!stopped) {
            uint modules = min(inputStarts[pc.plants], pc.inputBound);
            words[kStepTotals + pc.step] = modules;
            words[block + kResultModules] = modules;
            words[block + kResultDepth] = pc.depth;
        }
    } else { // kSizeCopy
        uint modules = stopped ? 0u : min(inputStarts[pc.plants], pc.inputBound);
        if (!stopped) {
            words[kStepTotals + pc.step] = modules;
            words[block + kResultModules] = modules;
            stopIfOutgrown(modules);
        }
        bool copies = words[kStepStopped] == 0u;
        setGroups(block + kArgsCopy, copies ? groupsOf(max(modules, pc.plants + 1u), kDeriveWorkgroupSize) : 0u);
    }
}
