// Exclusive prefix sum of uint32 device buffers: the step that turns per-module successor counts into
// write offsets. Kernels in compute/scan; algorithms and their sources described there.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

#include "compute/shared/config.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::vk {
class Context;
}

namespace simeco::gpu {

enum class ScanAlgorithm {
    // Three kernels (reduce tiles, scan tile sums recursively, rescan tiles). Never waits across workgroups,
    // so it is correct on any device; allows in-place scans.
    ReduceThenScan,
    // One kernel with decoupled look-back; reads the input once less. Its wait on earlier tiles is bounded
    // (it falls back to reducing a stalled tile itself), so it terminates even without forward-progress
    // guarantees between workgroups, as on lavapipe. Input and output must differ. The default: on lavapipe it
    // takes about a sixth less time than ReduceThenScan (tests/gpu/scan_bench.cpp).
    DecoupledLookBack,
};

std::string_view scanAlgorithmName(ScanAlgorithm algorithm);

class GpuScan {
public:
    explicit GpuScan(const vk::Context& context);

    // Sizes the scratch buffers for scans of up to `count` elements. Replaces the old scratch, so no recorded
    // scan may still be pending on the GPU when it grows.
    void reserve(std::uint32_t count);
    std::uint32_t capacity() const { return capacity_; }

    // Records output[i] = input[0] + ... + input[i-1] for i < count, and the sum of all `count` elements into
    // totalBuffer(). The caller orders the writes of `input` before this (e.g. Hazard::ComputeToCompute) and
    // its reads of `output` and the total after it. Throws std::logic_error if count > capacity().
    void record(VkCommandBuffer cmd, const vk::Buffer& input, const vk::Buffer& output, std::uint32_t count,
                ScanAlgorithm algorithm = ScanAlgorithm::DecoupledLookBack);

    // As record() with DecoupledLookBack, for a count that only the device knows when this is recorded: the scan
    // adds up the first counts[countIndex] elements (a word an earlier kernel wrote, at most capacity()),
    // dispatched with the workgroup counts at `arguments` + `argumentsOffset` (one per kScanTileSize elements, as
    // vk::ComputePipeline::dispatchIndirect takes them). The total of an empty scan is not written.
    void recordCountedOnDevice(VkCommandBuffer cmd, const vk::Buffer& input, const vk::Buffer& output,
                               const vk::Buffer& counts, std::uint32_t countIndex, const vk::Buffer& arguments,
                               VkDeviceSize argumentsOffset);

    // Polls of a stalled predecessor before DecoupledLookBack reduces its tile itself. Tests set 1 to drive the
    // fallback path, which a fast device would otherwise rarely take.
    void setLookBackSpins(std::uint32_t spins) { lookBackSpins_ = spins > 0 ? spins : 1; }

    // One uint32: the total of the most recently executed scan.
    const vk::Buffer& totalBuffer() const { return total_; }

    // Reserves, records, submits and waits; returns the total. For tests, tools and one-off work.
    std::uint32_t run(const vk::Buffer& input, const vk::Buffer& output, std::uint32_t count,
                      ScanAlgorithm algorithm = ScanAlgorithm::DecoupledLookBack);

private:
    struct Level {
        VkDeviceSize offset = 0;  // into levelSums_
        std::uint32_t tiles = 0;  // tiles of the data scanned at this level = entries of its sums
    };

    void recordLevel(VkCommandBuffer cmd, vk::BufferRange input, vk::BufferRange output, std::uint32_t count,
                     std::size_t level);
    void recordSinglePass(VkCommandBuffer cmd, const vk::Buffer& input, const vk::Buffer& output, std::uint32_t count);

    const vk::Context& context_;
    vk::ComputePipeline reduce_;
    vk::ComputePipeline downsweep_;
    vk::ComputePipeline singlePass_;
    std::uint32_t capacity_ = 0;
    std::uint32_t lookBackSpins_ = shared::kScanLookBackSpins;
    std::vector<Level> levels_;  // the reduce-then-scan hierarchy for capacity_ elements
    vk::Buffer levelSums_;       // tile sums of every level, each at an aligned offset
    vk::Buffer lookBackStatus_;  // counter + two status words per tile for DecoupledLookBack
    vk::Buffer total_;
};

} // namespace simeco::gpu
