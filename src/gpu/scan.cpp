#include "gpu/scan.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "compute/shared/config.h"
#include "vk/barriers.h"
#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::gpu {
namespace {

using shared::kScanTileSize;

std::uint32_t tilesFor(std::uint32_t count) {
    // An empty scan still runs one tile, which writes the total (zero).
    return std::max<std::uint32_t>(1, (count + kScanTileSize - 1) / kScanTileSize);
}

// Bytes bound for `count` words: never zero, since an empty range is not a valid binding.
VkDeviceSize wordBytes(std::uint32_t count) {
    return VkDeviceSize{std::max<std::uint32_t>(count, 1)} * sizeof(std::uint32_t);
}

} // namespace

std::string_view scanAlgorithmName(ScanAlgorithm algorithm) {
    switch (algorithm) {
    case ScanAlgorithm::ReduceThenScan:
        return "reduce-then-scan";
    case ScanAlgorithm::DecoupledLookBack:
        return "decoupled-look-back";
    }
    return "unknown";
}

GpuScan::GpuScan(const vk::Context& context)
    : context_(context),
      reduce_(vk::ComputePipeline::embedded(context, "scan/reduce")),
      downsweep_(vk::ComputePipeline::embedded(context, "scan/downsweep")),
      singlePass_(vk::ComputePipeline::embedded(context, "scan/single_pass")),
      total_(context, sizeof(std::uint32_t), vk::MemoryUsage::DeviceLocal) {
    // The tile shape in compute/shared/config.h and the kernels' local size must agree; both come from the same header,
    // so this only fails if a kernel stops using it.
    for (const vk::ComputePipeline* pipeline : {&reduce_, &downsweep_, &singlePass_}) {
        if (pipeline->reflection().localSize[0] != shared::kScanWorkgroupSize) {
            throw vk::DispatchMismatch(fmt::format("kernel {} has local size {}, config.h says {}", pipeline->name(),
                                                   pipeline->reflection().localSize[0], shared::kScanWorkgroupSize));
        }
    }
}

void GpuScan::reserve(std::uint32_t count) {
    if (count <= capacity_ && levelSums_) {
        return;
    }
    VkDeviceSize alignment = std::max<VkDeviceSize>(context_.limits().minStorageBufferOffsetAlignment, 4);
    std::vector<Level> levels;
    VkDeviceSize bytes = 0;
    for (std::uint32_t n = count; tilesFor(n) > 1; n = tilesFor(n)) {
        levels.push_back({bytes, tilesFor(n)});
        bytes = vk::alignUp(bytes + wordBytes(tilesFor(n)), alignment);
    }
    levelSums_ = vk::Buffer(context_, std::max<VkDeviceSize>(bytes, 4), vk::MemoryUsage::DeviceLocal);
    lookBackStatus_ = vk::Buffer(context_, wordBytes(1 + 2 * tilesFor(count)), vk::MemoryUsage::DeviceLocal);
    levels_ = std::move(levels);
    capacity_ = count;
}

void GpuScan::record(VkCommandBuffer cmd, const vk::Buffer& input, const vk::Buffer& output, std::uint32_t count,
                     ScanAlgorithm algorithm) {
    if (count > capacity_ || !levelSums_) {
        throw std::logic_error(fmt::format("GpuScan: scan of {} elements recorded after reserve({})", count, capacity_));
    }
    VkDeviceSize bytes = wordBytes(count);
    if (input.size() < bytes || output.size() < bytes) {
        throw std::invalid_argument(fmt::format("GpuScan: {} elements do not fit the input ({} bytes) or output ({} bytes)",
                                                count, input.size(), output.size()));
    }
    if (bytes > context_.limits().maxStorageBufferRange) {
        throw vk::VulkanError(fmt::format("a scan of {} elements exceeds the device's largest storage buffer binding "
                                          "({} bytes)",
                                          count, context_.limits().maxStorageBufferRange),
                              VK_ERROR_FEATURE_NOT_PRESENT);
    }
    if (algorithm == ScanAlgorithm::DecoupledLookBack && input.handle() == output.handle()) {
        throw std::invalid_argument("GpuScan: the decoupled look-back scan cannot run in place");
    }
    // Scratch may still be in use by a scan recorded just before this one.
    vk::bufferBarrier(cmd, levelSums_, vk::Hazard::ComputeToCompute);
    vk::bufferBarrier(cmd, total_, vk::Hazard::ComputeToCompute);
    if (algorithm == ScanAlgorithm::DecoupledLookBack) {
        recordSinglePass(cmd, input, output, count);
    } else {
        recordLevel(cmd, vk::BufferRange(input, 0, bytes), vk::BufferRange(output, 0, bytes), count, 0);
    }
}

