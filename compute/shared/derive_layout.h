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
    uint firstPlant;   // the random stream of plant 0 (stream::DeriveOptions::firstPlant)
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
    // Where a light grid runs, 1 / the light in the open (light() = the rewritten module's particle's light times
    // this); 0: none, light() is 1 (stream::DeriveOptions::lightScale).
    float lightScale;
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

// The greedy walk over predecessors of several modules (derive/greedy_*.comp): modules a chunk walks, and
// chunks per block of derive/greedy_scan.comp.
SIMECO_CONST kGreedyChunk = 256u;
SIMECO_CONST kGreedyBlock = 256u;

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
    uint count;   // elements; or kCountOnDevice: the last entry of the plant table the kernel reads from
    uint level;   // depth tree: the level being built; tiled plant starts: the tile size
    uint total;   // plant starts: modules of the new stream, or kCountOnDevice: the scan's total
    uint plants;  // plant starts and hints: plants
};

// Push constants of derive/stream_copy.comp.
SIMECO_CONST kCopySettle = 0u;
SIMECO_CONST kCopyHomomorphism = 1u;
struct StreamCopyPush {
    uint mode;   // kCopySettle or kCopyHomomorphism
    uint bound;  // modules both streams hold at most
    uint plants;
    uint stride; // parameter slots per module
};

// Steps recorded one after the other in one submission (GpuDeriver's recorded steps), with the stream sizes on the
// device: derive/step_sizes.comp turns each step's counts into the workgroup counts of its dispatches and stops
// the batch at a step whose string outgrows its stream or the module budget. Its words:
SIMECO_CONST kStepStopped = 0u;   // 0, or (batch step + 1) << 2 | kStopCapacity, kStopBudget or kStopDepths
SIMECO_CONST kStopCapacity = 1u;  // the step's string outgrew the stream it is written to (more room, then again)
SIMECO_CONST kStopBudget = 2u;    // ... or the module budget
SIMECO_CONST kStopDepths = 3u;    // its decomposition goes deeper than the depths recorded (more, then again)
SIMECO_CONST kStepTotals = 4u;    // + batch step: the modules it derived
SIMECO_CONST kMostRecordedSteps = 64u;
SIMECO_CONST kStepBlocks = kStepTotals + kMostRecordedSteps; // + batch step * kStepBlockWords
SIMECO_CONST kStepBlockWords = 144u;
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
// ... and where the step rewrites by depths (decomposition, or the homomorphism, which a batch records as a step
// of its own): the copy that starts the homomorphism, the result's copy into the step's output stream when the
// last depth wrote the other one, the particle states' gather, the result's modules and the depth that wrote it,
// whether the depths ended (no module left to rewrite), the modules the depths read and wrote in all, and the
// modules the step's own write wrote.
SIMECO_CONST kArgsCopy = 115u;
SIMECO_CONST kArgsSettle = 118u;
SIMECO_CONST kArgsGather = 121u;
SIMECO_CONST kResultModules = 124u;
SIMECO_CONST kResultDepth = 125u;
SIMECO_CONST kDepthsEnded = 126u;
SIMECO_CONST kDepthsRead = 127u;
SIMECO_CONST kDepthsWritten = 128u;
SIMECO_CONST kStepWritten = 129u;
// ... and where its match does not scan its counts itself (cuts, predecessors of several modules): the cut's
// application over every module, the greedy walk's dispatches over its chunks, over their blocks, and its one
// invocation that walks the blocks.
SIMECO_CONST kArgsCut = 130u;
SIMECO_CONST kArgsChunks = 133u;
SIMECO_CONST kArgsBlocks = 136u;
SIMECO_CONST kArgsOne = 139u;
SIMECO_CONST kStepWords = kStepBlocks + kMostRecordedSteps * kStepBlockWords;
// The blocks of a step's depths follow the steps' blocks: depth d of batch step s at kStepWords + (s * depths per
// step + d) * kDepthBlockWords. Each holds the workgroups of the depth's plant hints, of its two scans (the live
// modules, then the counts; both over its modules), match, write and plant starts, and its modules.
SIMECO_CONST kDepthArgsHints = 0u;
SIMECO_CONST kDepthArgsScan = 3u;
SIMECO_CONST kDepthArgsMatch = 6u;
SIMECO_CONST kDepthArgsWrite = 9u;
SIMECO_CONST kDepthArgsPlantStarts = 12u;
SIMECO_CONST kDepthModules = 15u;
SIMECO_CONST kDepthBlockWords = 16u;

// What a call of derive/step_sizes.comp sizes (StepSizesPush::mode).
SIMECO_CONST kSizeStep = 0u;          // a step, before its match
SIMECO_CONST kSizeStepWrite = 1u;     // ... after its scan: its total, its write
SIMECO_CONST kSizeDepth = 2u;         // a depth, before the scan of its live modules
SIMECO_CONST kSizeDepthMatch = 3u;    // ... after it: its match, or the end of the depths
SIMECO_CONST kSizeDepthWrite = 4u;    // ... after the scan of its counts: its total, its write
SIMECO_CONST kSizeDepthsEnd = 5u;     // after the depths: the result's copy and gather
SIMECO_CONST kSizeCopy = 6u;          // the copy that starts the homomorphism
SIMECO_CONST kSizeResume = 7u;        // a step's depths going on from pc.depth, where an earlier batch stopped

struct StepSizesPush {
    uint mode;         // kSizeStep ... kSizeResume
    uint step;         // the step's place in the batch
    uint plants;
    uint tileSize;     // modules per element of the fused scan
    uint chunkedMatch; // 1: the match runs an invocation per tile, not per module
    uint capacity;     // modules the step's output stream, and the next step's scratch, hold
    uint budget;       // the module budget, at most 2^32 - 1
    uint maxGroupsX;   // the device's workgroups along x; more go over y
    uint brackets;     // 1: the step builds a bracket tree: also its levels and workgroups
    uint inputBound;   // modules the input holds at most: a count past it is not trusted
    uint depthBlock;   // depths: the word where the depth's block starts
    uint depth;        // depths: the depth
    uint lastDepth;    // depths: 1 when the depths recorded end here short of the grammar's deepest (a probe)
};

#ifdef __cplusplus
static_assert(sizeof(DerivePush) == 96);
static_assert(sizeof(StepSizesPush) == 52);
static_assert(kArgsTreeLevels + 3u * (kMaxDepthLevels - 1u) <= kArgsCopy);
static_assert(kArgsOne + 3u <= kStepBlockWords);
static_assert(kLoopProbeTrips < kLoopProbeCounts);
static_assert(sizeof(DeriveHelperPush) == 16);
static_assert(sizeof(StreamCopyPush) == 16);
#endif
SIMECO_SHARED_END

#endif
