// The module stream on the device and the derivation kernels' push constants, shared by C++ and GLSL.
//
// A module is one uint (symbol in the low 24 bits, parameter count in the high 8) and `stride` floats of
// parameters; plants are contiguous segments described by a table of first modules. Symbols 0, 1 and 2 are
// `[`, `]` and `%` in every grammar (ir::kBranchOpen, ir::kBranchClose, ir::kCut).
#ifndef SIMECO_SHARED_DERIVE_LAYOUT_H
#define SIMECO_SHARED_DERIVE_LAYOUT_H

#include "compute/shared/config.h"
#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kDeriveWorkgroupSize = 64u;
SIMECO_CONST kSymbolBits = 24u;
SIMECO_CONST kSymbolMask = 0xFFFFFFu;
// Modules one invocation of a match pass by chunks rewrites (derive/context_chunks.glsl): its tile of the scan.
SIMECO_CONST kContextChunk = 64u;
SIMECO_CONST kMaxDepthLevels = 32u;  // levels of the bracket-depth min tree (enough for 2^32 modules)
SIMECO_CONST kNoModule = 0xFFFFFFFFu;
SIMECO_CONST kChoiceDropped = 0xFFFFFFFFu; // the module lies in a cut part of a branch
SIMECO_CONST kChoiceCopy = 0u;             // no production: the module is copied
// A random-stream pass per rewriting pass: step * kPassesPerStep, decomposition depth d at + 1 + d.
SIMECO_CONST kPassesPerStep = 1024u;

// Iterations of the loop that tells whether the driver cut an invocation's loops; a push constant, so that the
// compiler cannot count them. The loop reads its next count from DerivePush::loopProbeCounts.
SIMECO_CONST kLoopProbeTrips = 2u;
SIMECO_CONST kLoopProbeCounts = 4u; // entries of DerivePush::loopProbeCounts, more than kLoopProbeTrips

// Push constants of the generated derivation kernels (all modes).
struct DerivePush {
    uint count;        // modules of the stream the kernel walks
    uint plants;       // plants in the stream
    uint step;         // derivation step (1-based)
    uint seed;         // random stream seed
    uint pass;         // random stream pass
    uint stride;       // parameter slots per module
    uint globalCount;  // globals per plant
    uint arrayStride;  // array elements per plant
    uint oldCount;     // modules of the string being rewritten (contexts are read there)
    uint depth;        // decomposition depth of this pass
    uint mode;         // sequential kernel: 0 counts each plant's modules, 1 writes them
    uint stackLevels;  // sequential kernel: decomposition stack levels per plant
    uint moduleLimit;  // sequential kernel: a plant counting past this stops and reports it
    uint chunk;        // sequential kernel: input modules a plant rewrites per dispatch
    uint dispatch;     // sequential kernel: the dispatch's index in its pass (0 starts the plants)
    uint loopProbeTrips; // kLoopProbeTrips (derive_lib.glsl's reportLoopsCut())
    uint loopProbeCounts[kLoopProbeCounts]; // {1, 2, 3, 4}: the probe loop's count after each trip
    // A step's match pass: some plant is frozen, so the modules of frozen plants are copied. A flag rather than a
    // specialisation: a second variant of a large match kernel cost the driver a second compilation as long as
    // the first, in every field whose species derive different lengths.
    uint frozenPlants;
    uint zero; // always 0: the kernels' opaqueZero() (derive_lib.glsl)
};

// plantFrozen values: the host freezes a plant that stopped or finished its derivation length; a production
// calling stop() asks for it to stop after the step.
SIMECO_CONST kPlantGrowing = 0u;
SIMECO_CONST kPlantFrozen = 1u;
SIMECO_CONST kPlantStopRequested = 2u;

// Flags the kernels raise in errors[1].
SIMECO_CONST kFlagStackFull = 1u;    // a plant's decomposition went deeper than its stack: retry with more levels
SIMECO_CONST kFlagOverLimit = 2u;    // a plant counted more than moduleLimit modules
// A loop ended before its condition let it: drivers may cap the iterations of one invocation (lavapipe stops
// all loops of an invocation after 65535 iterations in total). Every generated kernel raises it; the sequential
// kernel is retried with smaller chunks, the parallel passes cannot be split and report it.
SIMECO_CONST kFlagLoopCut = 4u;

