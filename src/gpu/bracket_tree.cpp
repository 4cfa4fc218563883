#include "gpu/bracket_tree.h"

#include <algorithm>
#include <cstring>

#include "compute/shared/derive_layout.h"
#include "gpu/scan.h"
#include "vk/barriers.h"
#include "vk/context.h"

namespace simeco::gpu {

using shared::kMaxDepthLevels;

BracketTree::BracketTree(const vk::Context& context, GpuScan& scan)
    : context_(context),
      scan_(scan),
      bracketDepth_(vk::ComputePipeline::embedded(context, "derive/bracket_depth")),
      depthLeaves_(vk::ComputePipeline::embedded(context, "derive/depth_leaves")),
      depthLevel_(vk::ComputePipeline::embedded(context, "derive/depth_level")),
      bracketPartners_(vk::ComputePipeline::embedded(context, "derive/bracket_partners")),
      // Kernels that may match brackets bind the tree even when a pass needs none: it always exists.
      tree_(context, 4, vk::MemoryUsage::DeviceLocal),
      levelInfo_(context, 2 * kMaxDepthLevels * 4, vk::MemoryUsage::Upload),
      partners_(context, 4, vk::MemoryUsage::DeviceLocal) {}

const vk::Buffer& BracketTree::carriedPartners(std::uint32_t count) {
    std::uint64_t elements = std::max(count, 1u);
    if (!carriedPartners_ || carriedPartners_.size() < elements * 4)
        carriedPartners_ = vk::Buffer(context_, (elements + elements / 2) * 4, vk::MemoryUsage::DeviceLocal);
    return carriedPartners_;
}

void BracketTree::record(VkCommandBuffer cmd, const vk::Buffer& symbols, std::uint32_t count) {
    // Level k holds ceil(n / 2^k) minima; levelInfo gives each level's offset and size.
    std::uint32_t info[2 * kMaxDepthLevels] = {};
    std::uint64_t offset = 0;
    std::uint32_t levels = 0;
    for (std::uint32_t size = std::max(count, 1u);; size = (size + 1) / 2) {
        info[levels] = static_cast<std::uint32_t>(offset);
        info[kMaxDepthLevels + levels] = size;
        offset += size;
        ++levels;
        if (size == 1 || levels == kMaxDepthLevels) break;
    }
    std::memcpy(levelInfo_.mapped(), info, sizeof info);
    static_cast<void>(reserve(count)); // the tree writes every partner anew

    shared::DeriveHelperPush push{count, 0, 0, 0};
    bracketDepth_.dispatch(cmd, {symbols, deltas_, levelInfo_}, push, bracketDepth_.groupsFor(count));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    scan_.record(cmd, deltas_, before_, count);
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    depthLeaves_.dispatch(cmd, {deltas_, before_, tree_, levelInfo_}, push, depthLeaves_.groupsFor(count));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    for (std::uint32_t level = 1; level < levels; ++level) {
        shared::DeriveHelperPush levelPush{info[kMaxDepthLevels + level], level, 0, 0};
        depthLevel_.dispatch(cmd, {tree_, levelInfo_}, levelPush, depthLevel_.groupsFor(levelPush.count));
        vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    }
    bracketPartners_.dispatch(cmd, {symbols, tree_, levelInfo_, partners_}, push, bracketPartners_.groupsFor(count));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
}

vk::Buffer BracketTree::reserve(std::uint32_t capacity) {
    std::uint64_t elements = std::max(capacity, 1u);
    vk::Buffer replaced;
    if (!deltas_ || deltas_.size() < elements * 4) {
        deltas_ = vk::Buffer(context_, (elements + elements / 2) * 4, vk::MemoryUsage::DeviceLocal);
        before_ = vk::Buffer(context_, (elements + elements / 2) * 4, vk::MemoryUsage::DeviceLocal);
    }
    if (partners_.size() < elements * 4) {
        replaced = std::move(partners_);
        partners_ = vk::Buffer(context_, (elements + elements / 2) * 4, vk::MemoryUsage::DeviceLocal);
    }
    // Every level's minima: fewer than twice the modules, and one per level past the halvings.
    std::uint64_t nodes = 2 * elements + kMaxDepthLevels;
    // Grown with room to spare, as strings grow step after step.
    if (tree_.size() < nodes * 4) tree_ = vk::Buffer(context_, (nodes + nodes / 2) * 4, vk::MemoryUsage::DeviceLocal);
    if (scan_.capacity() < elements) scan_.reserve(static_cast<std::uint32_t>(elements));
    return replaced;
}

void BracketTree::recordCountedOnDevice(VkCommandBuffer cmd, const vk::Buffer& symbols, std::uint32_t capacity,
                                        const vk::Buffer& arguments, VkDeviceSize blockOffset) {
    using namespace shared;
    std::uint32_t levels = 1;
    for (std::uint32_t size = std::max(capacity, 1u); size > 1 && levels < kMaxDepthLevels; size = (size + 1) / 2)
        ++levels;
    const DeriveHelperPush push{kCountOnDevice, 0, 0, 0};
    bracketDepth_.dispatchIndirect(cmd, {symbols, deltas_, levelInfo_}, push, arguments,
                                   blockOffset + kArgsModules * 4);
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    scan_.recordCountedOnDevice(cmd, deltas_, before_, levelInfo_, kMaxDepthLevels, arguments,
                                blockOffset + kArgsTreeScan * 4);
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    depthLeaves_.dispatchIndirect(cmd, {deltas_, before_, tree_, levelInfo_}, push, arguments,
                                  blockOffset + kArgsModules * 4);
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    for (std::uint32_t level = 1; level < levels; ++level) {
        const DeriveHelperPush levelPush{kCountOnDevice, level, 0, 0};
        depthLevel_.dispatchIndirect(cmd, {tree_, levelInfo_}, levelPush, arguments,
                                     blockOffset + (kArgsTreeLevels + 3 * (level - 1)) * 4);
        vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    }
    bracketPartners_.dispatchIndirect(cmd, {symbols, tree_, levelInfo_, partners_}, push, arguments,
                                      blockOffset + kArgsModules * 4);
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
}

} // namespace simeco::gpu
