// The parallel strategy's passes, each waited for: each step's match, scan and write over all plants and its
// decomposition depth by depth, where the steps are not recorded (derive_gpu_recorded.cpp), and the moves of the
// particle state.
#include "gpu/derive_gpu_impl.h"

#include <cstring>
#include <span>

#include <fmt/format.h>

#include "stream/random_passes.h"
#include "vk/barriers.h"

namespace simeco::gpu {

using shared::DeriveHelperPush;
using shared::DerivePush;
using vk::Hazard;

ir::LimitError loopsCutError(const std::string& what) {
    return ir::LimitError(fmt::format("{}: the device's driver ended a shader loop early (lavapipe ends an "
                                      "invocation's loops after 65535 iterations in all); derive this grammar with "
                                      "--backend cpu",
                                      what));
}

DerivePush GpuDeriver::Impl::push(uint32_t count, uint32_t step, uint32_t seed, uint32_t pass, uint32_t oldCount,
                                  uint32_t depth) const {
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

uint32_t GpuDeriver::Impl::submit(const std::function<void(VkCommandBuffer)>& record, vk::Timestamps* timer,
                                  double& gpuMillis, bool retriesCutLoops) {
    std::optional<SubmissionEnd> submission{*this};
    ctx.submitAndWait([&](VkCommandBuffer cmd) {
        if (timer) {
            timer->cmdReset(cmd);
            timer->cmdWrite(cmd, 0, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
        }
        recordPendingCopies(cmd);
        record(cmd);
        vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
        VkBufferCopy error{0, 4, 12}; // the error site, the flags, the sequential kernel's unfinished plants
        vkCmdCopyBuffer(cmd, errors.handle(), readback.handle(), 1, &error);
        vk::memoryBarrier(cmd, Hazard::TransferToHost);
        if (timer) timer->cmdWrite(cmd, 1, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
    });
    submission.reset();
    if (timer) gpuMillis += timer->elapsedNs(0, 1) / 1e6;
    uint32_t words[4];
    std::memcpy(words, readback.mapped(), sizeof words);
    lastFlags = words[2];
    lastUnfinished = words[3] != 0;
    checkKernelErrors(*active->errors, words[1], words[2], retriesCutLoops);
    return words[0];
}

void GpuDeriver::Impl::checkKernelErrors(const std::vector<codegen::ErrorSite>& sites, uint32_t site, uint32_t flags,
                                         bool retriesCutLoops) {
    if (site != 0) {
        if (site - 1 < sites.size()) throw ir::InputError(sites[site - 1].loc, sites[site - 1].message);
        throw std::runtime_error("a derivation kernel reported an unknown error");
    }
    if ((flags & shared::kFlagLoopCut) && !retriesCutLoops)
        throw loopsCutError("a production loops long or a context walk passes very many modules");
}

void GpuDeriver::Impl::checkBudget(uint64_t total, uint64_t budget, uint32_t stepIndex) {
    if (total > budget) throw stream::moduleBudgetExceeded(budget, int(stepIndex));
}

void GpuDeriver::Impl::copyTotal(VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
    VkBufferCopy total{0, 0, 4};
    vkCmdCopyBuffer(cmd, scan.totalBuffer().handle(), readback.handle(), 1, &total);
}

void GpuDeriver::Impl::recordGreedyWalk(VkCommandBuffer cmd, const Stream& in) {
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

std::vector<vk::BufferRange> GpuDeriver::Impl::deriveBindings(const Stream& strings,
                                                              std::initializer_list<vk::BufferRange> rest,
                                                              bool parameterVectors) const {
    bool slot = batchSlot >= 0;
    VkDeviceSize at = slot ? VkDeviceSize(batchSlot) : 0;
    std::vector<vk::BufferRange> buffers{
        strings.sym, strings.par, plantTable(strings), brackets.tree(), brackets.levelInfo(), brackets.partners(),
        slot ? vk::BufferRange(batchGlobals, at * globalsSlice, globalsSlice) : vk::BufferRange(globals),
        slot ? vk::BufferRange(batchArrays, at * arraysSlice, arraysSlice) : vk::BufferRange(arrays),
        active->funcTables, active->speciesTable, vk::BufferRange(errors, active->errorOffset, 16),
        slot ? vk::BufferRange(batchFrozen, at * frozenSlice, frozenSlice) : vk::BufferRange(plantFrozen)};
    buffers.insert(buffers.end(), rest.begin(), rest.end());
    buffers.push_back(plantHints);
    if (parameterVectors)
        buffers.push_back(vk::BufferRange(strings.par).viewedAs(stride == 4 ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                                             : VK_FORMAT_R32G32_SFLOAT));
    return buffers;
}

void GpuDeriver::Impl::dispatchDerive(VkCommandBuffer cmd, const vk::ComputePipeline& kernel, const Stream& strings,
                                      std::initializer_list<vk::BufferRange> rest, const DerivePush& p, uint32_t n,
                                      bool parameterVectors) {
    kernel.dispatchBytes(cmd, deriveBindings(strings, rest, parameterVectors), std::as_bytes(std::span(&p, 1)),
                         kernel.groupsFor(n));
}

void GpuDeriver::Impl::dispatchDeriveIndirect(VkCommandBuffer cmd, const vk::ComputePipeline& kernel,
                                              const Stream& strings, std::initializer_list<vk::BufferRange> rest,
                                              const DerivePush& p, VkDeviceSize argumentsOffset,
                                              bool parameterVectors) {
    kernel.dispatchIndirectBytes(cmd, deriveBindings(strings, rest, parameterVectors),
                                 std::as_bytes(std::span(&p, 1)), stepWords, argumentsOffset);
}

void GpuDeriver::Impl::recordBrackets(VkCommandBuffer cmd, int index) {
    const Stream& s = streams[index];
    if (s.count == 0 || partnersStream == index) return;
    brackets.record(cmd, s.sym, s.count);
    partnersStream = index;
    ++bracketTrees;
}

void GpuDeriver::Impl::overwriting(int index) {
    if (partnersStream == index) partnersStream = -1;
}

void GpuDeriver::Impl::recordPlantStarts(VkCommandBuffer cmd, const Stream& from, const Stream& to, uint32_t n,
                                         uint32_t total) {
    DeriveHelperPush hp{n, 0, total, plants};
    plantStarts.dispatch(cmd, {plantTable(from), offsets, plantTable(to), scan.totalBuffer()}, hp,
                         plantStarts.groupsFor(plants + 1));
}

void GpuDeriver::Impl::scatterParticles(int from, int to, vk::Timestamps* timer, double& millis) {
    Stream& in = streams[from];
    Stream& out = streams[to];
    ensureParticles(out);
    if (in.count == 0 || out.count == 0) return;
    DeriveHelperPush hp{in.count, kernels.fusedScan ? tileSize : 0u, out.count, plants};
    const vk::ComputePipeline& scatter = particleScatterKernel();
    submit(
        [&](VkCommandBuffer cmd) {
            scatter.dispatch(cmd,
                             {kernels.fusedScan ? counts : offsets, kernels.fusedScan ? tileOffsets : offsets,
                              in.particles, out.particles, plantTable(in), scan.totalBuffer()},
                             hp, scatter.groupsFor(in.count));
        },
        timer, millis);
}

const vk::ComputePipeline& GpuDeriver::Impl::particleScatterKernel() {
    if (!particleScatter) {
        const uint32_t choiceBits[] = {kernels.fusedScan ? kernels.choiceBits : 0u};
        particleScatter = vk::ComputePipeline::embedded(ctx, "derive/particle_scatter", choiceBits);
    }
    return *particleScatter;
}

void GpuDeriver::Impl::gatherParticles(int from, int to, vk::Timestamps* timer, double& millis) {
    Stream& out = streams[to];
    ensureParticles(out);
    if (out.count == 0) return;
    if (!particleGather) particleGather = vk::ComputePipeline::embedded(ctx, "derive/particle_gather");
    DeriveHelperPush hp{out.count, 0, 0, plants};
    submit(
        [&](VkCommandBuffer cmd) {
            particleGather->dispatch(cmd, {out.origin, streams[from].particles, out.particles, plantTable(out)}, hp,
                                     particleGather->groupsFor(out.count));
        },
        timer, millis);
}

void GpuDeriver::Impl::recordPlantHints(VkCommandBuffer cmd, const Stream& s) {
    DeriveHelperPush hp{s.count, 0, 0, plants};
    plantHintsKernel.dispatch(cmd, {plantTable(s), plantHints}, hp,
                              plantHintsKernel.groupsFor(shared::plantHintBlocks(s.count) + 1));
}

uint64_t GpuDeriver::Impl::stepBytesMoved(uint64_t n, uint64_t total) const {
    // Match writes counts, choices and draw starts, and write reads them; with a fused scan the counts and the
    // choice are one word, otherwise a separate scan reads the counts twice and writes offsets, which write reads.
    uint64_t perModule = kernels.fusedScan ? 4 + 4ull * uint64_t(stride) + 8 + 8
                                           : 4 + 4ull * uint64_t(stride) + 12 + 12 + 12;
    return n * perModule + total * (4 + 4ull * uint64_t(stride) + 8);
}

int GpuDeriver::Impl::step(int cur, uint32_t stepIndex, uint32_t seed, uint64_t budget, vk::Timestamps* timer,
                           GpuDeriveStats& stats) {
    Stream& in = streams[cur];
    int outIndex = (cur + 1) % 3;
    Stream& out = streams[outIndex];
    uint32_t n = in.count;
    double millis = 0;
    ensureScratch(n);
    matchScanWrite(cur, outIndex, stepIndex, seed, budget, timer, millis);
    if (carriesParticles && !kernels.hasDecomposition) scatterParticles(cur, outIndex, timer, millis);
    stats.bytesMoved += stepBytesMoved(n, out.count);
    if (kernels.hasDecomposition) {
        outIndex = decompose(cur, outIndex, stepIndex, seed, budget, timer, millis, stats, decompositionPasses());
        if (carriesParticles) gatherParticles(cur, outIndex, timer, millis);
    }
    if (timer) stats.stepMillis.push_back(millis);
    return outIndex;
}

void GpuDeriver::Impl::matchScanWrite(int cur, int outIndex, uint32_t stepIndex, uint32_t seed, uint64_t budget,
                                      vk::Timestamps* timer, double& millis) {
    const Stream& in = streams[cur];
    Stream& out = streams[outIndex];
    overwriting(outIndex);
    uint32_t n = in.count;
    bool fused = kernels.fusedScan;
    DerivePush p = push(n, stepIndex, seed, stepIndex * shared::kPassesPerStep, n, 0);
    p.frozenPlants = anyFrozen ? 1u : 0u;
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
                // A match by chunks runs an invocation per tile.
                dispatchDerive(cmd, matcher, in, {counts, drawStarts, cutDelta, tileSums}, p,
                               kernels.chunkedMatch ? static_cast<uint32_t>(tilesFor(n)) : n,
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
                plantStartsTiled->dispatch(cmd,
                                           {plantTable(in), counts, tileOffsets, plantTable(out), scan.totalBuffer()},
                                           hp, plantStartsTiled->groupsFor(plants + 1));
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

GpuDeriver::Impl::RecursivePasses GpuDeriver::Impl::decompositionPasses() const {
    return {&*decompositionMatch, &*decompositionWrite, kernels.maxDecompositionDepth};
}

int GpuDeriver::Impl::decompose(int old, int x, uint32_t stepIndex, uint32_t seed, uint64_t budget,
                                vk::Timestamps* timer, double& millis, GpuDeriveStats& stats,
                                const RecursivePasses& passes) {
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
        uint32_t pass = stream::decompositionPass(stepIndex, depth);
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
        stats.bytesMoved += depthBytesMoved(n, total);
        std::swap(x, y);
    }
    return x;
}

} // namespace simeco::gpu