void GpuScan::recordLevel(VkCommandBuffer cmd, vk::BufferRange input, vk::BufferRange output, std::uint32_t count,
                          std::size_t level) {
    std::uint32_t tiles = tilesFor(count);
    if (tiles == 1) {
        // The top of the hierarchy: one workgroup scans everything and knows the total. The offsets binding is
        // unused here (hasTileOffsets = 0) but must still name a buffer.
        shared::ScanDownsweepPush push{count, 1, 0, 1};
        downsweep_.dispatch(cmd, {input, output, total_, total_}, push, 1);
        return;
    }
    vk::BufferRange sums(levelSums_, levels_.at(level).offset, wordBytes(tiles));
    reduce_.dispatch(cmd, {input, sums}, shared::ScanReducePush{count, tiles}, tiles);
    vk::bufferBarrier(cmd, levelSums_, vk::Hazard::ComputeToCompute);
    recordLevel(cmd, sums, sums, tiles, level + 1);  // in place: tile sums become tile offsets
    vk::bufferBarrier(cmd, levelSums_, vk::Hazard::ComputeToCompute);
    shared::ScanDownsweepPush push{count, tiles, 1, 0};
    downsweep_.dispatch(cmd, {input, output, sums, total_}, push, tiles);
}

void GpuScan::recordSinglePass(VkCommandBuffer cmd, const vk::Buffer& input, const vk::Buffer& output,
                               std::uint32_t count) {
    std::uint32_t tiles = tilesFor(count);
    VkDeviceSize bytes = wordBytes(count);
    vk::bufferBarrier(cmd, lookBackStatus_, vk::Hazard::ComputeToTransfer);
    vk::cmdFill(cmd, lookBackStatus_, 0);  // tile counter and every tile's state back to "not ready"
    vk::bufferBarrier(cmd, lookBackStatus_, vk::Hazard::TransferToCompute);
    shared::ScanSinglePassPush push{count, tiles, 1, lookBackSpins_};
    singlePass_.dispatch(cmd, {vk::BufferRange(input, 0, bytes), vk::BufferRange(output, 0, bytes), lookBackStatus_,
                               total_, total_}, // the count binding is unread with a count in the push constants
                         push, tiles);
}

void GpuScan::recordCountedOnDevice(VkCommandBuffer cmd, const vk::Buffer& input, const vk::Buffer& output,
                                    const vk::Buffer& counts, std::uint32_t countIndex, const vk::Buffer& arguments,
                                    VkDeviceSize argumentsOffset) {
    if (!levelSums_) throw std::logic_error("GpuScan: scan recorded before reserve()");
    if (input.handle() == output.handle())
        throw std::invalid_argument("GpuScan: the decoupled look-back scan cannot run in place");
    vk::bufferBarrier(cmd, total_, vk::Hazard::ComputeToCompute);
    vk::bufferBarrier(cmd, lookBackStatus_, vk::Hazard::ComputeToTransfer);
    vk::cmdFill(cmd, lookBackStatus_, 0);  // room for the tiles of capacity() elements
    vk::bufferBarrier(cmd, lookBackStatus_, vk::Hazard::TransferToCompute);
    shared::ScanSinglePassPush push{shared::kCountOnDevice, countIndex, 1, lookBackSpins_};
    singlePass_.dispatchIndirect(cmd, {input, output, lookBackStatus_, total_, counts}, push, arguments,
                                 argumentsOffset);
}

std::uint32_t GpuScan::run(const vk::Buffer& input, const vk::Buffer& output, std::uint32_t count,
                           ScanAlgorithm algorithm) {
    reserve(count);
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        vk::memoryBarrier(cmd, vk::Hazard::TransferToCompute);
        record(cmd, input, output, count, algorithm);
    });
    return vk::downloadVector<std::uint32_t>(context_, total_, 1).at(0);
}

} // namespace simeco::gpu
