#include "view/presenter.h"

#include "render/shared/draw_layout.h"
#include "view/swapchain.h"
#include "vk/barriers.h"
#include "vk/context.h"

namespace simeco::view {
Presenter::Presenter(const vk::Context& context)
    : context_(context), toBytes_(vk::ComputePipeline::embedded(context, "present/display_bytes")) {}

void Presenter::record(VkCommandBuffer cmd, const vk::Buffer& color, std::uint32_t width, std::uint32_t height,
                       const Swapchain& swapchain, std::uint32_t image) {
    const std::uint64_t pixels = std::uint64_t(width) * height;
    if (!bytes_ || bytes_.size() < pixels * 4) bytes_ = vk::Buffer(context_, pixels * 4, vk::MemoryUsage::DeviceLocal);
    if (stagingSize_.width != width || stagingSize_.height != height) {
        // Sampled too: a view of the image is made with it, which needs a usage that views take.
        const VkImageUsageFlags usage =
            VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
        staging_ = draw::DeviceImage(context_, VK_FORMAT_R8G8B8A8_UNORM, VK_IMAGE_ASPECT_COLOR_BIT, usage,
                                     {width, height}, 1, 1);
        stagingSize_ = {width, height};
    }
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
    const shared::DisplayPush push{std::uint32_t(pixels), swapchain.encodesSrgb() ? 0u : 1u, 0, 0};
    toBytes_.dispatch(cmd, {color, bytes_}, push, toBytes_.groupsFor(pixels));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToTransfer);

    const VkImage staging = staging_.image.get();
    draw::imageTransition(cmd, staging, 1, 1, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT);
    VkBufferImageCopy copy{};
    copy.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    copy.imageExtent = {width, height, 1};
    vkCmdCopyBufferToImage(cmd, bytes_.handle(), staging, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    draw::imageTransition(cmd, staging, 1, 1, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_READ_BIT);

    // The acquire semaphore's wait is at the transfer stage: the window's image is written from here on.
    const VkImage target = swapchain.image(image);
    draw::imageTransition(cmd, target, 1, 1, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                          VK_PIPELINE_STAGE_TRANSFER_BIT, 0, VK_PIPELINE_STAGE_TRANSFER_BIT,
                          VK_ACCESS_TRANSFER_WRITE_BIT);
    const VkExtent2D into = swapchain.extent();
    VkImageBlit blit{};
    blit.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.srcOffsets[1] = {std::int32_t(width), std::int32_t(height), 1};
    blit.dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    blit.dstOffsets[1] = {std::int32_t(into.width), std::int32_t(into.height), 1};
    vkCmdBlitImage(cmd, staging, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, target, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   1, &blit, VK_FILTER_LINEAR);
}

} // namespace simeco::view
