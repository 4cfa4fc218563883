#include "view/swapchain.h"

#include <algorithm>

#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::view {
namespace {

// Bytes in the order the display kernel packs them where the surface offers it; a format that encodes sRGB
// itself otherwise.
VkSurfaceFormatKHR chooseFormat(VkPhysicalDevice device, VkSurfaceKHR surface) {
    std::uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, nullptr));
    std::vector<VkSurfaceFormatKHR> formats(count);
    VK_CHECK(vkGetPhysicalDeviceSurfaceFormatsKHR(device, surface, &count, formats.data()));
    if (formats.empty()) throw vk::VulkanError("the window's surface offers no format", VK_ERROR_FORMAT_NOT_SUPPORTED);
    for (VkFormat wanted : {VK_FORMAT_B8G8R8A8_UNORM, VK_FORMAT_R8G8B8A8_UNORM, VK_FORMAT_B8G8R8A8_SRGB,
                            VK_FORMAT_R8G8B8A8_SRGB})
        for (const VkSurfaceFormatKHR& f : formats)
            if (f.format == wanted && f.colorSpace == VK_COLOR_SPACE_SRGB_NONLINEAR_KHR) return f;
    return formats.front();
}

// Frames as fast as they are drawn, without tearing where the surface can (mailbox), else in step with the
// display (FIFO, which every surface offers).
VkPresentModeKHR choosePresentMode(VkPhysicalDevice device, VkSurfaceKHR surface) {
    std::uint32_t count = 0;
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &count, nullptr));
    std::vector<VkPresentModeKHR> modes(count);
    VK_CHECK(vkGetPhysicalDeviceSurfacePresentModesKHR(device, surface, &count, modes.data()));
    return std::find(modes.begin(), modes.end(), VK_PRESENT_MODE_MAILBOX_KHR) != modes.end()
               ? VK_PRESENT_MODE_MAILBOX_KHR
               : VK_PRESENT_MODE_FIFO_KHR;
}

} // namespace

UniqueSemaphore makeSemaphore(VkDevice device) {
    VkSemaphoreCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
    VkSemaphore semaphore = VK_NULL_HANDLE;
    VK_CHECK(vkCreateSemaphore(device, &info, nullptr, &semaphore));
    return UniqueSemaphore(device, semaphore);
}

Swapchain::Swapchain(const vk::Context& context, VkSurfaceKHR surface, VkExtent2D size)
    : context_(context), surface_(surface) {
    make(size, VK_NULL_HANDLE);
}

Swapchain::~Swapchain() {
    views_.clear();
    drawn_.clear();
    if (swapchain_ != VK_NULL_HANDLE) vkDestroySwapchainKHR(context_.device(), swapchain_, nullptr);
}

bool Swapchain::encodesSrgb() const {
    return format_ == VK_FORMAT_B8G8R8A8_SRGB || format_ == VK_FORMAT_R8G8B8A8_SRGB;
}

void Swapchain::recreate(VkExtent2D size) {
    VK_CHECK(vkDeviceWaitIdle(context_.device()));
    views_.clear();
    drawn_.clear();
    const VkSwapchainKHR old = swapchain_;
    make(size, old);
    vkDestroySwapchainKHR(context_.device(), old, nullptr);
}

void Swapchain::make(VkExtent2D size, VkSwapchainKHR old) {
    const VkPhysicalDevice physical = context_.physicalDevice();
    const VkDevice device = context_.device();
    VkSurfaceCapabilitiesKHR caps{};
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(physical, surface_, &caps));
    if ((caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_DST_BIT) == 0)
        throw vk::VulkanError("the window's images cannot be copied into", VK_ERROR_FEATURE_NOT_PRESENT);
    const VkSurfaceFormatKHR format = chooseFormat(physical, surface_);
    format_ = format.format;
    extent_ = caps.currentExtent.width != 0xFFFFFFFFu
                  ? caps.currentExtent
                  : VkExtent2D{std::clamp(size.width, caps.minImageExtent.width, caps.maxImageExtent.width),
                               std::clamp(size.height, caps.minImageExtent.height, caps.maxImageExtent.height)};
    minImageCount_ = caps.maxImageCount == 0 ? caps.minImageCount + 1
                                              : std::min(caps.minImageCount + 1, caps.maxImageCount);
    minImageCount_ = std::max(minImageCount_, 2u);

    VkSwapchainCreateInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR;
    info.surface = surface_;
    info.minImageCount = minImageCount_;
    info.imageFormat = format.format;
    info.imageColorSpace = format.colorSpace;
    info.imageExtent = extent_;
    info.imageArrayLayers = 1;
    info.imageUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    info.imageSharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.preTransform = caps.currentTransform;
    info.compositeAlpha = (caps.supportedCompositeAlpha & VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR)
                              ? VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR
                              : VkCompositeAlphaFlagBitsKHR(caps.supportedCompositeAlpha &
                                                            ~(caps.supportedCompositeAlpha - 1));
    info.presentMode = choosePresentMode(physical, surface_);
    info.clipped = VK_TRUE;
    info.oldSwapchain = old;
    VK_CHECK(vkCreateSwapchainKHR(device, &info, nullptr, &swapchain_));

    std::uint32_t count = 0;
    VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, nullptr));
    images_.resize(count);
    VK_CHECK(vkGetSwapchainImagesKHR(device, swapchain_, &count, images_.data()));
    for (VkImage image : images_) {
        VkImageViewCreateInfo viewInfo{};
        viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
        viewInfo.image = image;
        viewInfo.viewType = VK_IMAGE_VIEW_TYPE_2D;
        viewInfo.format = format_;
        viewInfo.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkImageView view = VK_NULL_HANDLE;
        VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &view));
        views_.emplace_back(device, view);
        drawn_.push_back(makeSemaphore(device));
    }
}

std::optional<std::uint32_t> Swapchain::acquire(VkSemaphore acquired) {
    std::uint32_t index = 0;
    const VkResult result =
        vkAcquireNextImageKHR(context_.device(), swapchain_, UINT64_MAX, acquired, VK_NULL_HANDLE, &index);
    if (result == VK_ERROR_OUT_OF_DATE_KHR) return std::nullopt;
    if (result != VK_SUCCESS && result != VK_SUBOPTIMAL_KHR)
        vk::throwVulkanError(result, "vkAcquireNextImageKHR", __FILE__, __LINE__);
    return index;
}

bool Swapchain::present(std::uint32_t image) {
    VkPresentInfoKHR info{};
    info.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
    const VkSemaphore wait = drawn(image);
    info.waitSemaphoreCount = 1;
    info.pWaitSemaphores = &wait;
    info.swapchainCount = 1;
    info.pSwapchains = &swapchain_;
    info.pImageIndices = &image;
    const VkResult result = vkQueuePresentKHR(context_.queue(), &info);
    if (result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR) return false;
    if (result != VK_SUCCESS) vk::throwVulkanError(result, "vkQueuePresentKHR", __FILE__, __LINE__);
    return true;
}

} // namespace simeco::view
