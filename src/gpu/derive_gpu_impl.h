// The GPU deriver's state, shared by the files that implement it: its kernels and buffers
// (derive_gpu_resources.cpp), what the kernels share (derive_gpu_passes.cpp), steps recorded with their sizes on
// the device (derive_gpu_recorded.cpp) and those that rewrite by depths (derive_gpu_depths.cpp), the sequential
// strategy (derive_gpu_sequential.cpp) and the derivation itself (derive_gpu.cpp). Private to src/gpu/.
#pragma once

#include <algorithm>
#include <cstdint>
#include <deque>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <vulkan/vulkan.h>

#include "codegen/derive_codegen.h"
#include "compute/shared/derive_layout.h"
#include "compute/shared/particle_layout.h"
#include "gpu/bracket_tree.h"
#include "gpu/derive_gpu.h"
#include "gpu/scan.h"
#include "ir/grammar.h"
#include "ir/source_loc.h"
#include "stream/plant_control.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/timestamps.h"

namespace simeco::gpu {

// A module stream on the device: symbols, parameters, the plant table, and for decomposition the position
// each module came from in the string being rewritten and whether the next depth examines it.
struct Stream {
    vk::Buffer sym, par, plantStart, origin, live;
    vk::Buffer particles; // kParticleStateFloats per module, while the derivation carries particle state
    uint64_t capacity = 0;
    uint32_t count = 0;
};

inline VkDeviceSize bytes(uint64_t count, uint64_t size) { return std::max<VkDeviceSize>(count * size, 4); }

using shared::kGreedyBlock;
using shared::kGreedyChunk;

// The driver ended an invocation's loops early (kFlagLoopCut) where the work cannot be split any finer.
ir::LimitError loopsCutError(const std::string& what);

// Where batch slot `slot`'s word `which` of its block lies in the step words, in bytes.
inline VkDeviceSize blockOffset(uint32_t slot, uint32_t which) {
    return VkDeviceSize(shared::kStepBlocks + slot * shared::kStepBlockWords + which) * 4;
}

// Derivations recorded into callers' command buffers that may be in flight at once (GpuDeriver::record).
inline constexpr int kDerivationsInFlight = 2;

// Depths a recorded step rewrites by at first (GpuDeriver::Impl::decompositionDepths), and the most depth blocks
// of one batch, which limit its steps where the steps rewrite by many depths.
inline constexpr int kFirstRecordedDepths = 4;
inline constexpr uint32_t kMostDepthBlocks = 512;

// Bytes of one module's particle state.
inline constexpr uint64_t kParticleBytes = 4ull * shared::kParticleStateFloats;

struct GpuDeriver::Impl {
    const vk::Context& ctx;
    std::vector<ir::Grammar> species;
    GpuStrategy strategy;
    int stride;
    bool texelInputs; // the generated kernels read their inputs through uniform texel buffers (GpuLoads)
    bool contextChunks; // the step's match pass finds context modules by chunks (GpuContextMatch)
    int lastStream = -1; // the stream the last derive() ended in
    uint32_t globalStride = 0, arrayStride = 0; // globals and array elements per plant (the most of any species)
    codegen::GeneratedKernels kernels;
    std::optional<vk::ComputePipeline> decompositionMatch, decompositionWrite, sequential;
    // The step's match and write passes, specialised for a stream of one plant (kSinglePlant) or not (stepMatch(),
    // stepWrite()). Each variant is made the first time a step needs it: drivers compile a pipeline when it is
    // made or first run, and a derivation needs one of them.
    std::vector<uint32_t> matchSpirv, writeSpirv;
    std::map<bool, vk::ComputePipeline> matchVariants, writeVariants; // by single plant
    bool anyFrozen = false; // some plant is frozen in the step being derived
    // The homomorphism, generated as the decomposition of grammars whose decomposition is their homomorphism;
    // empty when no species has one, or when its productions need the host (homomorphismHostReason).
    codegen::GeneratedKernels homomorphismKernels;
    std::optional<vk::ComputePipeline> homomorphismMatch, homomorphismWrite;
    std::optional<std::string> homomorphismHostReason;
    // What the kernels read besides the stream and report by index: their species table (context filter and
    // classes of species), func() tables and error sites. The derivation's kernels and the homomorphism's lay
    // them out each for its own classes of species (codegen::classifySpecies). `active`: those of the kernels
    // being run (the homomorphism's while it runs).
    // Each reports its errors in a region of `errors` of its own (at errorOffset), so that a submission that runs
    // both tells whose sites they are.
    struct KernelTables {
        const std::vector<codegen::ErrorSite>* errors = nullptr;
        vk::Buffer speciesTable, funcTables;
        VkDeviceSize errorOffset = 0;
        bool readsLight = false; // the passes bind the rewritten string's particles last (light())
    };
    KernelTables derivationTables, homomorphismTables;
    const KernelTables* active = &derivationTables;
    KernelTables tablesOf(const codegen::GeneratedKernels& k) const;
    vk::ComputePipeline plantStarts, plantHintsKernel, cutApply;
    std::optional<vk::ComputePipeline> plantStartsTiled; // with a fused scan, specialised for its match words
    vk::ComputePipeline greedyReduce, greedyScan, greedyMark, streamCopy;
    // The particle state's moves, made the first time a derivation carries it: by the step's positions (with a
    // fused scan, specialised for its match words), or from each module's origin.
    std::optional<vk::ComputePipeline> particleScatter, particleGather;
    bool carriesParticles = false; // the derivation running carries particle state (DeriveOptions::particles)
    float lightScale = 0.0f;       // light()'s DeriveOptions::lightScale, where the derivation carries particles
    uint32_t firstPlant = 0;       // DeriveOptions::firstPlant
    vk::Buffer noParticles;        // bound for light() where the string carries none (lightScale is then 0)
    GpuScan scan;
    BracketTree brackets; // after scan, which it uses
    vk::Buffer errors, readback;
    vk::Buffer globals, arrays, plantFrozen;
    vk::Buffer counts, choices, drawStarts, offsets, cutDelta, cutBefore, examined;
    vk::Buffer chunkFunctions, chunkEntries; // the greedy walk over predecessors of several modules
    vk::Buffer blockFunctions, blockEntries; // ... and over blocks of chunks
    vk::Buffer plantHints; // of the stream the running kernels find plants in (recordPlantHints)
    vk::Buffer tileSums, tileOffsets; // a fused scan's sums of counts per tile, and their scan
    uint32_t tileSize = 1;            // a fused scan's tile: the device's subgroup size, or a match chunk
    // The sequential strategy: persistent locals, copies of the state for the counting pass, the decomposition
    // stack, and each plant's module count.
    vk::Buffer frames, framesCopy, globalsCopy, arraysCopy, stackSym, stackPar, stackState, plantCounts, countsReadback;
    vk::Buffer resume;
    uint32_t stackLevels = 0;
    // Work per plant and dispatch (input modules and decomposition steps): small enough that no invocation loops
    // long (kFlagLoopCut).
    uint32_t chunk = 256;
    std::vector<uint32_t> hostPlantTable; // the current stream's plant table, kept on the host
    uint32_t lastFlags = 0;      // errors[1] of the last submit
    // The stream whose bracket partners brackets.partners() holds, or -1; a step whose write pass carries them
    // (GeneratedKernels::carriesPartners) leaves them for the next, when every plant's string is balanced.
    int partnersStream = -1;
    bool axiomsBalanced = false;
    uint32_t bracketTrees = 0; // built since the derivation started
    bool lastUnfinished = false; // errors[2] of the last submit: the sequential kernel's plants need more dispatches
    uint64_t scratchCapacity = 0;
    Stream streams[3];
    uint32_t plants = 1;
    double compileSeconds = 0;
    // Steps recorded one after the other (derive_gpu_recorded.cpp): the sizes kernel and its words.
    std::optional<vk::ComputePipeline> stepSizes;
    vk::Buffer stepWords;
    // What the host writes for a batch and reads back from it: a set for each derivation in flight, so that a
    // second recording writes and reads its own while the first one's submission runs. The axioms' staging
    // buffer, each batch step's slice of the plant state, the step words and the last plant table read back, and
    // whether each batch step builds a bracket tree.
    struct HostSide {
        vk::Buffer axiomStaging;
        vk::Buffer batchGlobals, batchArrays, batchFrozen;
        vk::Buffer stepWordsReadback, tableReadback;
        bool treeBuilt[shared::kMostRecordedSteps] = {};
    };
    HostSide hostSides[kDerivationsInFlight];
    int hostSide = 0; // the set of the derivation being recorded or read
    HostSide& host() { return hostSides[hostSide]; }
    const HostSide& host() const { return hostSides[hostSide]; }
    VkDeviceSize globalsSlice = 0, arraysSlice = 0, frozenSlice = 0;
    std::optional<vk::Timestamps> batchTimer;
    // Copies the next submission records first (the axioms from their staging buffer, a grown stream's string from
    // its old buffers), and the buffers they read, kept until it ends.
    struct PendingCopy {
        VkBuffer from, to;
        VkBufferCopy region;
    };
    std::vector<PendingCopy> pendingCopies;
    std::vector<vk::Buffer> retiredBuffers;
    // host().tableReadback holds the plant table of streams[tableReadFrom], read back at the end of the last batch
    // (-1: none).
    int tableReadFrom = -1;
    // The plant state the derivation kernels bind: the host's buffers, or batch step `batchSlot`'s slices.
    int batchSlot = -1;
    // Recorded steps of grammars with contexts: brackets.partners() holds those of the next step's input, carried
    // by the steps' writes.
    bool partnersLive = false;
    uint32_t bracketRoom = 0; // modules the bracket tree was last reserved for by makeRoom

