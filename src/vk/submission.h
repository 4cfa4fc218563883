// Work handed to the queue and not yet waited for: the command buffer and fence of one submission
// (Context::submit). Several may be pending at once; the queue runs them in order, so the device need not idle
// while the host prepares the next. Only once a submission is waited for are its command buffer, and whatever
// the work reads or writes, free to reuse.
#pragma once

#include <chrono>

#include <vulkan/vulkan.h>

#include "vk/handle.h"

namespace simeco::vk {

class Submission {
public:
    Submission() = default;
    Submission(VkDevice device, VkCommandPool pool, VkCommandBuffer cmd, UniqueFence fence);
    // Waits: the command buffer is freed only once the device is done with it.
    ~Submission();

    Submission(const Submission&) = delete;
    Submission& operator=(const Submission&) = delete;
    Submission(Submission&& other) noexcept;
    Submission& operator=(Submission&& other) noexcept;

    // Waits for the device to finish the work. A GPU that does not within `timeout` raises VulkanError; the
    // command buffer and fence are then left alone rather than destroyed while the device may still use them.
    void wait(std::chrono::seconds timeout = std::chrono::seconds(120));
    // Whether work was submitted and not yet waited for.
    bool pending() const { return cmd_ != VK_NULL_HANDLE; }

private:
    VkDevice device_ = VK_NULL_HANDLE;
    VkCommandPool pool_ = VK_NULL_HANDLE;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    UniqueFence fence_;
};

} // namespace simeco::vk
