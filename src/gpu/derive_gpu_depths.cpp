// Recorded steps that rewrite by depths: a step's decomposition, and the homomorphism, which a batch records as a
// step of its own after the derivation's. Each depth is sized on the device like a step (derive/step_sizes.comp):
// the scan of its live modules tells whether any is left to rewrite, and once none is, every later depth of the
// step gets no workgroups. The depths write two streams in turn; where the last one wrote the other, the result
// is copied into the stream the step writes, so that a batch's streams follow each other as they do without
// depths. A step records a few depths at first and more once one of its plants needs them (kStopDepths).
#include "gpu/derive_gpu_impl.h"

#include <algorithm>

#include "stream/random_passes.h"
#include "vk/barriers.h"

namespace simeco::gpu {

using shared::DeriveHelperPush;
using shared::DerivePush;
using shared::StepSizesPush;
using shared::StreamCopyPush;
using vk::Hazard;

uint32_t GpuDeriver::Impl::depthBlocksPerStep() const {
    return kernels.hasDecomposition ? uint32_t(decompositionDepths) + 1 : 0;
}

size_t GpuDeriver::Impl::batchSteps() const {
    const uint32_t blocks = std::max<uint32_t>(depthBlocksPerStep(), 1);
    return std::clamp<size_t>(kMostDepthBlocks / blocks, 1, shared::kMostRecordedSteps);
}

uint32_t GpuDeriver::Impl::depthBlock(uint32_t slot, int depth) const {
    return shared::kStepWords + (slot * depthBlocksPerStep() + uint32_t(depth)) * shared::kDepthBlockWords;
}

void GpuDeriver::Impl::reserveStepWords(const std::vector<RecordedStep>& batch) {
    // The homomorphism is the batch's last step; its depths follow the steps'.
    const bool homomorphism = !batch.empty() && batch.back().homomorphism;
    const uint64_t blocks = (batch.size() - (homomorphism ? 1 : 0)) * depthBlocksPerStep() +
                            (homomorphism ? uint64_t(homomorphismDepths) + 1 : 0);
    const VkDeviceSize size = (shared::kStepWords + blocks * shared::kDepthBlockWords) * 4;
    if (stepWords && stepWords.size() >= size) return;
    mayReplace("step words");
    stepWords = vk::Buffer(ctx, size, vk::MemoryUsage::DeviceLocal, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
}

void GpuDeriver::Impl::deepen(const RecordedStep& step) {
    int& depths = step.homomorphism ? homomorphismDepths : decompositionDepths;
    const int deepest = step.homomorphism ? homomorphismKernels.maxDecompositionDepth : kernels.maxDecompositionDepth;
    depths = std::min(deepest, depths * 4);
}

void GpuDeriver::Impl::planHomomorphism(stream::PlantControl& control, std::vector<RecordedStep>& batch) {
    for (uint32_t plant = 0; plant < plants; ++plant) control.start(plant, nullptr);
    const std::vector<uint8_t> growing(plants, 1);
    const VkDeviceSize slot = batch.size();
    writePlantState(control, growing, reinterpret_cast<double*>(host().batchGlobals.mapped() + slot * globalsSlice),
                    reinterpret_cast<double*>(host().batchArrays.mapped() + slot * arraysSlice),
                    reinterpret_cast<uint32_t*>(host().batchFrozen.mapped() + slot * frozenSlice));
    batch.push_back({0, false, true});
}

int GpuDeriver::Impl::applyHomomorphism(stream::PlantControl& control, int cur, uint32_t seed, uint64_t budget,
                                        bool timed, GpuDeriveStats& stats) {
    prepareRecorded(timed);
    makeRoom(cur, streams[cur].count);
    std::vector<RecordedStep> batch;
    planHomomorphism(control, batch);
    for (size_t done = 0; done < batch.size();) done = runBatch(batch, done, cur, seed, budget, timed, 0, stats);
    partnersStream = -1;
    return cur;
}

void GpuDeriver::Impl::recordStreamCopy(VkCommandBuffer cmd, uint32_t mode, const Stream& from, Stream& to,
                                        VkDeviceSize argumentsOffset) {
    const StreamCopyPush copy{mode, uint32_t(std::min(recordedCapacity(from), recordedCapacity(to))), plants,
                              uint32_t(stride)};
    streamCopy.dispatchIndirect(cmd,
                                {from.sym, from.par, plantTable(from), from.origin, to.sym, to.par, plantTable(to),
                                 to.origin, to.live},
                                copy, stepWords, argumentsOffset);
}

void GpuDeriver::Impl::recordHomomorphism(VkCommandBuffer cmd, uint32_t slot, int in, uint32_t seed,
                                          uint64_t budget) {
    const Stream& input = streams[in];
    Stream& output = streams[(in + 1) % 3];
    batchSlot = int(slot);
    host().treeBuilt[slot] = homomorphismKernels.needsBrackets;
    StepSizesPush sizes = sizesPush(slot, input, output, budget, host().treeBuilt[slot]);
    const std::initializer_list<vk::BufferRange> sizeBindings{plantTable(input), scan.totalBuffer(), stepWords,
                                                              brackets.levelInfo()};
    stepSizes->dispatch(cmd, sizeBindings, sizes, 1);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    sizes.mode = shared::kSizeCopy;
    stepSizes->dispatch(cmd, sizeBindings, sizes, 1);
    vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
    if (host().treeBuilt[slot]) {
        brackets.recordCountedOnDevice(cmd, input.sym, uint32_t(recordedCapacity(input)), stepWords,
                                       blockOffset(slot, 0));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    }
    recordStreamCopy(cmd, shared::kCopyHomomorphism, input, output, blockOffset(slot, shared::kArgsCopy));
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    recordHomomorphismDepths(cmd, slot, in, 0, seed, budget);
}

void GpuDeriver::Impl::recordHomomorphismDepths(VkCommandBuffer cmd, uint32_t slot, int in, int firstDepth,
                                                uint32_t seed, uint64_t budget) {
    // The homomorphism's kernels read their own tables and report their errors apart.
    active = &homomorphismTables;
    struct Restore {
        Impl& impl;
        ~Restore() { impl.active = &impl.derivationTables; }
    } restore{*this};
    const RecursivePasses passes{&*homomorphismMatch, &*homomorphismWrite, homomorphismKernels.maxDecompositionDepth};
    recordDepths(cmd, slot, in, passes, firstDepth, homomorphismDepths, 0, seed, budget);
}

void GpuDeriver::Impl::recordResumedDepths(VkCommandBuffer cmd, const RecordedStep& step, uint32_t slot, int in,
                                           uint32_t seed, uint64_t budget) {
    batchSlot = int(slot);
    host().treeBuilt[slot] = false; // the bracket tree of its input is still the one its first submission built
    // The string the last depth wrote: the next stream after an even depth, the one after it after an odd one.
    const Stream& last = streams[(in + 1 + step.resumeDepth % 2) % 3];
    StepSizesPush sizes = sizesPush(slot, last, last, budget, false);
    sizes.mode = shared::kSizeResume;
    sizes.depth = uint32_t(step.resumeDepth);
    stepSizes->dispatch(cmd, {plantTable(last), scan.totalBuffer(), stepWords, brackets.levelInfo()}, sizes, 1);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    if (step.homomorphism)
        recordHomomorphismDepths(cmd, slot, in, step.resumeDepth, seed, budget);
    else
        recordDepths(cmd, slot, in, decompositionPasses(), step.resumeDepth, decompositionDepths, step.index, seed,
                     budget);
}

void GpuDeriver::Impl::recordDepths(VkCommandBuffer cmd, uint32_t slot, int old, const RecursivePasses& passes,
                                    int firstDepth, int depths, uint32_t stepIndex, uint32_t seed, uint64_t budget) {
    const Stream& oldStream = streams[old];
    Stream& first = streams[(old + 1) % 3];
    Stream& second = streams[(old + 2) % 3];
    const int end = std::min(firstDepth + depths, passes.maxDepth);
    const bool probes = end < passes.maxDepth;
    for (int depth = firstDepth; depth < end + (probes ? 1 : 0); ++depth) {
        Stream& X = depth % 2 == 0 ? first : second;
        Stream& Y = depth % 2 == 0 ? second : first;
        const uint32_t block = depthBlock(slot, depth - firstDepth);
        StepSizesPush sizes = sizesPush(slot, X, Y, budget, false);
        sizes.depthBlock = block;
        sizes.depth = uint32_t(depth);
        sizes.lastDepth = depth == end ? 1u : 0u;
        const std::initializer_list<vk::BufferRange> sizeBindings{plantTable(X), scan.totalBuffer(), stepWords,
                                                                  brackets.levelInfo()};
        sizes.mode = shared::kSizeDepth;
        stepSizes->dispatch(cmd, sizeBindings, sizes, 1);
        vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
        const DeriveHelperPush counted{shared::kCountOnDevice, 0, shared::kCountOnDevice, plants};
        if (depth < end)
            plantHintsKernel.dispatchIndirect(cmd, {plantTable(X), plantHints}, counted, stepWords,
                                              VkDeviceSize(block + shared::kDepthArgsHints) * 4);
        scan.recordCountedOnDevice(cmd, X.live, examined, stepWords, block + shared::kDepthModules, stepWords,
                                   VkDeviceSize(block + shared::kDepthArgsScan) * 4);
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        sizes.mode = shared::kSizeDepthMatch;
        stepSizes->dispatch(cmd, sizeBindings, sizes, 1);
        vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
        if (depth == end) break; // the probe: whether modules are left past the depths recorded

        DerivePush p = push(shared::kCountOnDevice, stepIndex, seed, stream::decompositionPass(stepIndex, depth),
                            shared::kCountOnDevice, uint32_t(depth));
        dispatchDeriveIndirect(cmd, *passes.match, oldStream,
                               {X.sym, X.par, plantTable(X), X.live, X.origin, examined, counts, choices, drawStarts},
                               p, VkDeviceSize(block + shared::kDepthArgsMatch) * 4, false);
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        scan.recordCountedOnDevice(cmd, counts, offsets, stepWords, block + shared::kDepthModules, stepWords,
                                   VkDeviceSize(block + shared::kDepthArgsScan) * 4);
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        sizes.mode = shared::kSizeDepthWrite;
        stepSizes->dispatch(cmd, sizeBindings, sizes, 1);
        vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
        dispatchDeriveIndirect(cmd, *passes.write, oldStream,
                               {X.sym, X.par, plantTable(X), X.live, X.origin, examined, offsets, choices, drawStarts,
                                Y.sym, Y.par, Y.origin, Y.live},
                               p, VkDeviceSize(block + shared::kDepthArgsWrite) * 4, false);
        plantStarts.dispatchIndirect(cmd, {plantTable(X), offsets, plantTable(Y), scan.totalBuffer()}, counted,
                                     stepWords, VkDeviceSize(block + shared::kDepthArgsPlantStarts) * 4);
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    }

    StepSizesPush sizes = sizesPush(slot, first, first, budget, false);
    sizes.mode = shared::kSizeDepthsEnd;
    stepSizes->dispatch(cmd, {plantTable(first), scan.totalBuffer(), stepWords, brackets.levelInfo()}, sizes, 1);
    vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
    recordStreamCopy(cmd, shared::kCopySettle, second, first, blockOffset(slot, shared::kArgsSettle));
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    if (carriesParticles) { // each module takes the state of the module it descends from
        if (!particleGather) particleGather = vk::ComputePipeline::embedded(ctx, "derive/particle_gather");
        particleGather->dispatchIndirect(cmd, {first.origin, oldStream.particles, first.particles, plantTable(first)},
                                         DeriveHelperPush{shared::kCountOnDevice, 0, 0, plants}, stepWords,
                                         blockOffset(slot, shared::kArgsGather));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    }
}

} // namespace simeco::gpu