    // ---- kernels and buffers (derive_gpu_resources.cpp) ----

    Impl(const vk::Context& c, std::vector<ir::Grammar> grammars, GpuStrategy requested, GpuLoads loads,
         GpuContextMatch contexts);

    // The homomorphism's kernels: the decomposition passes of copies of the species whose decomposition is
    // their homomorphism (one pass per depth, contexts in the derived string, no cuts).
    template <typename Build> void buildHomomorphism(Build& build);

    // The most bytes a buffer of the derivation may hold: what a kernel can bind, as storage or, with texel
    // inputs, as a texel buffer of 4-byte texels.
    uint64_t bufferLimit() const;
    void checkRange(uint64_t count, uint64_t size, const char* what) const;
    void ensureStream(Stream& s, uint64_t count);
    void ensureScratch(uint64_t count);
    uint64_t tilesFor(uint64_t count) const { return (count + tileSize - 1) / tileSize; }

    // Room for the particle state of s's modules, while the derivation carries it.
    void ensureParticles(Stream& s);
    // Modules whose particle state a buffer for `s` holds: its capacity, as far as a binding reaches.
    uint64_t particleCapacity(const Stream& s) const {
        return std::min<uint64_t>(s.capacity, bufferLimit() / kParticleBytes);
    }

    // The module budget of a derivation that names none: what half the device's memory holds of the streams
    // and scratch (stream::deviceBytesPerModule, with the particle state where it is carried) and a quarter of
    // the host's of the string read back; from one memory where the device shares the host's (lavapipe,
    // integrated GPUs).
    uint64_t defaultModuleBudget(bool particles) const;

