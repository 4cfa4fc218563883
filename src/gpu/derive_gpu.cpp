#include "gpu/derive_gpu.h"

#include <algorithm>
#include <chrono>
#include <cstring>
#include <initializer_list>
#include <functional>
#include <map>
#include <optional>
#include <span>

#include <fmt/format.h>

#include "compute/shared/derive_layout.h"
#include "compute/shared/particle_layout.h"
#include "cpu/evaluator.h"
#include "gpu/bracket_tree.h"
#include "gpu/derive_codegen.h"
#include "gpu/glsl_compiler.h"
#include "gpu/production_codegen.h"
#include "gpu/scan.h"
#include "ir/species.h"
#include "vk/barriers.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/timestamps.h"

namespace simeco::gpu {

namespace {

using shared::DeriveHelperPush;
using shared::DerivePush;
using vk::Hazard;

// A module stream on the device: symbols, parameters, the plant table, and for decomposition the position
// each module came from in the string being rewritten and whether the next depth examines it.
struct Stream {
    vk::Buffer sym, par, plantStart, origin, live;
    vk::Buffer particles; // kParticleStateFloats per module, while the derivation carries particle state
    uint64_t capacity = 0;
    uint32_t count = 0;
};

VkDeviceSize bytes(uint64_t count, uint64_t size) { return std::max<VkDeviceSize>(count * size, 4); }

constexpr uint32_t kGreedyChunk = 256; // as greedy_chunks.glsl
constexpr uint32_t kGreedyBlock = 256; // chunks per block of greedy_scan.comp

// The driver ended an invocation's loops early (kFlagLoopCut) where the work cannot be split any finer.
ir::LimitError loopsCutError(const std::string& what) {
    return ir::LimitError(fmt::format("{}: the device's driver ended a shader loop early (lavapipe ends an "
                                      "invocation's loops after 65535 iterations in all); derive this grammar with "
                                      "--backend cpu",
                                      what));
}

// Whether every plant's `[` and `]` pair up within the plant.
bool bracketsBalanced(const cpu::ModuleString& s) {
    for (size_t plant = 0; plant < s.plants(); ++plant) {
        int64_t depth = 0;
        for (uint64_t i = s.plantStart[plant]; i < s.plantStart[plant + 1]; ++i) {
            depth += s.sym[i] == ir::kBranchOpen ? 1 : s.sym[i] == ir::kBranchClose ? -1 : 0;
            if (depth < 0) return false;
        }
        if (depth != 0) return false;
    }
    return true;
}

} // namespace

struct GpuDeriver::Impl {
    const vk::Context& ctx;
    std::vector<ir::Grammar> species;
    GpuStrategy strategy;
    int stride;
    bool texelInputs; // the generated kernels read their inputs through uniform texel buffers (GpuLoads)
    int lastStream = -1; // the stream the last derive() ended in
    uint32_t globalStride = 0, arrayStride = 0; // globals and array elements per plant (the most of any species)
    GeneratedKernels kernels;
    std::optional<vk::ComputePipeline> decompositionMatch, decompositionWrite, sequential;
    // The step's match and write passes, specialised for what the step needs (stepMatch(), stepWrite()): to copy
    // the modules of frozen plants (kFrozenPlants) and for a stream of one plant (kSinglePlant). Each variant is
    // made the first time a step needs it: drivers compile a pipeline when it is made or first run, and a
    // derivation needs one or two of them.
    std::vector<uint32_t> matchSpirv, writeSpirv;
    std::map<std::pair<bool, bool>, vk::ComputePipeline> matchVariants; // by (frozen plants, single plant)
    std::map<bool, vk::ComputePipeline> writeVariants;                  // by single plant
    bool anyFrozen = false; // some plant is frozen in the step being derived
    // The homomorphism, generated as the decomposition of grammars whose decomposition is their homomorphism;
    // empty when no species has one, or when its productions need the host (homomorphismHostReason).
    GeneratedKernels homomorphismKernels;
    std::optional<vk::ComputePipeline> homomorphismMatch, homomorphismWrite;
    std::optional<std::string> homomorphismHostReason;
    // The error sites of the kernels being run (the homomorphism's while it runs).
    const std::vector<ErrorSite>* activeErrors = nullptr;
    vk::ComputePipeline plantStarts, plantHintsKernel, cutApply;
    std::optional<vk::ComputePipeline> plantStartsTiled; // with a fused scan, specialised for its match words
    vk::ComputePipeline greedyReduce, greedyScan, greedyMark, homomorphismStart;
    // The particle state's moves, made the first time a derivation carries it: by the step's positions (with a
    // fused scan, specialised for its match words), or from each module's origin.
    std::optional<vk::ComputePipeline> particleScatter, particleGather;
    bool carriesParticles = false; // the derivation running carries particle state (DeriveOptions::particles)
    GpuScan scan;
    BracketTree brackets; // after scan, which it uses
    vk::Buffer contextSkip, funcTables, errors, readback;
    vk::Buffer globals, arrays, plantFrozen;
    vk::Buffer counts, choices, drawStarts, offsets, cutDelta, cutBefore, examined;
    vk::Buffer chunkFunctions, chunkEntries; // the greedy walk over predecessors of several modules
    vk::Buffer blockFunctions, blockEntries; // ... and over blocks of chunks
    vk::Buffer plantHints; // of the stream the running kernels find plants in (recordPlantHints)
    vk::Buffer tileSums, tileOffsets; // a fused scan's sums of counts per subgroup, and their scan
    uint32_t tileSize = 1;            // a fused scan's tile: the device's subgroup size
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

