// GPU time per kernel. When a context has a profile, every dispatch recorded in one of its submissions is
// followed by a timestamp, and once the submission has finished the time since the previous timestamp is added
// to the kernel's total. Copies and fills between dispatches count towards the kernel that follows them, so the
// totals add up to the GPU time of the profiled submissions.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/timestamps.h"

namespace simeco::vk {

class Context;

class KernelProfile {
public:
    struct Kernel {
        std::string name;
        std::uint64_t dispatches = 0;
        double milliseconds = 0;
    };

    // `capacity`: the timestamps one submission can hold; dispatches past it are counted in unprofiled().
    explicit KernelProfile(const Context& context, std::uint32_t capacity = 8192);

    // Called by the context: at the start of a command buffer, and after its submission has finished.
    void begin(VkCommandBuffer cmd);
    void finish();

    // Called by ComputePipeline after recording a dispatch into `cmd`.
    void afterDispatch(VkCommandBuffer cmd, const std::string& kernel);

    // Kernels by total time, longest first.
    std::vector<Kernel> kernels() const;
    std::uint64_t unprofiled() const { return unprofiled_; }
    // A table of kernels, dispatches, milliseconds and shares of the total.
    std::string table() const;

private:
    Timestamps stamps_;
    std::uint32_t capacity_;
    VkCommandBuffer recording_ = VK_NULL_HANDLE;
    std::vector<const std::string*> pending_; // the kernel behind timestamp i + 1
    std::map<std::string, Kernel> totals_;
    std::uint64_t unprofiled_ = 0;
};

} // namespace simeco::vk