    // A stream of one plant is that plant: the variants specialised for it find no plants.
    bool singlePlant(bool findsPlants) const { return plants == 1 && findsPlants; }
    const vk::ComputePipeline& stepMatch();
    const vk::ComputePipeline& stepWrite();

    // ---- the host's side of a derivation (derive_gpu.cpp) ----

    // The axioms (and their particle state) into streams[0], and the per-plant buffers sized to `plants`. The
    // axioms are copied in by the first submission (pendingCopies), not by submissions of their own.
    void uploadAxioms(const stream::ModuleString& axioms, const stream::DeriveOptions& options);
    // `buffer` at least `size` bytes; a new one, of that size, when smaller.
    void reserve(vk::Buffer& buffer, VkDeviceSize size, vk::MemoryUsage usage);
    // The plants' globals and arrays, and which plants grow in the step (the others are copied).
    void uploadPlantState(const stream::PlantControl& control, const std::vector<uint8_t>& growing);
    // The same into the given memory; returns whether some plant is frozen.
    bool writePlantState(const stream::PlantControl& control, const std::vector<uint8_t>& growing, double* globalsOut,
                         double* arraysOut, uint32_t* frozenOut) const;
    // What the sequential kernel's productions wrote to the globals and arrays, and the stop() calls.
    void downloadPlantState(stream::PlantControl& control) const;
    // Stream `s` read back to the host, with its particle state when `particles`.
    stream::ModuleString readBack(const Stream& s, bool particles) const;