    Impl(const vk::Context& c, std::vector<ir::Grammar> grammars, GpuStrategy requested, GpuLoads loads)
        : ctx(c), species(std::move(grammars)), strategy(requested), stride(1),
          texelInputs(loads == GpuLoads::TexelBuffers ||
                      (loads == GpuLoads::Auto && c.deviceInfo().type == VK_PHYSICAL_DEVICE_TYPE_CPU)),
          plantStarts(vk::ComputePipeline::embedded(c, "derive/plant_starts")),
          plantHintsKernel(vk::ComputePipeline::embedded(c, "derive/plant_hints")),
          cutApply(vk::ComputePipeline::embedded(c, "derive/cut_apply")),
          greedyReduce(vk::ComputePipeline::embedded(c, "derive/greedy_reduce")),
          greedyScan(vk::ComputePipeline::embedded(c, "derive/greedy_scan")),
          greedyMark(vk::ComputePipeline::embedded(c, "derive/greedy_mark")),
          homomorphismStart(vk::ComputePipeline::embedded(c, "derive/homomorphism_start")), scan(c),
          brackets(c, scan) {
        if (species.empty()) throw std::invalid_argument("GpuDeriver: no species");
        for (const ir::Grammar& g : species) {
            if (std::optional<std::string> reason = gpuUnsupportedReason(g))
                throw std::runtime_error("the GPU backend cannot derive this grammar: " + *reason +
                                         " (use --backend cpu)");
            std::optional<std::string> parallelReason = gpuParallelUnsupportedReason(g);
            if (parallelReason && strategy == GpuStrategy::Parallel)
                throw std::runtime_error("the parallel GPU passes cannot derive this grammar: " + *parallelReason);
            if (parallelReason) strategy = GpuStrategy::Sequential;
            stride = std::max(stride, g.maxParams());
            globalStride = std::max(globalStride, static_cast<uint32_t>(g.globalNames.size()));
            uint32_t elements = 0;
            for (const ir::GlobalArray& a : g.arrays) elements += static_cast<uint32_t>(a.init.size());
            arrayStride = std::max(arrayStride, elements);
        }
        if (strategy == GpuStrategy::Auto) strategy = GpuStrategy::Parallel;
        auto start = std::chrono::steady_clock::now();
        auto build = [&](const std::string& source, const char* name) {
            std::vector<uint32_t> spirv = cachedComputeKernel(source, name);
            return vk::ComputePipeline(ctx, spirv, name);
        };
        if (strategy == GpuStrategy::Sequential) {
            kernels = generateSequentialKernel(species, texelInputs);
            sequential.emplace(build(kernels.sequential, "derive/sequential"));
        } else {
            kernels = generateDeriveKernels(species, texelInputs);
            if (kernels.stride != static_cast<uint32_t>(stride))
                throw std::logic_error(fmt::format("the step's write pass stores {} parameter slots per module, the "
                                                   "stream has {}", kernels.stride, stride));
            matchSpirv = cachedComputeKernel(kernels.match, "derive/match");
            writeSpirv = cachedComputeKernel(kernels.write, "derive/write");
        }
        if (kernels.hasDecomposition && strategy == GpuStrategy::Parallel) {
            decompositionMatch.emplace(build(kernels.decompositionMatch, "derive/decomposition_match"));
            decompositionWrite.emplace(build(kernels.decompositionWrite, "derive/decomposition_write"));
        }
        if (kernels.fusedScan) {
            const uint32_t choiceBits[] = {kernels.choiceBits};
            plantStartsTiled = vk::ComputePipeline::embedded(ctx, "derive/plant_starts_tiled", choiceBits);
            tileSize = ctx.deviceInfo().subgroupSize;
            if (tileSize == 0 || shared::kDeriveWorkgroupSize % tileSize != 0)
                throw std::runtime_error(fmt::format("the GPU backend needs subgroups that divide its workgroups of {} "
                                                     "invocations; device {} has subgroups of {}",
                                                     shared::kDeriveWorkgroupSize, ctx.deviceInfo().name, tileSize));
        }
        activeErrors = &kernels.errors;
        buildHomomorphism(build);
        compileSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

        std::vector<uint32_t> skipBits = codegen::contextSkipBits(species);
        contextSkip = vk::deviceBufferWith(ctx, std::span<const uint32_t>(skipBits));
        std::vector<double> tables = kernels.functionTables;
        if (tables.empty()) tables.push_back(0.0);
        funcTables = vk::deviceBufferWith(ctx, std::span<const double>(tables));
        errors = vk::Buffer(ctx, 16, vk::MemoryUsage::DeviceLocal);
        readback = vk::Buffer(ctx, 16, vk::MemoryUsage::Readback);
    }


    // The homomorphism's kernels: the decomposition passes of copies of the species whose decomposition is
    // their homomorphism (one pass per depth, contexts in the derived string, no cuts).
    template <typename Build>
    void buildHomomorphism(Build& build) {
        bool any = false;
        std::vector<ir::Grammar> images = species;
        for (ir::Grammar& g : images) {
            any = any || !g.homomorphism.productions.empty();
            g.decomposition = g.homomorphism;
            g.productions = ir::RuleSet{};
            if (!homomorphismHostReason) homomorphismHostReason = gpuUnsupportedReason(g);
            if (!homomorphismHostReason) homomorphismHostReason = gpuParallelUnsupportedReason(g);
        }
        if (!any) {
            homomorphismHostReason.reset(); // nothing to apply, on the device or elsewhere
            return;
        }
        if (homomorphismHostReason) return;
        homomorphismKernels = generateDeriveKernels(images, texelInputs);
        homomorphismMatch.emplace(build(homomorphismKernels.decompositionMatch, "derive/homomorphism_match"));
        homomorphismWrite.emplace(build(homomorphismKernels.decompositionWrite, "derive/homomorphism_write"));
    }

    // The most bytes a buffer of the derivation may hold: what a kernel can bind, as storage or, with texel
    // inputs, as a texel buffer of 4-byte texels.
    uint64_t bufferLimit() const {
        uint64_t limit = ctx.limits().maxStorageBufferRange;
        if (texelInputs) limit = std::min<uint64_t>(limit, uint64_t(ctx.limits().maxTexelBufferElements) * 4);
        return limit;
    }

    void checkRange(uint64_t count, uint64_t size, const char* what) const {
        uint64_t limit = bufferLimit();
        if (count * size > limit)
            throw ir::LimitError(fmt::format("the device binds at most {} MiB per buffer; {} modules need {} MiB of {} "
                                             "(derive fewer steps or plants, or use a device with larger buffers)",
                                             limit >> 20, count, (count * size) >> 20, what));
    }

    void ensureStream(Stream& s, uint64_t count) {
        if (s.capacity >= count && s.sym) return;
        uint64_t capacity = std::max<uint64_t>({count + count / 2, 1024, s.capacity});
        uint64_t limit = bufferLimit();
        capacity = std::min<uint64_t>(capacity, limit / (4ull * uint64_t(stride)));
        capacity = std::max(capacity, count);
        checkRange(count, 4ull * uint64_t(stride), "parameters");
        s.sym = vk::Buffer(ctx, bytes(capacity, 4), vk::MemoryUsage::DeviceLocal);
        s.par = vk::Buffer(ctx, bytes(capacity, 4ull * uint64_t(stride)), vk::MemoryUsage::DeviceLocal);
        s.origin = vk::Buffer(ctx, bytes(capacity, 4), vk::MemoryUsage::DeviceLocal);
        s.live = vk::Buffer(ctx, bytes(capacity, 4), vk::MemoryUsage::DeviceLocal);
        if (!s.plantStart) s.plantStart = vk::Buffer(ctx, bytes(plants + 1, 4), vk::MemoryUsage::DeviceLocal);
        s.capacity = capacity;
    }

