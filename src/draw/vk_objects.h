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

// A 2D image in device-local memory with `levels` mip levels and `layers` layers, and a view of all of them of the
// given aspect and type; `samples` a pixel (a multisampled image has one level).
struct DeviceImage {
    DeviceImage() = default;
    DeviceImage(const vk::Context& context, VkFormat format, VkImageAspectFlags aspect, VkImageUsageFlags usage,
                VkExtent2D extent, std::uint32_t levels, std::uint32_t layers,
                VkImageViewType viewType = VK_IMAGE_VIEW_TYPE_2D, std::uint32_t samples = 1);

    vk::UniqueMemory memory; // declared first so the image and view go before their memory
    UniqueImage image;
    UniqueImageView view;
};

// A render target's image: one level, one layer, `samples` a pixel.
struct Attachment : DeviceImage {
    Attachment() = default;
    Attachment(const vk::Context& context, VkFormat format, VkImageAspectFlags aspect, VkImageUsageFlags usage,
               std::uint32_t width, std::uint32_t height, std::uint32_t samples = 1);

    VkFormat format = VK_FORMAT_UNDEFINED;
};

// A layout transition of an image's colour levels [0, levels) and layers [0, layers), after the given stages and
// accesses and before the others.
void imageTransition(VkCommandBuffer cmd, VkImage image, std::uint32_t levels, std::uint32_t layers, VkImageLayout from,
                     VkImageLayout to, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                     VkPipelineStageFlags dstStage, VkAccessFlags dstAccess);

// One dependency over all memory between the given stages and accesses.
void memoryDependency(VkCommandBuffer cmd, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                      VkPipelineStageFlags dstStages, VkAccessFlags dstAccess);

} // namespace simeco::draw