    // ---- what the kernels share (derive_gpu_passes.cpp) ----

    shared::DerivePush push(uint32_t count, uint32_t step, uint32_t seed, uint32_t pass, uint32_t oldCount,
                            uint32_t depth) const;

    // Submits `record` after the pending copies, waits, and returns the total the recording copied into the
    // readback buffer; throws
    // the located error a kernel reported, and kFlagLoopCut unless the caller retries (`retriesCutLoops`).
    uint32_t submit(const std::function<void(VkCommandBuffer)>& record, vk::Timestamps* timer, double& gpuMillis,
                    bool retriesCutLoops = false);
    // Throws the located error kernels with the error `sites` reported in their errors[0] (a site + 1) and
    // errors[1] (flags).
    static void checkKernelErrors(const std::vector<codegen::ErrorSite>& sites, uint32_t site, uint32_t flags,
                                  bool retriesCutLoops);
    static void checkBudget(uint64_t total, uint64_t budget, uint32_t stepIndex);

    // Dispatches a generated derivation kernel with the workgroup counts a recorded step's sizes kernel wrote at
    // `argumentsOffset` of stepWords. Its bindings start as every generated derivation kernel's do
    // (deriveBindings; see declarations() in derive_codegen.cpp): the string being rewritten, its brackets, the
    // plants' globals and arrays, function tables, the context filter and the error word; `rest` follows them.
    // `parameterVectors`: the kernel reads each module's parameters as one vector too, the last binding
    // (GeneratedKernels::matchReadsParameterVectors, writeReadsParameterVectors).
    void dispatchDeriveIndirect(VkCommandBuffer cmd, const vk::ComputePipeline& kernel, const Stream& strings,
                                std::initializer_list<vk::BufferRange> rest, const shared::DerivePush& p,
                                VkDeviceSize argumentsOffset, bool parameterVectors);
    std::vector<vk::BufferRange> deriveBindings(const Stream& strings, std::initializer_list<vk::BufferRange> rest,
                                                bool parameterVectors) const;

    // The bracket tree and partners of streams[index], unless its partners are already there.
    void recordBrackets(VkCommandBuffer cmd, int index);

    // Called before a pass writes streams[index]: partners describing it no longer do.
    void overwriting(int index);

    // After a step without decomposition, each module passes its particle state to its successor's modules, at
    // the positions the step's scan gave them.
    const vk::ComputePipeline& particleScatterKernel();

    // Each module of streams[to] takes the particle state of the module of streams[from] it descends from (its
    // origin): after decomposition, the homomorphism or a sequential step.
    void gatherParticles(int from, int to, vk::Timestamps* timer, double& millis);
    // The same recorded into `cmd`, streams[to] holding its particles already.
    void recordParticleGather(VkCommandBuffer cmd, int from, int to);

    vk::BufferRange plantTable(const Stream& s) const { return vk::BufferRange(s.plantStart, 0, bytes(plants + 1, 4)); }

    // What a step's match, scan and write read and write for `n` modules that derive `total` (a model, counted
    // by the host).
    uint64_t stepBytesMoved(uint64_t n, uint64_t total) const;
    // ... and decomposition depths that read `n` modules and wrote `total` in all.
    uint64_t depthBytesMoved(uint64_t n, uint64_t total) const {
        return n * (2 * (4 + 4ull * uint64_t(stride)) + 40) + total * (12 + 4ull * uint64_t(stride));
    }

    // Recursive rewriting by depth: the decomposition's kernels, or the homomorphism's.
    struct RecursivePasses {
        const vk::ComputePipeline* match;
        const vk::ComputePipeline* write;
        int maxDepth;
    };
    RecursivePasses decompositionPasses() const;

    // The derivation's start, for derive() and record() alike: the plants and their axioms (or the string
    // `from`, with its particles, where a saved derivation goes on), staged for the first submission to copy.
    void startDerivation(stream::PlantControl& control, const stream::DeriveOptions& options,
                         const stream::ModuleString* from = nullptr);

    // ---- steps recorded one after the other (derive_gpu_recorded.cpp) ----