    void ensureScratch(uint64_t count) {
        scan.reserve(static_cast<uint32_t>(count + 1));
        if (scratchCapacity >= count + 1 && counts) return;
        uint64_t capacity = std::max<uint64_t>(count + count / 2 + 1, 1024);
        capacity = std::min<uint64_t>(capacity, bufferLimit() / 4);
        capacity = std::max<uint64_t>(capacity, count + 1);
        checkRange(count + 1, 4, "per-module scratch");
        for (vk::Buffer* b : {&counts, &choices, &drawStarts, &offsets, &cutDelta, &cutBefore, &examined})
            *b = vk::Buffer(ctx, bytes(capacity, 4), vk::MemoryUsage::DeviceLocal);
        chunkFunctions = vk::Buffer(ctx, bytes(capacity / kGreedyChunk + 1, 4), vk::MemoryUsage::DeviceLocal);
        chunkEntries = vk::Buffer(ctx, bytes(capacity / kGreedyChunk + 1, 4), vk::MemoryUsage::DeviceLocal);
        uint64_t blocks = capacity / kGreedyChunk / kGreedyBlock + 1;
        blockFunctions = vk::Buffer(ctx, bytes(blocks, 4), vk::MemoryUsage::DeviceLocal);
        blockEntries = vk::Buffer(ctx, bytes(blocks, 4), vk::MemoryUsage::DeviceLocal);
        plantHints = vk::Buffer(ctx, bytes(shared::plantHintBlocks(static_cast<uint32_t>(capacity)) + 1, 4),
                                vk::MemoryUsage::DeviceLocal);
        if (kernels.fusedScan)
            for (vk::Buffer* b : {&tileSums, &tileOffsets})
                *b = vk::Buffer(ctx, bytes(tilesFor(capacity) + 1, 4), vk::MemoryUsage::DeviceLocal);
        scratchCapacity = capacity;
    }

    uint64_t tilesFor(uint64_t count) const { return (count + tileSize - 1) / tileSize; }

    DerivePush push(uint32_t count, uint32_t step, uint32_t seed, uint32_t pass, uint32_t oldCount, uint32_t depth) const {
        DerivePush p{};
        p.count = count;
        p.plants = plants;
        p.step = step;
        p.seed = seed;
        p.pass = pass;
        p.stride = static_cast<uint32_t>(stride);
        p.globalCount = globalStride;
        p.arrayStride = arrayStride;
        p.oldCount = oldCount;
        p.depth = depth;
        p.loopProbeTrips = shared::kLoopProbeTrips;
        for (uint32_t k = 0; k < shared::kLoopProbeCounts; ++k)
            p.loopProbeCounts[k] = k + 1;
        return p;
    }

