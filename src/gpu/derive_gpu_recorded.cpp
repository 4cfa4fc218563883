// Steps recorded one after the other into one submission, with the stream sizes on the device: each step's
// sizes kernel (derive/step_sizes.comp) turns the modules of its input into the workgroup counts of its
// dispatches, so the host waits once per batch of steps instead of twice per step. On a discrete GPU each wait
// costs far more than a small step's kernels. GpuDeriver::record writes such a batch into the caller's command
// buffer instead, for a tick that interprets and draws the string in the same submission. Steps that rewrite by
// depths (decomposition, the homomorphism) are recorded in derive_gpu_depths.cpp.
#include "gpu/derive_gpu_impl.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "vk/barriers.h"

namespace simeco::gpu {

using shared::DeriveHelperPush;
using shared::DerivePush;
using shared::StepSizesPush;
using vk::Hazard;

namespace {

// Steps ahead a stream that overflowed makes room for, at the rate the overflowing step grew, and the most it
// grows by at once: a few steps keep the submissions few without holding far more memory than the string.
constexpr int kStepsAhead = 4;
constexpr double kMostGrowth = 64.0;

} // namespace

bool GpuDeriver::Impl::recordsSteps() const {
    return strategy == GpuStrategy::Parallel;
}

void GpuDeriver::Impl::reserveBatchState(uint32_t steps) {
    VkDeviceSize alignment = std::max<VkDeviceSize>(ctx.limits().minStorageBufferOffsetAlignment, 8);
    VkDeviceSize globalsBytes = vk::alignUp(bytes(uint64_t(plants) * std::max<uint32_t>(globalStride, 1), 8), alignment);
    VkDeviceSize arraysBytes = vk::alignUp(bytes(uint64_t(plants) * std::max<uint32_t>(arrayStride, 1), 8), alignment);
    VkDeviceSize frozenBytes = vk::alignUp(bytes(plants, 4), alignment);
    auto slices = [&](vk::Buffer& buffer, VkDeviceSize& slice, VkDeviceSize sliceBytes) {
        reserve(buffer, sliceBytes * steps, vk::MemoryUsage::Upload);
        slice = sliceBytes;
    };
    slices(host().batchGlobals, globalsSlice, globalsBytes);
    slices(host().batchArrays, arraysSlice, arraysBytes);
    slices(host().batchFrozen, frozenSlice, frozenBytes);
}

uint64_t GpuDeriver::Impl::recordedCapacity(const Stream& out) const {
    uint64_t room = std::min<uint64_t>({out.capacity, scratchCapacity - 1, scan.capacity()});
    if (carriesParticles) room = std::min<uint64_t>(room, out.particles.size() / kParticleBytes);
    return std::min<uint64_t>(room, std::numeric_limits<uint32_t>::max() - 1);
}

void GpuDeriver::Impl::makeRoom(int cur, uint64_t modules) {
    for (int k = 0; k < 3; ++k) {
        Stream& s = streams[k];
        if (s.capacity < modules || !s.sym) {
            mayReplace("streams"); // before the old buffers are moved out
            vk::Buffer oldSymbols = std::move(s.sym), oldParameters = std::move(s.par);
            ensureStream(s, modules);
            if (k == cur && s.count > 0) {
                // The batch reads this string: its modules move to the new buffers first thing in the submission.
                pendingCopies.push_back({oldSymbols.handle(), s.sym.handle(), {0, 0, bytes(s.count, 4)}});
                pendingCopies.push_back(
                    {oldParameters.handle(), s.par.handle(), {0, 0, bytes(s.count, 4ull * uint64_t(stride))}});
                retiredBuffers.push_back(std::move(oldSymbols));
                retiredBuffers.push_back(std::move(oldParameters));
            }
        }
        // Particle state for as many modules as the stream holds (as far as a buffer binds it), the string's
        // moved along like its modules.
        if (carriesParticles && s.particles.size() < particleCapacity(s) * kParticleBytes) {
            mayReplace("particle states");
            vk::Buffer oldParticles = std::move(s.particles);
            s.particles = vk::Buffer(ctx, particleCapacity(s) * kParticleBytes, vk::MemoryUsage::DeviceLocal);
            if (k == cur && s.count > 0 && oldParticles) {
                pendingCopies.push_back(
                    {oldParticles.handle(), s.particles.handle(), {0, 0, uint64_t(s.count) * kParticleBytes}});
                retiredBuffers.push_back(std::move(oldParticles));
            }
        }
    }
    // The scratch as large as the smallest stream (a step's output is the next step's input), as far as a buffer
    // holds it with its one word more.
    ensureScratch(std::min({streams[0].capacity, streams[1].capacity, streams[2].capacity, bufferLimit() / 4 - 1}));
    // Sized before recording: a recorded step must not replace a buffer.
    if (kernels.needsBrackets || homomorphismKernels.needsBrackets) {
        uint32_t most = uint32_t(std::max({recordedCapacity(streams[0]), recordedCapacity(streams[1]),
                                          recordedCapacity(streams[2])}));
        if (most > bracketRoom) mayReplace("bracket tree");
        bracketRoom = std::max(bracketRoom, most);
        vk::Buffer replaced = brackets.reserve(most);
        if (replaced && partnersLive && streams[cur].count > 0) { // the next step reads these partners
            VkBufferCopy live{0, 0, bytes(streams[cur].count, 4)};
            pendingCopies.push_back({replaced.handle(), brackets.partners().handle(), live});
            retiredBuffers.push_back(std::move(replaced));
        }
        if (kernels.carriesPartners) brackets.carriedPartners(most);
    }
}

void GpuDeriver::Impl::prepareRecorded(bool timed) {
    if (!stepSizes) stepSizes = vk::ComputePipeline::embedded(ctx, "derive/step_sizes");
    // The step words' blocks, and the derivation's and the homomorphism's error words.
    reserve(host().stepWordsReadback, (shared::kStepWords + 6) * 4, vk::MemoryUsage::Readback);
    if (timed && !batchTimer) batchTimer.emplace(ctx, shared::kMostRecordedSteps + 1);
    reserve(host().tableReadback, bytes(plants + 1, 4), vk::MemoryUsage::Readback);
    reserveBatchState(shared::kMostRecordedSteps);
    partnersLive = false;
}

void GpuDeriver::Impl::planBatch(stream::PlantControl& control, int& step, std::vector<RecordedStep>& batch,
                                 std::vector<uint8_t>& growing, bool& finished, bool& homomorphism) {
    batch.clear();
    const int steps = control.steps();
    for (; step <= steps && batch.size() < batchSteps(); ++step) {
        if (!control.beginFieldStep(step, growing)) {
            step = steps + 1;
            break;
        }
        VkDeviceSize slot = batch.size();
        bool frozen = writePlantState(control, growing,
                                      reinterpret_cast<double*>(host().batchGlobals.mapped() + slot * globalsSlice),
                                      reinterpret_cast<double*>(host().batchArrays.mapped() + slot * arraysSlice),
                                      reinterpret_cast<uint32_t*>(host().batchFrozen.mapped() + slot * frozenSlice));
        batch.push_back({uint32_t(step), frozen});
        control.endFieldStep(step, growing);
    }
    if (step > steps && !finished) { // every step is planned
        for (uint32_t plant = 0; plant < plants; ++plant) control.finish(plant);
        finished = true;
    }
    if (finished && homomorphism && batch.size() < batchSteps()) {
        planHomomorphism(control, batch);
        homomorphism = false;
    }
}

int GpuDeriver::Impl::deriveRecorded(stream::PlantControl& control, int cur, uint32_t seed, uint64_t budget,
                                     bool timed, bool homomorphism, GpuDeriveStats& stats) {
    prepareRecorded(timed);
    makeRoom(cur, streams[cur].count);
    std::vector<uint8_t> growing(plants, 0);
    std::vector<RecordedStep> batch;
    bool finished = false;
    for (int step = 1; !finished || homomorphism;) {
        planBatch(control, step, batch, growing, finished, homomorphism);
        int stepsAfterBatch = std::max(control.steps() - step + 1, 0);
        for (size_t done = 0; done < batch.size();)
            done = runBatch(batch, done, cur, seed, budget, timed, stepsAfterBatch, stats);
    }
    partnersStream = -1; // the partners describe the last step's input, or its string when carried
    partnersLive = false;
    return cur;
}

std::vector<vk::Buffer> GpuDeriver::Impl::endRecording() {
    std::vector<vk::Buffer> retired = std::move(retiredBuffers);
    retiredBuffers.clear();
    pendingCopies.clear();
    batchSlot = -1;
    return retired;
}

void GpuDeriver::Impl::recordPendingCopies(VkCommandBuffer cmd) const {
    for (const PendingCopy& copy : pendingCopies) {
        vk::memoryBarrier(cmd, Hazard::AnyToTransfer); // a copy may read what the one before wrote
        vkCmdCopyBuffer(cmd, copy.from, copy.to, 1, &copy.region);
    }
    vk::memoryBarrier(cmd, Hazard::TransferToCompute);
}

int GpuDeriver::Impl::recordBatch(VkCommandBuffer cmd, const std::vector<RecordedStep>& batch, size_t first, int in,
                                  uint32_t seed, uint64_t budget, vk::Timestamps* timer) {
    // After whatever the queue ran before (a derivation in flight and the passes that read its string).
    vk::memoryBarrier(cmd, Hazard::AnyToTransfer);
    if (timer) {
        timer->cmdReset(cmd);
        timer->cmdWrite(cmd, uint32_t(first), VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
    }
    reserveStepWords(batch);
    recordPendingCopies(cmd);
    vk::cmdFill(cmd, errors, 0);
    vk::cmdFill(cmd, stepWords, 0);
    vk::memoryBarrier(cmd, Hazard::TransferToCompute);
    for (size_t j = first; j < batch.size(); ++j) {
        if (batch[j].resumeDepth > 0) recordResumedDepths(cmd, batch[j], uint32_t(j), in, seed, budget);
        else if (batch[j].homomorphism) recordHomomorphism(cmd, uint32_t(j), in, seed, budget);
        else recordStep(cmd, batch[j], uint32_t(j), in, seed, budget);
        in = (in + 1) % 3;
        if (timer) timer->cmdWrite(cmd, uint32_t(j + 1));
    }
    vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
    // The words the host reads: the stop, the totals and the blocks of the batch's steps.
    const VkDeviceSize read = (shared::kStepBlocks + batch.size() * shared::kStepBlockWords) * 4;
    const VkDeviceSize errorWords = shared::kStepWords * 4;
    VkBufferCopy copies[] = {{0, 0, read},
                             {derivationTables.errorOffset, errorWords, 12},
                             {homomorphismTables.errorOffset, errorWords + 12, 12}};
    vkCmdCopyBuffer(cmd, stepWords.handle(), host().stepWordsReadback.handle(), 1, &copies[0]);
    vkCmdCopyBuffer(cmd, errors.handle(), host().stepWordsReadback.handle(), 2, &copies[1]);
    VkBufferCopy table{0, 0, bytes(plants + 1, 4)};
    // The last step's plant table, which the caller reads when no step stopped the batch.
    vkCmdCopyBuffer(cmd, streams[in].plantStart.handle(), host().tableReadback.handle(), 1, &table);
    vk::memoryBarrier(cmd, Hazard::TransferToHost);
    return in;
}

size_t GpuDeriver::Impl::completeBatch(const std::vector<RecordedStep>& batch, size_t first, int& cur,
                                       uint64_t budget, vk::Timestamps* timer, GpuDeriveStats& stats) {
    const uint32_t* words = reinterpret_cast<const uint32_t*>(host().stepWordsReadback.mapped());
    const uint32_t* errorWords = words + shared::kStepWords;
    lastFlags = errorWords[1] | errorWords[4];
    checkKernelErrors(*derivationTables.errors, errorWords[0], errorWords[1], false);
    if (homomorphismTables.errors) checkKernelErrors(*homomorphismTables.errors, errorWords[3], errorWords[4], false);
    const uint32_t stopped = words[shared::kStepStopped];
    const size_t done = stopped != 0 ? (stopped >> 2) - 1 : batch.size();
    for (size_t j = first; j < done; ++j) bracketTrees += host().treeBuilt[j] ? 1u : 0u;
    // Partners were carried through every recorded step; the stream the rest goes on from has those of step `done`.
    const auto carried = std::count_if(batch.begin() + std::ptrdiff_t(done), batch.end(),
                                       [](const RecordedStep& step) { return !step.homomorphism; });
    if (kernels.carriesPartners && axiomsBalanced && carried % 2 == 1) brackets.carried();
    for (size_t j = first; j < done; ++j) {
        uint32_t n = streams[cur].count, total = words[shared::kStepTotals + j];
        const uint32_t* block = words + shared::kStepBlocks + j * shared::kStepBlockWords;
        cur = (cur + 1) % 3;
        streams[cur].count = total;
        // The homomorphism copies its input before its depths; a step matches it (unless an earlier submission
        // did, and this one went on with its depths).
        if (batch[j].resumeDepth == 0)
            stats.bytesMoved += batch[j].homomorphism ? 2 * uint64_t(n) * (4 + 4ull * uint64_t(stride))
                                                      : stepBytesMoved(n, block[shared::kStepWritten]);
        stats.bytesMoved += depthBytesMoved(block[shared::kDepthsRead], block[shared::kDepthsWritten]);
        stats.peakModules = std::max<uint64_t>(stats.peakModules, total);
        if (timer && !batch[j].homomorphism)
            stats.stepMillis.push_back(timer->elapsedNs(uint32_t(j), uint32_t(j + 1)) / 1e6);
    }
    if (stopped == 0) tableReadFrom = cur;
    else if ((stopped & 3u) == shared::kStopBudget)
        checkBudget(words[shared::kStepTotals + done], budget, batch[done].index);
    return done;
}

size_t GpuDeriver::Impl::runBatch(std::vector<RecordedStep>& batch, size_t first, int& cur, uint32_t seed,
                                  uint64_t budget, bool timed, int stepsAfterBatch, GpuDeriveStats& stats) {
    vk::Timestamps* timer = timed ? &*batchTimer : nullptr;
    std::optional<SubmissionEnd> submission{*this};
    ctx.submitAndWait([&](VkCommandBuffer cmd) { recordBatch(cmd, batch, first, cur, seed, budget, timer); });
    submission.reset();
    const size_t done = completeBatch(batch, first, cur, budget, timer, stats);
    if (done < batch.size()) prepareToGoOn(batch, done, cur, budget, stepsAfterBatch);
    return done;
}

void GpuDeriver::Impl::prepareToGoOn(std::vector<RecordedStep>& batch, size_t done, int cur, uint64_t budget,
                                     int stepsAfterBatch) {
    const uint32_t* words = reinterpret_cast<const uint32_t*>(host().stepWordsReadback.mapped());
    if ((words[shared::kStepStopped] & 3u) == shared::kStopDepths) {
        // The step goes on from the last depth it wrote, with more depths.
        deepen(batch[done]);
        const uint32_t* block = words + shared::kStepBlocks + done * shared::kStepBlockWords;
        batch[done].resumeDepth = int(block[shared::kResultDepth]);
        return;
    }
    // The streams grow, and only the step's input keeps its string: the step runs again from its start.
    batch[done].resumeDepth = 0;
    const uint64_t total = words[shared::kStepTotals + done];
    // The step outgrew its stream: room for it and a few steps more at its rate of growth, as far as the rest of
    // the derivation goes. A step that rewrites by depths may have stopped at any depth, short of its own total.
    int stepsAhead = std::min<int>(kStepsAhead, int(batch.size() - done - 1) + stepsAfterBatch);
    if (batch[done].homomorphism || kernels.hasDecomposition) stepsAhead = std::max(stepsAhead, 1);
    double rate = double(total) / double(std::max<uint32_t>(streams[cur].count, 1));
    double growth = std::min(std::pow(std::max(rate, 1.0), stepsAhead), kMostGrowth);
    uint64_t room = std::max<uint64_t>(total, uint64_t(double(total) * growth));
    room = std::min<uint64_t>(room, std::max<uint64_t>(total, budget));
    room = std::min<uint64_t>(room, std::max<uint64_t>(total, bufferLimit() / (4ull * uint64_t(stride))));
    makeRoom(cur, room);
}

StepSizesPush GpuDeriver::Impl::sizesPush(uint32_t slot, const Stream& input, const Stream& output, uint64_t budget,
                                          bool buildsTree) const {
    StepSizesPush sizes{};
    sizes.mode = shared::kSizeStep;
    sizes.step = slot;
    sizes.plants = plants;
    sizes.tileSize = tileSize;
    sizes.chunkedMatch = kernels.chunkedMatch ? 1u : 0u;
    sizes.capacity = uint32_t(recordedCapacity(output));
    sizes.budget = uint32_t(std::min<uint64_t>(budget, std::numeric_limits<uint32_t>::max()));
    sizes.maxGroupsX = ctx.limits().maxComputeWorkGroupCount[0];
    sizes.brackets = buildsTree ? 1u : 0u;
    sizes.inputBound = uint32_t(recordedCapacity(input));
    return sizes;
}

void GpuDeriver::Impl::recordStep(VkCommandBuffer cmd, const RecordedStep& step, uint32_t slot, int in,
                                  uint32_t seed, uint64_t budget) {
    const Stream& input = streams[in];
    Stream& output = streams[(in + 1) % 3];
    batchSlot = int(slot);
    // Where each step's write carries the partners of the brackets it writes, the first step builds a tree.
    const bool carries = kernels.carriesPartners && axiomsBalanced;
    host().treeBuilt[slot] = kernels.needsBrackets && !(carries && partnersLive);
    StepSizesPush sizes = sizesPush(slot, input, output, budget, host().treeBuilt[slot]);
    stepSizes->dispatch(cmd, {plantTable(input), scan.totalBuffer(), stepWords, brackets.levelInfo()}, sizes, 1);
    vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
    if (host().treeBuilt[slot]) {
        brackets.recordCountedOnDevice(cmd, input.sym, uint32_t(recordedCapacity(input)), stepWords,
                                       blockOffset(slot, 0));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    }

    DerivePush p = push(shared::kCountOnDevice, step.index, seed, step.index * shared::kPassesPerStep,
                        shared::kCountOnDevice, 0);
    p.frozenPlants = step.anyFrozen ? 1u : 0u;
    if ((kernels.matchFindsPlants || kernels.writeFindsPlants || step.anyFrozen) && plants > 1) {
        plantHintsKernel.dispatchIndirect(cmd, {plantTable(input), plantHints},
                                          DeriveHelperPush{shared::kCountOnDevice, 0, 0, plants}, stepWords,
                                          blockOffset(slot, shared::kArgsHints));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    }
    const uint32_t countWord = uint32_t(blockOffset(slot, shared::kScanCountWord) / 4);
    if (kernels.fusedScan) {
        dispatchDeriveIndirect(cmd, stepMatch(), input, {counts, drawStarts, cutDelta, tileSums}, p,
                               blockOffset(slot, shared::kArgsMatch), kernels.matchReadsParameterVectors);
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        scan.recordCountedOnDevice(cmd, tileSums, tileOffsets, stepWords, countWord, stepWords,
                                   blockOffset(slot, shared::kArgsScan));
    } else {
        recordSeparateScan(cmd, slot, input, p);
    }
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);

    sizes.mode = shared::kSizeStepWrite;
    stepSizes->dispatch(cmd, {plantTable(input), scan.totalBuffer(), stepWords, brackets.levelInfo()}, sizes, 1);
    vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
    recordStepWrite(cmd, slot, input, output, p);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    if (kernels.hasDecomposition)
        recordDepths(cmd, slot, in, decompositionPasses(), 0, decompositionDepths, step.index, seed, budget);
    if (carries) { // the next step reads the partners this one wrote
        brackets.carried();
        partnersLive = true;
    }
}

void GpuDeriver::Impl::recordStepWrite(VkCommandBuffer cmd, uint32_t slot, const Stream& input, Stream& output,
                                       const DerivePush& p) {
    const DeriveHelperPush counted{shared::kCountOnDevice, kernels.fusedScan ? tileSize : 0u, shared::kCountOnDevice,
                                   plants};
    const VkDeviceSize writeArguments = blockOffset(slot, shared::kArgsWrite);
    if (!kernels.fusedScan) {
        dispatchDeriveIndirect(cmd, stepWrite(), input,
                               {offsets, choices, drawStarts, output.sym, output.par, output.origin, output.live}, p,
                               writeArguments, kernels.writeReadsParameterVectors);
        plantStarts.dispatchIndirect(cmd, {plantTable(input), offsets, plantTable(output), scan.totalBuffer()},
                                     counted, stepWords, blockOffset(slot, shared::kArgsPlantStarts));
    } else if (kernels.carriesPartners) {
        dispatchDeriveIndirect(cmd, stepWrite(), input,
                               {counts, tileOffsets, drawStarts, output.sym, output.par, output.origin, output.live,
                                brackets.carriedPartners(uint32_t(recordedCapacity(output)))},
                               p, writeArguments, kernels.writeReadsParameterVectors);
    } else {
        dispatchDeriveIndirect(cmd, stepWrite(), input,
                               {counts, tileOffsets, drawStarts, output.sym, output.par, output.origin, output.live},
                               p, writeArguments, kernels.writeReadsParameterVectors);
    }
    if (kernels.fusedScan)
        plantStartsTiled->dispatchIndirect(
            cmd, {plantTable(input), counts, tileOffsets, plantTable(output), scan.totalBuffer()}, counted,
            stepWords, blockOffset(slot, shared::kArgsPlantStarts));
    if (carriesParticles && !kernels.hasDecomposition) { // each module's state to its successor's modules
        const vk::Buffer& before = kernels.fusedScan ? counts : offsets;
        const vk::Buffer& offset = kernels.fusedScan ? tileOffsets : offsets;
        particleScatterKernel().dispatchIndirect(
            cmd, {before, offset, input.particles, output.particles, plantTable(input), scan.totalBuffer()}, counted,
            stepWords, writeArguments);
    }
}

void GpuDeriver::Impl::recordSeparateScan(VkCommandBuffer cmd, uint32_t slot, const Stream& input,
                                          const DerivePush& p) {
    if (kernels.mayCut) { // the match adds up each cut's reach
        vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
        vk::cmdFill(cmd, cutDelta, 0);
        vk::memoryBarrier(cmd, Hazard::TransferToCompute);
    }
    dispatchDeriveIndirect(cmd, stepMatch(), input, {counts, choices, drawStarts, cutDelta}, p,
                           blockOffset(slot, shared::kArgsMatch), kernels.matchReadsParameterVectors);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    const uint32_t countWord = uint32_t(blockOffset(slot, shared::kScanCountWord) / 4);
    const DeriveHelperPush counted{shared::kCountOnDevice, 0, 0, plants};
    if (kernels.mayCut) {
        scan.recordCountedOnDevice(cmd, cutDelta, cutBefore, stepWords, countWord, stepWords,
                                   blockOffset(slot, shared::kArgsScan));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        cutApply.dispatchIndirect(cmd, {cutDelta, cutBefore, counts, choices, plantTable(input)}, counted, stepWords,
                                  blockOffset(slot, shared::kArgsCut));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    }
    if (kernels.longestPredecessor > 1) recordGreedyWalk(cmd, slot, input);
    scan.recordCountedOnDevice(cmd, counts, offsets, stepWords, countWord, stepWords,
                               blockOffset(slot, shared::kArgsScan));
}

void GpuDeriver::Impl::recordGreedyWalk(VkCommandBuffer cmd, uint32_t slot, const Stream& in) {
    const DeriveHelperPush chunked{shared::kCountOnDevice, kernels.longestPredecessor, 0, plants};
    greedyReduce.dispatchIndirect(cmd, {choices, plantTable(in), chunkFunctions}, chunked, stepWords,
                                  blockOffset(slot, shared::kArgsChunks));
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    for (uint32_t phase = 0; phase < 3; ++phase) {
        greedyScan.dispatchIndirect(cmd, {chunkFunctions, chunkEntries, blockFunctions, blockEntries, plantTable(in)},
                                    DeriveHelperPush{shared::kCountOnDevice, phase, 0, plants}, stepWords,
                                    blockOffset(slot, phase == 1 ? shared::kArgsOne : shared::kArgsBlocks));
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    }
    greedyMark.dispatchIndirect(cmd, {choices, plantTable(in), chunkEntries, counts}, chunked, stepWords,
                                blockOffset(slot, shared::kArgsChunks));
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
}

stream::DeviceModules GpuDeriver::record(VkCommandBuffer cmd, const stream::DeriveOptions& asked, uint64_t room) {
    Impl& m = *impl_;
    stream::DeriveOptions options = asked;
    if (options.maxModules == 0) options.maxModules = m.defaultModuleBudget(options.particles);
    if (!m.recordsSteps())
        throw std::logic_error("GpuDeriver::record: the sequential strategy's steps need the host between them");
    if (options.homomorphism && m.homomorphismHostReason)
        throw std::logic_error("the homomorphism cannot run on the device: " + *m.homomorphismHostReason);
    const bool homomorphism = options.homomorphism && m.homomorphismMatch;
    if (m.recordings.size() >= size_t(kDerivationsInFlight))
        throw std::logic_error(fmt::format("GpuDeriver::record: {} recorded derivations are in flight; read the "
                                           "oldest first (recorded())",
                                           m.recordings.size()));

    // A host side of its own, while the other recording in flight reads its results from the other.
    m.hostSide = m.recordings.empty() ? 0 : (m.recordings.back().hostSide + 1) % kDerivationsInFlight;
    Impl::Recording recording;
    recording.hostSide = m.hostSide;
    recording.control = std::make_unique<stream::PlantControl>(m.species, options);
    recording.submissionsBefore = m.ctx.submissions();
    stream::PlantControl& control = *recording.control;
    recording.budget = control.budget();
    m.stepped.reset();
    m.startDerivation(control, options);
    m.prepareRecorded(false);
    m.makeRoom(0, std::max<uint64_t>(std::min(room, recording.budget), m.streams[0].count));
    std::vector<uint8_t> growing(m.plants, 0);
    int step = 1;
    bool finished = false, homomorphismLeft = homomorphism;
    m.planBatch(control, step, recording.batch, growing, finished, homomorphismLeft);
    if (!finished || homomorphismLeft)
        throw std::logic_error(fmt::format("GpuDeriver::record: at most {} steps in one recording",
                                           m.batchSteps() - (homomorphism ? 1 : 0)));
    const int last = m.recordBatch(cmd, recording.batch, 0, 0, control.seed(), recording.budget, nullptr);
    recording.retired = m.endRecording();
    m.recordings.push_back(std::move(recording));
    m.lastStream = -1; // until recorded() knows the string is there
    const Stream& s = m.streams[last];
    stream::DeviceModules modules{&s.sym,
                                  &s.par,
                                  &s.plantStart,
                                  uint32_t(m.recordedCapacity(s)),
                                  m.plants,
                                  uint32_t(m.stride),
                                  m.carriesParticles ? &s.particles : nullptr};
    modules.countOnDevice = true;
    return modules;
}

std::optional<stream::DeriveResult> GpuDeriver::recorded(GpuDeriveStats* statsOut) {
    Impl& m = *impl_;
    if (m.recordings.empty()) throw std::logic_error("GpuDeriver::recorded() without record()");
    Impl::Recording recording = std::move(m.recordings.front());
    m.recordings.pop_front();
    m.hostSide = recording.hostSide;
    GpuDeriveStats stats;
    stats.compileSeconds = m.compileSeconds;
    int cur = 0;
    m.partnersStream = -1;
    m.partnersLive = false;
    const size_t done = m.completeBatch(recording.batch, 0, cur, recording.budget, nullptr, stats);
    if (done < recording.batch.size()) { // a step outgrew the room or the depths it was recorded with
        const uint32_t* words = reinterpret_cast<const uint32_t*>(m.host().stepWordsReadback.mapped());
        if ((words[shared::kStepStopped] & 3u) == shared::kStopDepths) m.deepen(recording.batch[done]);
        return std::nullopt;
    }
    stream::PlantControl& control = *recording.control;
    stream::DeriveResult result;
    result.steps = control.mostStepsDerived();
    result.string.stride = m.stride;
    const uint32_t* table = reinterpret_cast<const uint32_t*>(m.host().tableReadback.mapped());
    result.string.plantStart.assign(table, table + m.plants + 1);
    m.lastStream = cur;
    stats.modules = m.streams[cur].count;
    stats.waits = static_cast<uint32_t>(m.ctx.submissions() - recording.submissionsBefore);
    if (statsOut) *statsOut = stats;
    return result;
}

} // namespace simeco::gpu