    // Whether the derivation's steps run with their sizes on the device: the parallel strategy's.
    bool recordsSteps() const;

    // Every step from `step` on, a batch of up to kMostRecordedSteps steps per submission: the host's plant control
    // runs a batch ahead of the device (the parallel strategy's productions write no plant state), and the
    // device sizes each step's dispatches from the last. A step that outgrows its stream ends the submission
    // there; the streams grow and the rest of the batch runs again. Returns the stream of the last step.
    // Every plant finishes (its End block) once the last step is planned, and with `homomorphism` the
    // homomorphism follows the steps.
    int deriveRecorded(stream::PlantControl& control, int cur, uint32_t seed, uint64_t budget, bool timed,
                       bool homomorphism, GpuDeriveStats& stats);

    struct RecordedStep {
        uint32_t index;  // the derivation step (0: the homomorphism)
        bool anyFrozen;  // some plant is copied in it
        bool homomorphism = false; // the homomorphism of the derived string, after the steps
        // > 0: the step's depths go on from this one, which an earlier submission wrote before it stopped for
        // want of depths; its match and write, or the homomorphism's copy, are done.
        int resumeDepth = 0;
    };
    // After a batch recorded into a caller's command buffer: the copies are in it, and the buffers they read
    // (returned) must stay until its submission has ended; the kernels bind the host's plant state again.
    std::vector<vk::Buffer> endRecording();
    // Records pendingCopies, ordered before what follows in the submission.
    void recordPendingCopies(VkCommandBuffer cmd) const;
    // When a batch's submission ends, by its wait or a throw: the kernels bind the host's plant state again, and
    // the copies it recorded and the buffers they read are done with.
    struct SubmissionEnd {
        Impl& impl;
        ~SubmissionEnd() {
            impl.batchSlot = -1;
            impl.pendingCopies.clear();
            impl.retiredBuffers.clear();
        }
    };
    // The pipelines and buffers of recorded steps; no partners carried yet.
    void prepareRecorded(bool timed);
    // The next batch of up to batchSteps() steps from `step` on, planned by the host's plant control with
    // their plant state in the batch slots; `step` moves past them (past the last step when no plant grows).
    // Once every step is planned, the plants finish (`finished` is set), and `homomorphism` asks for it to
    // follow in the batch where there is a slot left (it is then cleared).
    void planBatch(stream::PlantControl& control, int& step, std::vector<RecordedStep>& batch,
                   std::vector<uint8_t>& growing, bool& finished, bool& homomorphism);
    // Runs batch steps `first` on from streams[cur] in one submission; returns the steps done, `cur` their stream.
    size_t runBatch(std::vector<RecordedStep>& batch, size_t first, int& cur, uint32_t seed, uint64_t budget,
                    bool timed, int stepsAfterBatch, GpuDeriveStats& stats);
    // After batch step `done` stopped the submission that ran it from streams[cur]: more depths for it, or room
    // for it and a few steps more, so that the next submission runs it again.
    void prepareToGoOn(std::vector<RecordedStep>& batch, size_t done, int cur, uint64_t budget, int stepsAfterBatch);
    // Records batch steps `first` on from streams[in] into `cmd`, then copies of their sizes and the last plant
    // table for the host; returns the stream the last step writes.
    int recordBatch(VkCommandBuffer cmd, const std::vector<RecordedStep>& batch, size_t first, int in, uint32_t seed,
                    uint64_t budget, vk::Timestamps* timer);
    // After the batch's submission: the steps it completed (all of them unless one stopped it), `cur` moved to
    // their last stream, with the streams' counts and the stats. Throws when the step that stopped it passed the
    // module `budget`.
    size_t completeBatch(const std::vector<RecordedStep>& batch, size_t first, int& cur, uint64_t budget,
                         vk::Timestamps* timer, GpuDeriveStats& stats);
    // A derivation record() wrote into a caller's command buffer, until recorded() reads what it left: its
    // host side, and the buffers its recording replaced, kept until its submission has ended.
    struct Recording {
        std::unique_ptr<stream::PlantControl> control;
        std::vector<RecordedStep> batch;
        uint64_t budget = 0;
        uint64_t submissionsBefore = 0;
        int hostSide = 0;
        std::vector<vk::Buffer> retired;
    };
    std::deque<Recording> recordings; // oldest first, at most kDerivationsInFlight
    // While a recording is in flight the buffers its submission uses stay as they are: a second recording that
    // would grow one is refused (throws std::logic_error naming `what`).
    void mayReplace(const char* what) const;
    void recordStep(VkCommandBuffer cmd, const RecordedStep& step, uint32_t slot, int in, uint32_t seed,
                    uint64_t budget);
    // A step's match and scan where the match does not scan its counts itself (GeneratedKernels::fusedScan): its
    // counts, which cuts and the greedy walk change after the match, get a scan of their own, into `offsets`.
    void recordSeparateScan(VkCommandBuffer cmd, uint32_t slot, const Stream& input, const shared::DerivePush& p);
    // Which modules start a rewrite when predecessors of several modules consume their neighbours.
    void recordGreedyWalk(VkCommandBuffer cmd, uint32_t slot, const Stream& in);
    // A step's write, its plant starts and its particle states' moves. With a fused scan the write takes each
    // module's counts before it in its tile and the tiles' offsets, the plant starts and the moves likewise;
    // otherwise each module's offset and choice.
    void recordStepWrite(VkCommandBuffer cmd, uint32_t slot, const Stream& input, Stream& output,
                         const shared::DerivePush& p);
    // A step's push constants for derive/step_sizes.comp, its mode and depth fields left at 0.
    shared::StepSizesPush sizesPush(uint32_t slot, const Stream& input, const Stream& output, uint64_t budget,
                                    bool buildsTree) const;
    // Room for `modules` in every stream (streams[cur] keeps its string) and in the scratch.
    void makeRoom(int cur, uint64_t modules);
    // Modules the output of a recorded step may hold: its stream's room, and the next step's scratch.
    uint64_t recordedCapacity(const Stream& out) const;
    // Batch slots' plant state, for `steps` steps.
    void reserveBatchState(uint32_t steps);

