#include "vk/submission.h"

#include <utility>

#include <fmt/format.h>

#include "vk/vk_error.h"

namespace simeco::vk {

Submission::Submission(VkDevice device, VkCommandPool pool, VkCommandBuffer cmd, UniqueFence fence)
    : device_(device), pool_(pool), cmd_(cmd), fence_(std::move(fence)) {}

Submission::~Submission() {
    if (!pending()) return;
    try {
        wait();
    } catch (const VulkanError&) {
        // A destructor cannot throw: the work is left to the device, its objects leaked as wait() leaves them.
    }
}

Submission::Submission(Submission&& other) noexcept
    : device_(other.device_),
      pool_(other.pool_),
      cmd_(std::exchange(other.cmd_, VK_NULL_HANDLE)),
      fence_(std::move(other.fence_)) {}

Submission& Submission::operator=(Submission&& other) noexcept {
    if (this != &other) {
        Submission old(std::move(*this)); // waits for what this held
        device_ = other.device_;
        pool_ = other.pool_;
        cmd_ = std::exchange(other.cmd_, VK_NULL_HANDLE);
        fence_ = std::move(other.fence_);
    }
    return *this;
}

void Submission::wait(std::chrono::seconds timeout) {
    if (!pending()) return;
    VkFence fence = fence_.get();
    auto nanoseconds = static_cast<std::uint64_t>(std::chrono::nanoseconds(timeout).count());
    VkResult waited = vkWaitForFences(device_, 1, &fence, VK_TRUE, nanoseconds);
    if (waited == VK_TIMEOUT) {
        // The GPU may still use the command buffer and fence; leaking them beats destroying objects in use.
        fence_.release();
        cmd_ = VK_NULL_HANDLE;
        throw VulkanError(fmt::format("GPU work did not finish within {} s", timeout.count()), VK_TIMEOUT);
    }
    vkFreeCommandBuffers(device_, pool_, 1, &cmd_);
    cmd_ = VK_NULL_HANDLE;
    fence_.reset();
    VK_CHECK(waited);
}

} // namespace simeco::vk
