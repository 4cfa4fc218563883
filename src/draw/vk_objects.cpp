#include "draw/vk_objects.h"

#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::draw {

DeviceImage::DeviceImage(const vk::Context& context, VkFormat format, VkImageAspectFlags aspect,
                         VkImageUsageFlags usage, VkExtent2D extent, std::uint32_t levels, std::uint32_t layers,
                         VkImageViewType viewType, std::uint32_t samples) {
    VkDevice device = context.device();
    VkImageCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
    info.imageType = VK_IMAGE_TYPE_2D;
    info.format = format;
    info.extent = {extent.width, extent.height, 1};
    info.mipLevels = levels;
    info.arrayLayers = layers;
    info.samples = static_cast<VkSampleCountFlagBits>(samples);
    info.tiling = VK_IMAGE_TILING_OPTIMAL;
    info.usage = usage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkImage rawImage = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImage(device, &info, nullptr, &rawImage));
    image = UniqueImage(device, rawImage);

    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(device, rawImage, &requirements);
    VkMemoryAllocateInfo allocateInfo{};
    allocateInfo.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    allocateInfo.allocationSize = requirements.size;
    allocateInfo.memoryTypeIndex = vk::chooseMemoryType(context.memoryProperties(), requirements.memoryTypeBits, 0,
                                                        VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    VkDeviceMemory rawMemory = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateMemory(device, &allocateInfo, nullptr, &rawMemory));
    memory = vk::UniqueMemory(device, rawMemory);
    VK_CHECK(vkBindImageMemory(device, rawImage, rawMemory, 0));

    VkImageViewCreateInfo viewInfo{};
    viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    viewInfo.image = rawImage;
    viewInfo.viewType = viewType;
    viewInfo.format = format;
    viewInfo.subresourceRange = {aspect, 0, levels, 0, layers};
    VkImageView rawView = VK_NULL_HANDLE;
    VK_CHECK(vkCreateImageView(device, &viewInfo, nullptr, &rawView));
    view = UniqueImageView(device, rawView);
}

Attachment::Attachment(const vk::Context& context, VkFormat imageFormat, VkImageAspectFlags aspect,
                       VkImageUsageFlags usage, std::uint32_t width, std::uint32_t height, std::uint32_t samples)
    : DeviceImage(context, imageFormat, aspect, usage, {width, height}, 1, 1, VK_IMAGE_VIEW_TYPE_2D, samples),
      format(imageFormat) {}

void imageTransition(VkCommandBuffer cmd, VkImage image, std::uint32_t levels, std::uint32_t layers, VkImageLayout from,
                     VkImageLayout to, VkPipelineStageFlags srcStage, VkAccessFlags srcAccess,
                     VkPipelineStageFlags dstStage, VkAccessFlags dstAccess) {
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, levels, 0, layers};
    vkCmdPipelineBarrier(cmd, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

void memoryDependency(VkCommandBuffer cmd, VkPipelineStageFlags srcStages, VkAccessFlags srcAccess,
                      VkPipelineStageFlags dstStages, VkAccessFlags dstAccess) {
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    vkCmdPipelineBarrier(cmd, srcStages, dstStages, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

} // namespace simeco::draw