    // ---- steps that rewrite by depths: decomposition and the homomorphism (derive_gpu_depths.cpp) ----

    // The homomorphism as the batch's next step: the plants' globals as the Start block sets them, every plant
    // rewritten (as the CPU reference applies it).
    void planHomomorphism(stream::PlantControl& control, std::vector<RecordedStep>& batch);
    // Steps a batch holds: as many as there are slots, fewer where the steps rewrite by many depths.
    size_t batchSteps() const;
    // Depth blocks a recorded step has in the step words: the decomposition's depths recorded, and one to probe
    // for more. The homomorphism, a batch's last step, has as many as its own depths need.
    uint32_t depthBlocksPerStep() const;
    // The step words for `batch` with its depths.
    void reserveStepWords(const std::vector<RecordedStep>& batch);
    // Where batch slot `slot`'s depth `depth` has its block in the step words, as a word index.
    uint32_t depthBlock(uint32_t slot, int depth) const;
    // Depths recorded per step, for the decomposition and the homomorphism: a few at first, more each time a
    // step needs more (kStopDepths), up to the grammar's deepest.
    int decompositionDepths = 0, homomorphismDepths = 0;
    // After a step that stopped for lack of depths: more of them for the next recording.
    void deepen(const RecordedStep& step);
    // A step whose depths go on from its resumeDepth: its result so far into its block (kSizeResume), then its
    // depths from there.
    void recordResumedDepths(VkCommandBuffer cmd, const RecordedStep& step, uint32_t slot, int in, uint32_t seed,
                             uint64_t budget);
    // The rewriting by depths of a step whose input is streams[old]: its first depth reads the next stream and
    // the depths write the stream after it and the next in turn (an even depth reads the next stream), `depths`
    // of them from `firstDepth` on and, short of the passes' deepest, one more that only looks for modules left
    // to rewrite (kStopDepths). Then the result goes into the next stream, and each module takes its origin's
    // particle state.
    void recordDepths(VkCommandBuffer cmd, uint32_t slot, int old, const RecursivePasses& passes, int firstDepth,
                      int depths, uint32_t stepIndex, uint32_t seed, uint64_t budget);
    // The homomorphism's depths from `firstDepth` on, with its kernels' tables.
    void recordHomomorphismDepths(VkCommandBuffer cmd, uint32_t slot, int in, int firstDepth, uint32_t seed,
                                  uint64_t budget);
    // derive/stream_copy.comp in `mode` from `from` into `to`, with the workgroups at `argumentsOffset` of the
    // step words.
    void recordStreamCopy(VkCommandBuffer cmd, uint32_t mode, const Stream& from, Stream& to,
                          VkDeviceSize argumentsOffset);
    // The homomorphism of streams[in] as batch step `slot`.
    void recordHomomorphism(VkCommandBuffer cmd, uint32_t slot, int in, uint32_t seed, uint64_t budget);
    // The homomorphism of the derived string streams[cur], into the next stream, as a batch of its own (after
    // the sequential strategy's steps); returns its index. `control`'s plants have finished.
    int applyHomomorphism(stream::PlantControl& control, int cur, uint32_t seed, uint64_t budget, bool timed,
                          GpuDeriveStats& stats);

