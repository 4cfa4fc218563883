// The window's swapchain: its images, and a semaphore per image that the frame drawn into it signals for the
// presentation to wait on. Made again when the window's size changes or the surface says it is out of date.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/handle.h"

namespace simeco::vk {
class Context;
}

namespace simeco::view {

using UniqueSemaphore = vk::DeviceHandle<VkSemaphore, vkDestroySemaphore>;
using UniqueImageView = vk::DeviceHandle<VkImageView, vkDestroyImageView>;

class Swapchain {
public:
    Swapchain(const vk::Context& context, VkSurfaceKHR surface, VkExtent2D size);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    // A new chain of `size` (after the device has finished with the old one's images).
    void recreate(VkExtent2D size);
    // The next image to draw into, signalling `acquired` when it may be written; none when the chain must be
    // made again first.
    std::optional<std::uint32_t> acquire(VkSemaphore acquired);
    // Presents `image` once its `drawn` semaphore is signalled; false when the chain must be made again.
    bool present(std::uint32_t image);

    VkFormat format() const { return format_; }
    // Whether the images' format encodes sRGB itself (what is written into them is linear).
    bool encodesSrgb() const;
    VkExtent2D extent() const { return extent_; }
    std::uint32_t imageCount() const { return std::uint32_t(images_.size()); }
    std::uint32_t minImageCount() const { return minImageCount_; }
    VkImage image(std::uint32_t i) const { return images_[i]; }
    VkImageView view(std::uint32_t i) const { return views_[i].get(); }
    VkSemaphore drawn(std::uint32_t i) const { return drawn_[i].get(); }

private:
    void make(VkExtent2D size, VkSwapchainKHR old);

    const vk::Context& context_;
    VkSurfaceKHR surface_;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkFormat format_ = VK_FORMAT_UNDEFINED;
    VkExtent2D extent_{};
    std::uint32_t minImageCount_ = 2;
    std::vector<VkImage> images_;
    std::vector<UniqueImageView> views_;
    std::vector<UniqueSemaphore> drawn_;
};

UniqueSemaphore makeSemaphore(VkDevice device);

} // namespace simeco::view
