// The sequential strategy: one invocation per plant rewrites its string in order, for grammars whose productions
// depend on the order of application.
#include "gpu/derive_gpu_impl.h"

#include <algorithm>
#include <span>

#include <fmt/format.h>

#include "vk/barriers.h"

namespace simeco::gpu {

using shared::DerivePush;
using vk::Hazard;

uint32_t GpuDeriver::Impl::deepestStack() const {
    return kernels.hasDecomposition ? static_cast<uint32_t>(kernels.maxDecompositionDepth) + 1 : 1;
}

void GpuDeriver::Impl::ensureStack(uint32_t levels) {
    uint64_t modules = uint64_t(plants) * levels * kernels.stackWidth;
    checkRange(modules, 4ull * uint64_t(stride), "decomposition stack (derive fewer plants at once)");
    checkRange(uint64_t(plants) * 3 * levels, 4, "decomposition stack state");
    stackSym = vk::Buffer(ctx, bytes(modules, 4), vk::MemoryUsage::DeviceLocal);
    stackPar = vk::Buffer(ctx, bytes(modules, 4ull * uint64_t(stride)), vk::MemoryUsage::DeviceLocal);
    stackState = vk::Buffer(ctx, bytes(uint64_t(plants) * 3 * levels, 4), vk::MemoryUsage::DeviceLocal);
    stackLevels = levels;
}

void GpuDeriver::Impl::prepareSequential() {
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

void GpuDeriver::Impl::dispatchSequential(VkCommandBuffer cmd, uint32_t mode, const Stream& in, const Stream& out,
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
                                         derivationTables.funcTables, derivationTables.speciesTable, errors,
                                         plantFrozen,
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

int GpuDeriver::Impl::stepSequential(int cur, uint32_t stepIndex, uint32_t seed, uint64_t budget, vk::Timestamps* timer,
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

} // namespace simeco::gpu
