// GPU timestamps: a query pool written from command buffers and read back as nanoseconds.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/handle.h"

namespace simeco::vk {

class Context;

class Timestamps {
public:
    // Throws VulkanError when the queue has no timestamp support.
    Timestamps(const Context& context, std::uint32_t count);

    // Must be recorded before the first write() of a submission.
    void cmdReset(VkCommandBuffer cmd) const;
    // Records the time at which all earlier work has finished `stage` (compute work by default).
    void cmdWrite(VkCommandBuffer cmd, std::uint32_t index,
                  VkPipelineStageFlagBits stage = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT) const;

    // Nanoseconds between queries `from` and `to`; waits for both results.
    double elapsedNs(std::uint32_t from, std::uint32_t to) const;
    // All raw results converted to nanoseconds since an arbitrary origin.
    std::vector<double> readNs() const { return readNs(count_); }
    // The first `count` results; waits for them.
    std::vector<double> readNs(std::uint32_t count) const;

private:
    VkDevice device_ = VK_NULL_HANDLE;
    std::uint32_t count_ = 0;
    double periodNs_ = 1.0;
    std::uint64_t validMask_ = 0;
    UniqueQueryPool pool_;
};

} // namespace simeco::vk