    // Submits `record`, waits, and returns the total the recording copied into the readback buffer; throws
    // the located error a kernel reported, and kFlagLoopCut unless the caller retries (`retriesCutLoops`).
    uint32_t submit(const std::function<void(VkCommandBuffer)>& record, vk::Timestamps* timer, double& gpuMillis,
                    bool retriesCutLoops = false) {
        ctx.submitAndWait([&](VkCommandBuffer cmd) {
            if (timer) {
                timer->cmdReset(cmd);
                timer->cmdWrite(cmd, 0, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
            }
            record(cmd);
            vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
            VkBufferCopy error{0, 4, 12}; // the error site, the flags, the sequential kernel's unfinished plants
            vkCmdCopyBuffer(cmd, errors.handle(), readback.handle(), 1, &error);
            vk::memoryBarrier(cmd, Hazard::TransferToHost);
            if (timer) timer->cmdWrite(cmd, 1, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
        });
        if (timer) gpuMillis += timer->elapsedNs(0, 1) / 1e6;
        uint32_t words[4];
        std::memcpy(words, readback.mapped(), sizeof words);
        lastFlags = words[2];
        lastUnfinished = words[3] != 0;
        if (words[1] != 0) {
            uint32_t site = words[1] - 1;
            const std::vector<ErrorSite>& sites = *activeErrors;
            if (site < sites.size()) throw ir::InputError(sites[site].loc, sites[site].message);
            throw std::runtime_error("a derivation kernel reported an unknown error");
        }
        if ((lastFlags & shared::kFlagLoopCut) && !retriesCutLoops)
            throw loopsCutError("a production loops long or a context walk passes very many modules");
        return words[0];
    }

    static void checkBudget(uint64_t total, uint64_t budget, uint32_t stepIndex) {
        if (total > budget)
            throw ir::LimitError(fmt::format("the string outgrew the module budget of {} modules in step {} "
                                             "(raise it with --max-modules, or derive fewer steps)",
                                             budget, stepIndex));
    }

    void copyTotal(VkCommandBuffer cmd) {
        vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
        VkBufferCopy total{0, 0, 4};
        vkCmdCopyBuffer(cmd, scan.totalBuffer().handle(), readback.handle(), 1, &total);
    }

    // Which modules start a rewrite when predecessors of several modules consume their neighbours.
    void recordGreedyWalk(VkCommandBuffer cmd, const Stream& in) {
        uint32_t n = in.count;
        uint32_t chunks = (n + kGreedyChunk - 1) / kGreedyChunk;
        DeriveHelperPush chunked{n, kernels.longestPredecessor, 0, plants};
        greedyReduce.dispatch(cmd, {choices, plantTable(in), chunkFunctions}, chunked, greedyReduce.groupsFor(chunks));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        uint32_t blocks = (chunks + kGreedyBlock - 1) / kGreedyBlock;
        for (uint32_t phase = 0; phase < 3; ++phase) {
            DeriveHelperPush composed{chunks, phase, 0, plants};
            greedyScan.dispatch(cmd, {chunkFunctions, chunkEntries, blockFunctions, blockEntries}, composed,
                                phase == 1 ? 1 : greedyScan.groupsFor(blocks));
            vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        }
        greedyMark.dispatch(cmd, {choices, plantTable(in), chunkEntries, counts}, chunked, greedyMark.groupsFor(chunks));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    }

    // The bindings every generated derivation kernel starts with (see declarations() in derive_codegen.cpp):
    // the string being rewritten, its brackets, the plants' globals and arrays, function tables, the context
    // filter and the error word; `rest` follows them.
    // `parameterVectors`: the kernel reads each module's parameters as one vector too, the last binding
    // (GeneratedKernels::matchReadsParameterVectors, writeReadsParameterVectors).
    void dispatchDerive(VkCommandBuffer cmd, const vk::ComputePipeline& kernel, const Stream& strings,
                        std::initializer_list<vk::BufferRange> rest, const DerivePush& p, uint32_t n,
                        bool parameterVectors = false) {
        std::vector<vk::BufferRange> buffers{strings.sym, strings.par, plantTable(strings), brackets.tree(),
                                             brackets.levelInfo(), brackets.partners(), globals, arrays, funcTables, contextSkip, errors,
                                             plantFrozen};
        buffers.insert(buffers.end(), rest.begin(), rest.end());
        buffers.push_back(plantHints);
        if (parameterVectors)
            buffers.push_back(vk::BufferRange(strings.par).viewedAs(stride == 4 ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                                                 : VK_FORMAT_R32G32_SFLOAT));
        kernel.dispatchBytes(cmd, buffers, std::as_bytes(std::span(&p, 1)), kernel.groupsFor(n));
    }

    // The bracket tree and partners of streams[index], unless its partners are already there.
    void recordBrackets(VkCommandBuffer cmd, int index) {
        const Stream& s = streams[index];
        if (s.count == 0 || partnersStream == index) return;
        brackets.record(cmd, s.sym, s.count);
        partnersStream = index;
        ++bracketTrees;
    }

    // Called before a pass writes streams[index]: partners describing it no longer do.
    void overwriting(int index) {
        if (partnersStream == index) partnersStream = -1;
    }

    // Each plant's first module in the stream written with `offsets`.
    void recordPlantStarts(VkCommandBuffer cmd, const Stream& from, const Stream& to, uint32_t n, uint32_t total) {
        DeriveHelperPush hp{n, 0, total, plants};
        plantStarts.dispatch(cmd, {plantTable(from), offsets, plantTable(to)}, hp, plantStarts.groupsFor(plants + 1));
    }

    // Room for the particle state of s's modules, while the derivation carries it.
    void ensureParticles(Stream& s) {
        if (!carriesParticles) return;
        static_assert(shared::kParticleStateFloats == 4 * shared::kParticleStateVec4s);
        uint64_t perModule = 4ull * shared::kParticleStateFloats;
        checkRange(s.count, perModule, "particle state");
        uint64_t capacity = std::min<uint64_t>(s.capacity, bufferLimit() / perModule);
        if (!s.particles || s.particles.size() < bytes(s.count, perModule))
            s.particles = vk::Buffer(ctx, bytes(std::max<uint64_t>(capacity, s.count), perModule),
                                     vk::MemoryUsage::DeviceLocal);
    }

    // After a step without decomposition: each module of streams[from] passes its particle state to its successor
    // in streams[to], at the positions this step's scan gave it.
    void scatterParticles(int from, int to, vk::Timestamps* timer, double& millis) {
        Stream& in = streams[from];
        Stream& out = streams[to];
        ensureParticles(out);
        if (in.count == 0 || out.count == 0) return;
        if (!particleScatter) {
            const uint32_t choiceBits[] = {kernels.fusedScan ? kernels.choiceBits : 0u};
            particleScatter = vk::ComputePipeline::embedded(ctx, "derive/particle_scatter", choiceBits);
        }
        DeriveHelperPush hp{in.count, kernels.fusedScan ? tileSize : 0u, out.count, plants};
        submit(
            [&](VkCommandBuffer cmd) {
                particleScatter->dispatch(cmd,
                                          {kernels.fusedScan ? counts : offsets, kernels.fusedScan ? tileOffsets : offsets,
                                           in.particles, out.particles},
                                          hp, particleScatter->groupsFor(in.count));
            },
            timer, millis);
    }

    // Each module of streams[to] takes the particle state of the module of streams[from] it descends from (its
    // origin): after decomposition, the homomorphism or a sequential step.
    void gatherParticles(int from, int to, vk::Timestamps* timer, double& millis) {
        Stream& out = streams[to];
        ensureParticles(out);
        if (out.count == 0) return;
        if (!particleGather) particleGather = vk::ComputePipeline::embedded(ctx, "derive/particle_gather");
        DeriveHelperPush hp{out.count, 0, 0, plants};
        submit(
            [&](VkCommandBuffer cmd) {
                particleGather->dispatch(cmd, {out.origin, streams[from].particles, out.particles}, hp,
                                         particleGather->groupsFor(out.count));
            },
            timer, millis);
    }

    // A stream of one plant is that plant: the variants specialised for it find no plants.
    bool singlePlant(bool findsPlants) const { return plants == 1 && findsPlants; }

    const vk::ComputePipeline& stepMatch() {
        bool single = singlePlant(kernels.matchFindsPlants || anyFrozen);
        auto key = std::make_pair(anyFrozen, single);
        auto found = matchVariants.find(key);
        if (found == matchVariants.end()) {
            const uint32_t values[] = {anyFrozen ? VK_TRUE : VK_FALSE, single ? VK_TRUE : VK_FALSE};
            found = matchVariants.emplace(key, vk::ComputePipeline(ctx, matchSpirv, "derive/match", values)).first;
        }
        return found->second;
    }

    const vk::ComputePipeline& stepWrite() {
        bool single = singlePlant(kernels.writeFindsPlants);
        auto found = writeVariants.find(single);
        if (found == writeVariants.end()) {
            const uint32_t values[] = {VK_FALSE, single ? VK_TRUE : VK_FALSE};
            found = writeVariants.emplace(single, vk::ComputePipeline(ctx, writeSpirv, "derive/write", values)).first;
        }
        return found->second;
    }

    // The hints the next derivation kernels find plants of `s` with; they stay valid until the next call.
    void recordPlantHints(VkCommandBuffer cmd, const Stream& s) {
        DeriveHelperPush hp{s.count, 0, 0, plants};
        plantHintsKernel.dispatch(cmd, {plantTable(s), plantHints}, hp,
                                  plantHintsKernel.groupsFor(shared::plantHintBlocks(s.count) + 1));
    }

    vk::BufferRange plantTable(const Stream& s) const { return vk::BufferRange(s.plantStart, 0, bytes(plants + 1, 4)); }

    // One derivation step from streams[cur] into a new stream; returns its index.
    int step(int cur, uint32_t stepIndex, uint32_t seed, uint64_t budget, vk::Timestamps* timer, GpuDeriveStats& stats) {
        Stream& in = streams[cur];
        int outIndex = (cur + 1) % 3;
        Stream& out = streams[outIndex];
        uint32_t n = in.count;
        double millis = 0;
        ensureScratch(n);
        matchScanWrite(cur, outIndex, stepIndex, seed, budget, timer, millis);
        if (carriesParticles && !kernels.hasDecomposition) scatterParticles(cur, outIndex, timer, millis);
        // Match writes counts, choices and draw starts, and write reads them; with a fused scan the counts and the
        // choice are one word, otherwise a separate scan reads the counts twice and writes offsets, which write reads.
        uint64_t perModule = kernels.fusedScan ? 4 + 4ull * uint64_t(stride) + 8 + 8
                                               : 4 + 4ull * uint64_t(stride) + 12 + 12 + 12;
        stats.bytesMoved += uint64_t(n) * perModule + uint64_t(out.count) * (4 + 4ull * uint64_t(stride) + 8);
        if (kernels.hasDecomposition) {
            outIndex = decompose(cur, outIndex, stepIndex, seed, budget, timer, millis, stats, decompositionPasses());
            if (carriesParticles) gatherParticles(cur, outIndex, timer, millis);
        }
        if (timer) stats.stepMillis.push_back(millis);
        return outIndex;
    }

    // One step's match, scan and write. With a fused scan (GeneratedKernels::fusedScan) match also sums each
    // subgroup's counts and the host scans only those sums; otherwise the counts, which cuts and the greedy walk
    // change after the match, get a scan of their own.
    void matchScanWrite(int cur, int outIndex, uint32_t stepIndex, uint32_t seed, uint64_t budget,
                        vk::Timestamps* timer, double& millis) {
        const Stream& in = streams[cur];
        Stream& out = streams[outIndex];
        overwriting(outIndex);
        uint32_t n = in.count;
        bool fused = kernels.fusedScan;
        DerivePush p = push(n, stepIndex, seed, stepIndex * shared::kPassesPerStep, n, 0);
        uint32_t total = submit(
            [&](VkCommandBuffer cmd) {
                vk::cmdFill(cmd, errors, 0);
                if (kernels.mayCut) vk::cmdFill(cmd, cutDelta, 0);
                vk::memoryBarrier(cmd, Hazard::TransferToCompute);
                if ((kernels.matchFindsPlants || kernels.writeFindsPlants || anyFrozen) && plants > 1)
                    recordPlantHints(cmd, in);
                vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                if (kernels.needsBrackets) recordBrackets(cmd, cur);
                const vk::ComputePipeline& matcher = stepMatch();
                if (fused) {
                    dispatchDerive(cmd, matcher, in, {counts, drawStarts, cutDelta, tileSums}, p, n,
                                   kernels.matchReadsParameterVectors);
                    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                    scan.record(cmd, tileSums, tileOffsets, static_cast<uint32_t>(tilesFor(n)));
                } else {
                    dispatchDerive(cmd, matcher, in, {counts, choices, drawStarts, cutDelta}, p, n,
                                   kernels.matchReadsParameterVectors);
                    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                    if (kernels.mayCut && n > 0) {
                        scan.record(cmd, cutDelta, cutBefore, n);
                        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                        DeriveHelperPush hp{n, 0, 0, plants};
                        cutApply.dispatch(cmd, {cutDelta, cutBefore, counts, choices}, hp, cutApply.groupsFor(n));
                        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                    }
                    if (kernels.longestPredecessor > 1 && n > 0) recordGreedyWalk(cmd, in);
                    scan.record(cmd, counts, offsets, n);
                }
                copyTotal(cmd);
            },
            timer, millis);
        checkBudget(total, budget, stepIndex);
        ensureStream(out, total);
        submit(
            [&](VkCommandBuffer cmd) {
                vk::cmdFill(cmd, errors, 0);
                vk::memoryBarrier(cmd, Hazard::TransferToCompute);
                if (fused) {
                    if (kernels.carriesPartners) // the partners go after the kernel's own outputs
                        dispatchDerive(cmd, stepWrite(), in,
                                       {counts, tileOffsets, drawStarts, out.sym, out.par, out.origin, out.live,
                                        brackets.carriedPartners(total)},
                                       p, n, kernels.writeReadsParameterVectors);
                    else
                        dispatchDerive(cmd, stepWrite(), in,
                                       {counts, tileOffsets, drawStarts, out.sym, out.par, out.origin, out.live}, p, n,
                                       kernels.writeReadsParameterVectors);
                    DeriveHelperPush hp{n, tileSize, total, plants};
                    plantStartsTiled->dispatch(cmd, {plantTable(in), counts, tileOffsets, plantTable(out)}, hp,
                                               plantStartsTiled->groupsFor(plants + 1));
                } else {
                    dispatchDerive(cmd, stepWrite(), in,
                                   {offsets, choices, drawStarts, out.sym, out.par, out.origin, out.live}, p, n,
                                   kernels.writeReadsParameterVectors);
                    recordPlantStarts(cmd, in, out, n, total);
                }
                vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
            },
            timer, millis);
        out.count = total;
        if (kernels.carriesPartners && axiomsBalanced && partnersStream == cur) {
            brackets.carried();
            partnersStream = outIndex;
        }
    }

    // Recursive rewriting by depth: the decomposition's kernels, or the homomorphism's.
    struct RecursivePasses {
        const vk::ComputePipeline* match;
        const vk::ComputePipeline* write;
        int maxDepth;
    };

    RecursivePasses decompositionPasses() const {
        return {&*decompositionMatch, &*decompositionWrite, kernels.maxDecompositionDepth};
    }

    // Decomposition depth by depth, from streams[x]; the string being rewritten (contexts) is streams[old].
    int decompose(int old, int x, uint32_t stepIndex, uint32_t seed, uint64_t budget, vk::Timestamps* timer,
                  double& millis, GpuDeriveStats& stats, const RecursivePasses& passes) {
        Stream& oldStream = streams[old];
        int y = 3 - old - x;
        for (int depth = 0; depth < passes.maxDepth; ++depth) {
            Stream& X = streams[x];
            uint32_t n = X.count;
            if (n == 0) break;
            ensureScratch(n);
            uint32_t live = submit(
                [&](VkCommandBuffer cmd) {
                    recordPlantHints(cmd, X);
                    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                    scan.record(cmd, X.live, examined, n);
                    copyTotal(cmd);
                },
                timer, millis);
            if (live == 0) break;
            uint32_t pass = cpu::decompositionPass(stepIndex, depth);
            DerivePush p = push(n, stepIndex, seed, pass, oldStream.count, uint32_t(depth));
            uint32_t total = submit(
                [&](VkCommandBuffer cmd) {
                    vk::cmdFill(cmd, errors, 0);
                    vk::memoryBarrier(cmd, Hazard::TransferToCompute);
                    dispatchDerive(cmd, *passes.match, oldStream,
                                   {X.sym, X.par, plantTable(X), X.live, X.origin, examined, counts, choices, drawStarts},
                                   p, n);
                    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                    scan.record(cmd, counts, offsets, n);
                    copyTotal(cmd);
                },
                timer, millis);
            checkBudget(total, budget, stepIndex);
            Stream& Y = streams[y];
            overwriting(y);
            ensureStream(Y, total);
            submit(
                [&](VkCommandBuffer cmd) {
                    vk::cmdFill(cmd, errors, 0);
                    vk::memoryBarrier(cmd, Hazard::TransferToCompute);
                    dispatchDerive(cmd, *passes.write, oldStream,
                                   {X.sym, X.par, plantTable(X), X.live, X.origin, examined, offsets, choices, drawStarts,
                                    Y.sym, Y.par, Y.origin, Y.live},
                                   p, n);
                    recordPlantStarts(cmd, X, Y, n, total);
                    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                },
                timer, millis);
            Y.count = total;
            stats.bytesMoved += uint64_t(n) * (2 * (4 + 4ull * uint64_t(stride)) + 40) + uint64_t(total) * (12 + 4ull * uint64_t(stride));
            std::swap(x, y);
        }
        return x;
    }

    // The homomorphism of the derived string streams[cur], into another stream; returns its index. Every
    // module is examined at depth 0 with its contexts around itself, and the passes draw from step 0's.
    int applyHomomorphism(int cur, uint32_t seed, uint64_t budget, vk::Timestamps* timer, GpuDeriveStats& stats) {
        Stream& derived = streams[cur];
        uint32_t n = derived.count;
        if (n == 0) return cur;
        int x = (cur + 1) % 3;
        Stream& X = streams[x];
        overwriting(x);
        ensureStream(X, n);
        ensureScratch(n);
        double millis = 0;
        submit(
            [&](VkCommandBuffer cmd) {
                VkBufferCopy symbols{0, 0, bytes(n, 4)}, parameters{0, 0, bytes(n, 4ull * uint64_t(stride))},
                    table{0, 0, bytes(plants + 1, 4)};
                vkCmdCopyBuffer(cmd, derived.sym.handle(), X.sym.handle(), 1, &symbols);
                vkCmdCopyBuffer(cmd, derived.par.handle(), X.par.handle(), 1, &parameters);
                vkCmdCopyBuffer(cmd, derived.plantStart.handle(), X.plantStart.handle(), 1, &table);
                vk::cmdFill(cmd, errors, 0);
                vk::memoryBarrier(cmd, Hazard::TransferToCompute);
                DeriveHelperPush hp{n, 0, 0, plants};
                homomorphismStart.dispatch(cmd, {X.live, X.origin}, hp, homomorphismStart.groupsFor(n));
                if (homomorphismKernels.needsBrackets) recordBrackets(cmd, cur);
                vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
            },
            timer, millis);
        X.count = n;
        activeErrors = &homomorphismKernels.errors;
        RecursivePasses passes{&*homomorphismMatch, &*homomorphismWrite, homomorphismKernels.maxDecompositionDepth};
        int result = decompose(cur, x, 0, seed, budget, timer, millis, stats, passes);
        activeErrors = &kernels.errors;
        if (carriesParticles) gatherParticles(cur, result, timer, millis);
        return result;
    }

    // ---- the sequential strategy ----

    // The stack levels the deepest decomposition can use (one level per depth, and the last one's modules).
    uint32_t deepestStack() const {
        return kernels.hasDecomposition ? static_cast<uint32_t>(kernels.maxDecompositionDepth) + 1 : 1;
    }

    // Sizes the decomposition stack for `levels` levels per plant.
    void ensureStack(uint32_t levels) {
        uint64_t modules = uint64_t(plants) * levels * kernels.stackWidth;
        checkRange(modules, 4ull * uint64_t(stride), "decomposition stack (derive fewer plants at once)");
        checkRange(uint64_t(plants) * 3 * levels, 4, "decomposition stack state");
        stackSym = vk::Buffer(ctx, bytes(modules, 4), vk::MemoryUsage::DeviceLocal);
        stackPar = vk::Buffer(ctx, bytes(modules, 4ull * uint64_t(stride)), vk::MemoryUsage::DeviceLocal);
        stackState = vk::Buffer(ctx, bytes(uint64_t(plants) * 3 * levels, 4), vk::MemoryUsage::DeviceLocal);
        stackLevels = levels;
    }

    // Buffers of a sequential derivation of `plants` plants; the locals start at zero as cpfg's do.
    void prepareSequential() {
        uint64_t frameBytes = bytes(uint64_t(plants) * std::max(kernels.frameSlots, 1u), 8);
        frames = vk::Buffer(ctx, frameBytes, vk::MemoryUsage::DeviceLocal);
        framesCopy = vk::Buffer(ctx, frameBytes, vk::MemoryUsage::DeviceLocal);
        globalsCopy = vk::Buffer(ctx, globals.size(), vk::MemoryUsage::DeviceLocal);
        arraysCopy = vk::Buffer(ctx, arrays.size(), vk::MemoryUsage::DeviceLocal);
        plantCounts = vk::Buffer(ctx, bytes(plants, 4), vk::MemoryUsage::DeviceLocal);
        countsReadback = vk::Buffer(ctx, bytes(plants, 4), vk::MemoryUsage::Readback);
        resume = vk::Buffer(ctx, bytes(4ull * plants, 4), vk::MemoryUsage::DeviceLocal);
        ctx.submitAndWait([&](VkCommandBuffer cmd) { vk::cmdFill(cmd, frames, 0); });
        ensureStack(std::min(deepestStack(), 16u));
    }

    // Dispatches `first` .. `first + count - 1` of a pass of the sequential kernel. The last one tells in errors[2]
    // whether a plant has work left.
    void dispatchSequential(VkCommandBuffer cmd, uint32_t mode, const Stream& in, const Stream& out,
                            const DerivePush& base, uint32_t first, uint32_t count) {
        DerivePush p = base;
        p.mode = mode;
        p.stackLevels = stackLevels;
        p.chunk = chunk;
        bool counting = mode == 0;
        // The counting pass runs on copies of the state, so that the writing pass starts from the same one.
        std::vector<vk::BufferRange> buffers{in.sym, in.par, plantTable(in), brackets.tree(), brackets.levelInfo(),
                                             brackets.partners(),
                                             counting ? globalsCopy : globals, counting ? arraysCopy : arrays,
                                             funcTables, contextSkip, errors, plantFrozen,
                                             counting ? framesCopy : frames, stackSym, stackPar, stackState,
                                             plantCounts, plantTable(out), out.sym, out.par, resume, out.origin};
        for (p.dispatch = first; p.dispatch < first + count; ++p.dispatch) {
            if (p.dispatch + 1 == first + count) {
                vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
                vkCmdFillBuffer(cmd, errors.handle(), 8, 4, 0);
                vk::memoryBarrier(cmd, Hazard::TransferToCompute);
            }
            sequential->dispatchBytes(cmd, buffers, std::as_bytes(std::span(&p, 1)), sequential->groupsFor(plants));
            vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        }
    }

    // One step with one invocation per plant: count (growing the stack when a plant outgrows it, splitting the work
    // finer when the driver cuts loops), then write in the same dispatches.
    int stepSequential(int cur, uint32_t stepIndex, uint32_t seed, uint64_t budget, vk::Timestamps* timer,
                       GpuDeriveStats& stats) {
        Stream& in = streams[cur];
        int outIndex = (cur + 1) % 3;
        Stream& out = streams[outIndex];
        overwriting(outIndex);
        uint32_t n = in.count;
        double millis = 0;
        ensureScratch(n);
        ensureStream(out, 1); // bound (unused) while counting
        DerivePush p = push(n, stepIndex, seed, stepIndex * shared::kPassesPerStep, n, 0);
        p.moduleLimit = static_cast<uint32_t>(std::min<uint64_t>(budget, UINT32_MAX - 1));
        uint32_t longest = 0;
        for (size_t plant = 0; plant + 1 < hostPlantTable.size(); ++plant)
            longest = std::max(longest, hostPlantTable[plant + 1] - hostPlantTable[plant]);
        uint32_t dispatches = 0;
        for (bool done = false; !done;) {
            // Batches of dispatches until no plant has work left; a full stack or a cut loop starts over.
            uint32_t batch = std::max<uint32_t>(1, (longest + chunk - 1) / chunk);
            dispatches = 0;
            for (bool more = true; more; dispatches += batch) {
                submit(
                    [&](VkCommandBuffer cmd) {
                        vk::cmdFill(cmd, errors, 0);
                        if (dispatches == 0) {
                            for (auto [from, to] : {std::pair{&globals, &globalsCopy}, {&arrays, &arraysCopy},
                                                    {&frames, &framesCopy}}) {
                                VkBufferCopy all{0, 0, from->size()};
                                vkCmdCopyBuffer(cmd, from->handle(), to->handle(), 1, &all);
                            }
                        }
                        vk::memoryBarrier(cmd, Hazard::TransferToCompute);
                        if (dispatches == 0 && kernels.needsBrackets) recordBrackets(cmd, cur);
                        dispatchSequential(cmd, 0, in, out, p, dispatches, batch);
                        vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
                        VkBufferCopy countsCopy{0, 0, plantCounts.size()};
                        vkCmdCopyBuffer(cmd, plantCounts.handle(), countsReadback.handle(), 1, &countsCopy);
                    },
                    timer, millis, true);
                if (lastFlags & shared::kFlagOverLimit) checkBudget(uint64_t(budget) + 1, budget, stepIndex);
                more = lastUnfinished && !(lastFlags & (shared::kFlagLoopCut | shared::kFlagStackFull));
            }
            if (lastFlags & shared::kFlagLoopCut) {
                if (chunk == 1)
                    throw loopsCutError(fmt::format("step {}, one module at a time", stepIndex));
                chunk = std::max<uint32_t>(1, chunk / 4);
            } else if (lastFlags & shared::kFlagStackFull) {
                if (stackLevels >= deepestStack()) throw std::logic_error("decomposition stack full at the maximum depth");
                ensureStack(std::min(stackLevels * 4, deepestStack()));
            } else {
                done = true;
            }
        }
        std::vector<uint32_t> table(plants + 1, 0);
        const uint32_t* counted = reinterpret_cast<const uint32_t*>(countsReadback.mapped());
        uint64_t total = 0;
        for (uint32_t plant = 0; plant < plants; ++plant) {
            table[plant] = static_cast<uint32_t>(std::min<uint64_t>(total, UINT32_MAX));
            total += counted[plant];
        }
        checkBudget(total, budget, stepIndex);
        checkRange(total, 4, "modules");
        table[plants] = static_cast<uint32_t>(total);
        ensureStream(out, total);

        vk::upload(ctx, out.plantStart, std::as_bytes(std::span<const uint32_t>(table)));
        submit(
            [&](VkCommandBuffer cmd) {
                vk::cmdFill(cmd, errors, 0);
                vk::memoryBarrier(cmd, Hazard::TransferToCompute);
                dispatchSequential(cmd, 1, in, out, p, 0, dispatches);
                vk::memoryBarrier(cmd, Hazard::ComputeToHost);
            },
            timer, millis);
        out.count = static_cast<uint32_t>(total);
        hostPlantTable = std::move(table);
        if (carriesParticles) gatherParticles(cur, outIndex, timer, millis);
        stats.bytesMoved += 2 * uint64_t(n) * (4 + 4ull * uint64_t(stride)) + total * (4 + 4ull * uint64_t(stride));
        if (timer) stats.stepMillis.push_back(millis);
        return outIndex;
    }
};

GpuDeriver::GpuDeriver(const vk::Context& context, const ir::Grammar& g, GpuStrategy strategy, GpuLoads loads)
    : impl_(std::make_unique<Impl>(context, std::vector<ir::Grammar>{g}, strategy, loads)) {}

GpuDeriver::GpuDeriver(const vk::Context& context, std::vector<ir::Grammar> species, GpuStrategy strategy,
                       GpuLoads loads)
    : impl_(std::make_unique<Impl>(context, std::move(species), strategy, loads)) {}

GpuStrategy GpuDeriver::strategy() const { return impl_->strategy; }

GpuLoads GpuDeriver::loads() const { return impl_->texelInputs ? GpuLoads::TexelBuffers : GpuLoads::StorageBuffers; }

GpuDeriver::~GpuDeriver() = default;

cpu::DeriveResult GpuDeriver::derive(const cpu::DeriveOptions& options, bool readBack, GpuDeriveStats* statsOut) {
    Impl& m = *impl_;
    GpuDeriveStats stats;
    stats.compileSeconds = m.compileSeconds;
    auto start = std::chrono::steady_clock::now();
    uint32_t seed = options.seed >= 0 ? uint32_t(options.seed) : m.species.front().seed;
    m.plants = std::max<uint32_t>(options.plants, 1);
    uint64_t budget = options.maxModules ? options.maxModules : cpu::defaultModuleBudget(m.stride);
    m.carriesParticles = options.particles;
    // The plant tables are sized by the plant count, which may change between derivations.
    for (Stream& s : m.streams) {
        s.plantStart = vk::Buffer(m.ctx, bytes(m.plants + 1, 4), vk::MemoryUsage::DeviceLocal);
        s.count = 0;
    }
    m.partnersStream = -1;
    m.bracketTrees = 0;
    auto speciesOf = [&](uint32_t plant) -> const ir::Grammar& {
        return m.species[ir::speciesOfPlant(plant, m.species.size())];
    };
    auto stepsOf = [&](uint32_t plant) { return options.steps >= 0 ? options.steps : speciesOf(plant).derivationLength; };
    int steps = 0;
    for (uint32_t plant = 0; plant < std::min<uint32_t>(m.plants, uint32_t(m.species.size())); ++plant)
        steps = std::max(steps, stepsOf(plant));

    // Host side: each plant's control blocks and axiom, exactly as the CPU reference evaluates them.
    std::vector<cpu::PlantState> states(m.plants);
    auto runBlock = [&](uint32_t plant, const std::vector<ir::Stmt>& block, uint32_t step, cpu::ControlBlock which) {
        cpu::Evaluator evaluator(speciesOf(plant), states[plant]);
        evaluator.key = cpu::controlBlockKey(seed, plant, step, which);
        evaluator.exec(block, nullptr);
    };
    cpu::ModuleString initial;
    initial.stride = m.stride;
    initial.plantStart.push_back(0);
    std::vector<float> values;
    for (uint32_t plant = 0; plant < m.plants; ++plant) {
        const ir::Grammar& g = speciesOf(plant);
        states[plant].reset(g);
        cpu::Evaluator evaluator(g, states[plant]);
        evaluator.key = cpu::controlBlockKey(seed, plant, 0, cpu::ControlBlock::Start);
        evaluator.exec(g.startBlock, nullptr);
        for (const ir::SuccessorModule& mod : g.axiom) {
            values.clear();
            for (const ir::Expr& e : mod.args) values.push_back(static_cast<float>(evaluator.eval(e, nullptr)));
            initial.push(mod.sym, values.data(), values.size());
        }
        initial.plantStart.push_back(initial.size());
    }
    if (initial.size() > budget)
        throw ir::LimitError(fmt::format("the axioms alone exceed the module budget of {} modules", budget));
    m.axiomsBalanced = bracketsBalanced(initial);

    int cur = 0;
    {
        Stream& s = m.streams[cur];
        m.ensureStream(s, initial.size());
        std::vector<uint32_t> words(initial.size());
        for (size_t i = 0; i < initial.size(); ++i) words[i] = initial.sym[i] | (uint32_t(initial.paramCount[i]) << 24);
        if (!words.empty()) {
            vk::upload(m.ctx, s.sym, std::as_bytes(std::span<const uint32_t>(words)));
            vk::upload(m.ctx, s.par, std::as_bytes(std::span<const float>(initial.params)));
        }
        std::vector<uint32_t> table(initial.plantStart.begin(), initial.plantStart.end());
        vk::upload(m.ctx, s.plantStart, std::as_bytes(std::span<const uint32_t>(table)));
        s.count = static_cast<uint32_t>(initial.size());
        if (options.particles) {
            std::vector<shared::ParticleState> particles;
            for (std::vector<shared::ParticleState>& plant :
                 cpu::splitAxiomParticles(m.species, m.plants, options.initialParticles))
                particles.insert(particles.end(), plant.begin(), plant.end());
            m.ensureParticles(s);
            if (!particles.empty())
                vk::upload(m.ctx, s.particles, std::as_bytes(std::span<const shared::ParticleState>(particles)));
        }
    }

    m.globals = vk::Buffer(m.ctx, bytes(uint64_t(m.plants) * std::max<uint32_t>(m.globalStride, 1), 8), vk::MemoryUsage::Upload);
    m.arrays = vk::Buffer(m.ctx, bytes(uint64_t(m.plants) * std::max<uint32_t>(m.arrayStride, 1), 8), vk::MemoryUsage::Upload);
    m.plantFrozen = vk::Buffer(m.ctx, bytes(m.plants, 4), vk::MemoryUsage::Upload);
    const bool sequential = m.strategy == GpuStrategy::Sequential;
    if (sequential) {
        m.prepareSequential();
        m.hostPlantTable.assign(initial.plantStart.begin(), initial.plantStart.end());
    }
    // The sequential kernel's productions write the state; the host reads it back after each step.
    auto downloadState = [&] {
        const double* gp = reinterpret_cast<const double*>(m.globals.mapped());
        const double* ap = reinterpret_cast<const double*>(m.arrays.mapped());
        const uint32_t* fp = reinterpret_cast<const uint32_t*>(m.plantFrozen.mapped());
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            std::vector<double>& globals = states[plant].globals;
            std::copy(gp + uint64_t(plant) * m.globalStride, gp + uint64_t(plant) * m.globalStride + globals.size(),
                      globals.begin());
            const double* at = ap + uint64_t(plant) * m.arrayStride;
            for (std::vector<double>& a : states[plant].arrays) {
                std::copy(at, at + a.size(), a.begin());
                at += a.size();
            }
            if (fp[plant] == shared::kPlantStopRequested) states[plant].stopRequested = true;
        }
    };
    // A plant freezes once it has derived its species' length, or after the step in which it called stop().
    std::vector<int> derived(m.plants, 0);
    std::vector<uint8_t> growing(m.plants, 0);
    auto uploadState = [&] {
        double* gp = reinterpret_cast<double*>(m.globals.mapped());
        double* ap = reinterpret_cast<double*>(m.arrays.mapped());
        uint32_t* fp = reinterpret_cast<uint32_t*>(m.plantFrozen.mapped());
        m.anyFrozen = false;
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            std::copy(states[plant].globals.begin(), states[plant].globals.end(), gp + uint64_t(plant) * m.globalStride);
            uint64_t at = uint64_t(plant) * m.arrayStride;
            for (const std::vector<double>& a : states[plant].arrays) {
                std::copy(a.begin(), a.end(), ap + at);
                at += a.size();
            }
            fp[plant] = growing[plant] ? shared::kPlantGrowing : shared::kPlantFrozen;
            m.anyFrozen = m.anyFrozen || !growing[plant];
        }
    };

