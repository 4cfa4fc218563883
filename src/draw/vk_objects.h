// Owners of the graphics objects the renderer adds to the compute-only Vulkan layer.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "vk/handle.h"

namespace simeco::vk {
class Context;
}

namespace simeco::draw {

using UniqueImage = vk::DeviceHandle<VkImage, vkDestroyImage>;
using UniqueImageView = vk::DeviceHandle<VkImageView, vkDestroyImageView>;
using UniqueRenderPass = vk::DeviceHandle<VkRenderPass, vkDestroyRenderPass>;
using UniqueFramebuffer = vk::DeviceHandle<VkFramebuffer, vkDestroyFramebuffer>;

// A 2D image in device-local memory with a view of the given aspect.
struct Attachment {
    Attachment() = default;
    Attachment(const vk::Context& context, VkFormat format, VkImageAspectFlags aspect, VkImageUsageFlags usage,
               std::uint32_t width, std::uint32_t height);

    vk::UniqueMemory memory; // declared first so the image and view go before their memory
    UniqueImage image;
    UniqueImageView view;
    VkFormat format = VK_FORMAT_UNDEFINED;
};

// One dependency over all memory between the given stages and accesses.
void memoryDependency(VkCommandBuffer cmd, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                      VkPipelineStageFlags dstStages, VkAccessFlags dstAccess);

} // namespace simeco::draw
