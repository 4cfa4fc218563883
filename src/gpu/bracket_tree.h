// The bracket-depth min tree of a module stream on the device: the inclusive bracket depth of every module and
// the minima of ever larger blocks above it, which kernels match brackets with in O(log n)
// (compute/derive/depth_tree.glsl); and every bracket's partner found on it, for kernels that jump over
// branches often (compute/derive/bracket_partners.comp).
#pragma once

#include <cstdint>
#include <utility>

#include <vulkan/vulkan.h>

#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::vk {
class Context;
}

namespace simeco::gpu {

class GpuScan;

class BracketTree {
public:
    BracketTree(const vk::Context& context, GpuScan& scan);

    // Records building the tree over the first `count` symbols (uint: symbol | parameter count << 24), sizing
    // the buffers first (no earlier recording that uses them may still be pending). Ends with the tree written
    // for compute kernels to read.
    void record(VkCommandBuffer cmd, const vk::Buffer& symbols, std::uint32_t count);

    // The same for a count only the device knows (a step recorded after others): derive/step_sizes.comp wrote the
    // levels into levelInfo() and the workgroups into the block of `arguments` at `blockOffset` (kArgsModules,
    // kArgsTreeScan, kArgsTreeLevels). The buffers must hold `capacity` modules, at least the count: reserve()
    // them first. Records the levels that many modules have (the others would get no workgroups).
    // reserve() returns the partners() it replaced (empty when it kept them), for a caller whose partners are
    // carried from step to step to copy from.
    [[nodiscard]] vk::Buffer reserve(std::uint32_t capacity);
    void recordCountedOnDevice(VkCommandBuffer cmd, const vk::Buffer& symbols, std::uint32_t capacity,
                               const vk::Buffer& arguments, VkDeviceSize blockOffset);

    const vk::Buffer& tree() const { return tree_; }
    const vk::Buffer& levelInfo() const { return levelInfo_; }
    const vk::Buffer& partners() const { return partners_; }

    // Partners that a derivation pass writes for the string it writes, instead of a tree built over that string
    // (GeneratedKernels::carriesPartners): the buffer for them, with room for `count` modules, and, once the pass
    // is recorded, carried() makes them partners(). The tree is then out of date.
    const vk::Buffer& carriedPartners(std::uint32_t count);
    void carried() { std::swap(partners_, carriedPartners_); }

private:
    const vk::Context& context_;
    GpuScan& scan_;
    vk::ComputePipeline bracketDepth_, depthLeaves_, depthLevel_, bracketPartners_;
    vk::Buffer deltas_, before_, tree_, levelInfo_, partners_, carriedPartners_;
};

} // namespace simeco::gpu