    // ---- derivation step by step over simulated time (derive_gpu_stepped.cpp) ----

    // A step recordAdvance() wrote into a caller's command buffer, the homomorphism after it where it has one: the
    // stream the step writes, the plants deriving, and the buffers its recording replaced, kept until its
    // submission has ended.
    struct PendingStep {
        std::vector<RecordedStep> batch;
        int out = 0;
        uint32_t deriving = 0;
        std::vector<vk::Buffer> retired;
    };
    // What begin() started: the plants' control, kept between steps, and the stream their string is in.
    struct Stepped {
        stream::PlantControl control;
        stream::DeriveOptions options;
        uint32_t seed = 0;
        uint64_t budget = 0;
        uint32_t fieldStep = 0; // advance() calls: the random streams' step
        int cur = 0;
        bool drawnStands = false; // the last drawn() string is the one drawn() would write now (drawnStands())
        std::optional<PendingStep> pending; // recordAdvance()'s, until advanced()
        // drawnSymbols and drawnParams hold the drawn string as the homomorphism wrote it; else the stream does,
        // unchanged since (a recorded step wrote it, and no drawing has grown it yet).
        bool drawnSaved = false;
    };
    // The last drawn() string's symbols and parameters as the homomorphism wrote them, which the drawing grows in
    // place (grow/grown_sizes.comp): recordDrawnAgain() puts them back.
    vk::Buffer drawnSymbols, drawnParams;
    // The drawn string streams[lastStream] copied into them, recorded into `cmd`.
    void recordDrawnSave(VkCommandBuffer cmd);
    std::unique_ptr<Stepped> stepped;
    Stepped& steppedState(const char* call) const;
    // The same, refusing while a recorded step is not read yet (advanced()).
    Stepped& settledState(const char* call) const;
    // advance()'s plan: which plants derive (returned: how many), their plant state into the batch slot, and the
    // step into `batch`.
    uint32_t planAdvance(const std::vector<uint8_t>& due, std::vector<RecordedStep>& batch);
    // begin() and resume(): from the axioms, or from a saved state.
    void beginStepped(const stream::DeriveOptions& options, const stream::SteppedState* from, uint64_t room = 0);
    // Runs `batch` from the stepped string's stream; returns the stream it ends in.
    int runSteppedBatch(std::vector<RecordedStep>& batch, int stepsAfterBatch);

    // ---- the sequential strategy (derive_gpu_sequential.cpp) ----

    // The stack levels the deepest decomposition can use (one level per depth, and the last one's modules).
    uint32_t deepestStack() const;

    // Sizes the decomposition stack for `levels` levels per plant.
    void ensureStack(uint32_t levels);

    // Buffers of a sequential derivation of `plants` plants; the locals start at zero as cpfg's do.
    void prepareSequential();

    // Dispatches `first` .. `first + count - 1` of a pass of the sequential kernel. The last one tells in errors[2]
    // whether a plant has work left.
    void dispatchSequential(VkCommandBuffer cmd, uint32_t mode, const Stream& in, const Stream& out,
                            const shared::DerivePush& base, uint32_t first, uint32_t count);

    // One step with one invocation per plant: count (growing the stack when a plant outgrows it, splitting the work
    // finer when the driver cuts loops), then write in the same dispatches.
    int stepSequential(int cur, uint32_t stepIndex, uint32_t seed, uint64_t budget, vk::Timestamps* timer,
                       GpuDeriveStats& stats);
};

} // namespace simeco::gpu
