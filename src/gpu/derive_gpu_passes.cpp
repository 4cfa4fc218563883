// What the derivation's kernels share: their push constants and bindings, their dispatches, the submissions the
// sequential strategy waits for and the errors the kernels report, the bracket tree of a stream, and the moves of
// the particle state.
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
    p.firstPlant = firstPlant;
    p.pass = pass;
    p.stride = static_cast<uint32_t>(stride);
    p.globalCount = globalStride;
    p.arrayStride = arrayStride;
    p.oldCount = oldCount;
    p.depth = depth;
    p.lightScale = lightScale;
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

std::vector<vk::BufferRange> GpuDeriver::Impl::deriveBindings(const Stream& strings,
                                                              std::initializer_list<vk::BufferRange> rest,
                                                              bool parameterVectors) const {
    bool slot = batchSlot >= 0;
    VkDeviceSize at = slot ? VkDeviceSize(batchSlot) : 0;
    std::vector<vk::BufferRange> buffers{
        strings.sym, strings.par, plantTable(strings), brackets.tree(), brackets.levelInfo(), brackets.partners(),
        slot ? vk::BufferRange(host().batchGlobals, at * globalsSlice, globalsSlice) : vk::BufferRange(globals),
        slot ? vk::BufferRange(host().batchArrays, at * arraysSlice, arraysSlice) : vk::BufferRange(arrays),
        active->funcTables, active->speciesTable, vk::BufferRange(errors, active->errorOffset, 16),
        slot ? vk::BufferRange(host().batchFrozen, at * frozenSlice, frozenSlice) : vk::BufferRange(plantFrozen)};
    buffers.insert(buffers.end(), rest.begin(), rest.end());
    buffers.push_back(plantHints);
    if (parameterVectors)
        buffers.push_back(vk::BufferRange(strings.par).viewedAs(stride == 4 ? VK_FORMAT_R32G32B32A32_SFLOAT
                                                                             : VK_FORMAT_R32G32_SFLOAT));
    if (active->readsLight) buffers.push_back(strings.particles ? strings.particles : noParticles);
    return buffers;
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

const vk::ComputePipeline& GpuDeriver::Impl::particleScatterKernel() {
    if (!particleScatter) {
        const uint32_t choiceBits[] = {kernels.fusedScan ? kernels.choiceBits : 0u};
        particleScatter = vk::ComputePipeline::embedded(ctx, "derive/particle_scatter", choiceBits);
    }
    return *particleScatter;
}

void GpuDeriver::Impl::gatherParticles(int from, int to, vk::Timestamps* timer, double& millis) {
    ensureParticles(streams[to]);
    if (streams[to].count == 0) return;
    submit([&](VkCommandBuffer cmd) { recordParticleGather(cmd, from, to); }, timer, millis);
}

void GpuDeriver::Impl::recordParticleGather(VkCommandBuffer cmd, int from, int to) {
    const Stream& out = streams[to];
    if (out.count == 0) return;
    if (!particleGather) particleGather = vk::ComputePipeline::embedded(ctx, "derive/particle_gather");
    particleGather->dispatch(cmd, {out.origin, streams[from].particles, out.particles, plantTable(out)},
                             DeriveHelperPush{out.count, 0, 0, plants}, particleGather->groupsFor(out.count));
}

uint64_t GpuDeriver::Impl::stepBytesMoved(uint64_t n, uint64_t total) const {
    // Match writes counts, choices and draw starts, and write reads them; with a fused scan the counts and the
    // choice are one word, otherwise a separate scan reads the counts twice and writes offsets, which write reads.
    uint64_t perModule = kernels.fusedScan ? 4 + 4ull * uint64_t(stride) + 8 + 8
                                           : 4 + 4ull * uint64_t(stride) + 12 + 12 + 12;
    return n * perModule + total * (4 + 4ull * uint64_t(stride) + 8);
}

GpuDeriver::Impl::RecursivePasses GpuDeriver::Impl::decompositionPasses() const {
    return {&*decompositionMatch, &*decompositionWrite, kernels.maxDecompositionDepth};
}

} // namespace simeco::gpu