// Modules per entry of the plant hints (derive/plant_hints.comp); a stream of n modules has
// plantHintBlocks(n) + 1 hints.
SIMECO_CONST kPlantHintBlock = 64u;
#ifdef __cplusplus
inline constexpr uint plantHintBlocks(uint count) { return (count + kPlantHintBlock - 1u) / kPlantHintBlock; }
#else
uint plantHintBlocks(uint count) { return (count + kPlantHintBlock - 1u) / kPlantHintBlock; }
#endif

// Push constants of the fixed helper kernels.
struct DeriveHelperPush {
    uint count;   // elements; plant hints and tiled plant starts: kCountOnDevice, the old plant table's last entry
    uint level;   // depth tree: the level being built; tiled plant starts: the tile size
    uint total;   // plant starts: modules of the new stream; tiled plant starts: kCountOnDevice, the scan's total
    uint plants;  // plant starts and hints: plants
};

// Steps recorded one after the other in one submission (GpuDeriver's recorded steps), with the stream sizes on the
// device: derive/step_sizes.comp turns each step's counts into the workgroup counts of its dispatches and stops
// the batch at a step whose string outgrows its stream or the module budget. Its words:
SIMECO_CONST kStepStopped = 0u;   // 0, or (batch step + 1) << 2 | kStopCapacity or kStopBudget
SIMECO_CONST kStopCapacity = 1u;  // the step's string outgrew the stream it is written to (more room, then again)
SIMECO_CONST kStopBudget = 2u;    // ... or the module budget
SIMECO_CONST kStepTotals = 4u;    // + batch step: the modules it derived
SIMECO_CONST kMostRecordedSteps = 64u;
SIMECO_CONST kStepBlocks = kStepTotals + kMostRecordedSteps; // + batch step * kStepBlockWords
SIMECO_CONST kStepBlockWords = 128u;
// A step's block: the workgroup counts (x, y, z) of its dispatches, and the elements its scan adds up.
SIMECO_CONST kArgsHints = 0u;
SIMECO_CONST kArgsMatch = 3u;
SIMECO_CONST kArgsScan = 6u;
SIMECO_CONST kArgsWrite = 9u;
SIMECO_CONST kArgsPlantStarts = 12u;
SIMECO_CONST kScanCountWord = 15u;
// ... and of its bracket tree (gpu::BracketTree), when its productions read contexts: the kernels over every
// module, the scan of the depths, and level L's minima at kArgsTreeLevels + 3 (L - 1), L = 1 .. kMaxDepthLevels - 1.
SIMECO_CONST kArgsModules = 16u;
SIMECO_CONST kArgsTreeScan = 19u;
SIMECO_CONST kArgsTreeLevels = 22u;
SIMECO_CONST kStepWords = kStepBlocks + kMostRecordedSteps * kStepBlockWords;

struct StepSizesPush {
    uint mode;         // 0: before the step's match (its sizes), 1: after its scan (the total, the write's sizes)
    uint step;         // the step's place in the batch
    uint plants;
    uint tileSize;     // modules per element of the fused scan
    uint chunkedMatch; // 1: the match runs an invocation per tile, not per module
    uint capacity;     // modules the step's output stream, and the next step's scratch, hold
    uint budget;       // the module budget, at most 2^32 - 1
    uint maxGroupsX;   // the device's workgroups along x; more go over y
    uint brackets;     // 1: the step builds a bracket tree: also its levels and workgroups
    uint inputBound;   // modules the input holds at most: a count past it is not trusted
};

#ifdef __cplusplus
static_assert(sizeof(DerivePush) == 88);
static_assert(sizeof(StepSizesPush) == 40);
static_assert(kArgsTreeLevels + 3u * (kMaxDepthLevels - 1u) <= kStepBlockWords);
static_assert(kLoopProbeTrips < kLoopProbeCounts);
static_assert(sizeof(DeriveHelperPush) == 16);
#endif
SIMECO_SHARED_END

#endif