    std::optional<vk::Timestamps> timer;
    if (m.ctx.timestampValidBits() > 0) timer.emplace(m.ctx, 2);

    for (int step = 1; step <= steps; ++step) {
        bool anyGrowing = false;
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            growing[plant] = step <= stepsOf(plant) && !states[plant].stopRequested;
            if (!growing[plant]) continue;
            anyGrowing = true;
            const ir::Grammar& g = speciesOf(plant);
            if (!g.globalNames.empty() && g.globalNames.front() == "Q") states[plant].globals[0] = step;
            runBlock(plant, g.startEachBlock, uint32_t(step), cpu::ControlBlock::StartEach);
        }
        if (!anyGrowing) break;
        uploadState();
        vk::Timestamps* stepTimer = timer ? &*timer : nullptr;
        if (sequential) {
            cur = m.stepSequential(cur, uint32_t(step), seed, budget, stepTimer, stats);
            downloadState();
        } else {
            cur = m.step(cur, uint32_t(step), seed, budget, stepTimer, stats);
        }
        stats.peakModules = std::max<uint64_t>(stats.peakModules, m.streams[cur].count);
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            if (!growing[plant]) continue;
            ++derived[plant];
            runBlock(plant, speciesOf(plant).endEachBlock, uint32_t(step), cpu::ControlBlock::EndEach);
        }
    }
    for (uint32_t plant = 0; plant < m.plants; ++plant)
        runBlock(plant, speciesOf(plant).endBlock, 0, cpu::ControlBlock::End);

    if (options.homomorphism && m.homomorphismMatch) {
        // As the CPU reference: the homomorphism sees the globals as the Start block sets them, in every plant.
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            const ir::Grammar& g = speciesOf(plant);
            states[plant].reset(g);
            cpu::Evaluator evaluator(g, states[plant]);
            evaluator.key = cpu::controlBlockKey(seed, plant, 0, cpu::ControlBlock::Start);
            evaluator.exec(g.startBlock, nullptr);
            growing[plant] = 1;
        }
        uploadState();
        cur = m.applyHomomorphism(cur, seed, budget, timer ? &*timer : nullptr, stats);
    } else if (options.homomorphism && m.homomorphismHostReason) {
        throw std::logic_error("the homomorphism cannot run on the device: " + *m.homomorphismHostReason);
    }

    cpu::DeriveResult result;
    result.steps = *std::max_element(derived.begin(), derived.end());
    Stream& final = m.streams[cur];
    m.lastStream = cur;
    stats.modules = final.count;
    stats.bracketTrees = m.bracketTrees;
    result.string.stride = m.stride;
    std::vector<uint32_t> table = vk::downloadVector<uint32_t>(m.ctx, final.plantStart, m.plants + 1);
    result.string.plantStart.assign(table.begin(), table.end());
    if (readBack && final.count > 0) {
        std::vector<uint32_t> words = vk::downloadVector<uint32_t>(m.ctx, final.sym, final.count);
        result.string.params = vk::downloadVector<float>(m.ctx, final.par, size_t(final.count) * size_t(m.stride));
        result.string.sym.resize(words.size());
        result.string.paramCount.resize(words.size());
        for (size_t i = 0; i < words.size(); ++i) {
            result.string.sym[i] = words[i] & shared::kSymbolMask;
            result.string.paramCount[i] = static_cast<uint8_t>(words[i] >> shared::kSymbolBits);
        }
        if (options.particles)
            result.string.particles = vk::downloadVector<shared::ParticleState>(m.ctx, final.particles, final.count);
        // Unused parameter slots are whatever the device left there; the CPU's are zero.
        for (size_t i = 0; i < words.size(); ++i)
            for (size_t k = result.string.paramCount[i]; k < size_t(m.stride); ++k)
                result.string.params[i * size_t(m.stride) + k] = 0.0f;
    }
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (statsOut) *statsOut = stats;
    return result;
}

bool GpuDeriver::appliesHomomorphism() const { return !impl_->homomorphismHostReason; }

DeviceModules GpuDeriver::lastString() const {
    const Impl& m = *impl_;
    if (m.lastStream < 0) throw std::logic_error("lastString() before derive()");
    const Stream& s = m.streams[m.lastStream];
    return DeviceModules{&s.sym,   &s.par, &s.plantStart, s.count, m.plants, static_cast<uint32_t>(m.stride),
                         m.carriesParticles ? &s.particles : nullptr};
}

} // namespace simeco::gpu
