#include "draw/render_target.h"

#include <vector>

#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::draw {

RenderTarget::RenderTarget(const vk::Context& context, VkRenderPass renderPass, std::uint32_t width,
                           std::uint32_t height, std::uint32_t samples)
    : width_(width), height_(height), samples_(samples) {
    const VkImageUsageFlags colorUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    const VkImageAspectFlags depthStencil = VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT;
    color_ = Attachment(context, kColorFormat, VK_IMAGE_ASPECT_COLOR_BIT, colorUsage, width, height);
    plant_ = Attachment(context, kIdFormat, VK_IMAGE_ASPECT_COLOR_BIT, colorUsage, width, height);
    organ_ = Attachment(context, kIdFormat, VK_IMAGE_ASPECT_COLOR_BIT, colorUsage, width, height);
    std::vector<VkImageView> views;
    if (samples == 1) {
        depth_ = Attachment(context, kDepthFormat, depthStencil,
                            VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, width,
                            height);
        sun_ = Attachment(context, kColorFormat, VK_IMAGE_ASPECT_COLOR_BIT,
                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT, width, height);
        views = {color_.view.get(), plant_.view.get(), organ_.view.get(), depth_.view.get(), sun_.view.get()};
    } else {
        // The samples never leave the render pass.
        const VkImageUsageFlags samplesUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                               VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT |
                                               VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
        colorSamples_ =
            Attachment(context, kColorFormat, VK_IMAGE_ASPECT_COLOR_BIT, samplesUsage, width, height, samples);
        idSamples_ =
            Attachment(context, kIdSamplesFormat, VK_IMAGE_ASPECT_COLOR_BIT, samplesUsage, width, height, samples);
        sun_ = Attachment(context, kColorFormat, VK_IMAGE_ASPECT_COLOR_BIT, samplesUsage, width, height, samples);
        depthSamples_ = Attachment(context, kDepthFormat, depthStencil,
                                   VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT |
                                       VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT,
                                   width, height, samples);
        depth_ = Attachment(context, kResolvedDepthFormat, VK_IMAGE_ASPECT_COLOR_BIT, colorUsage, width, height);
        views = {colorSamples_.view.get(), idSamples_.view.get(), sun_.view.get(), depthSamples_.view.get(),
                 color_.view.get(),        plant_.view.get(),     organ_.view.get(), depth_.view.get()};
    }

    VkFramebufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    info.renderPass = renderPass;
    info.attachmentCount = static_cast<std::uint32_t>(views.size());
    info.pAttachments = views.data();
    info.width = width;
    info.height = height;
    info.layers = 1;
    VkFramebuffer framebuffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFramebuffer(context.device(), &info, nullptr, &framebuffer));
    framebuffer_ = UniqueFramebuffer(context.device(), framebuffer);

    VkDeviceSize pixels = VkDeviceSize{width} * height;
    colorCopy_ = vk::Buffer(context, pixels * 16, vk::MemoryUsage::Readback);
    depthCopy_ = vk::Buffer(context, pixels * 4, vk::MemoryUsage::Readback);
    plantCopy_ = vk::Buffer(context, pixels * 4, vk::MemoryUsage::Readback);
    organCopy_ = vk::Buffer(context, pixels * 4, vk::MemoryUsage::Readback);
    outlined_ = vk::Buffer(context, pixels * 16, vk::MemoryUsage::Readback);
}

void RenderTarget::cmdCopyToBuffers(VkCommandBuffer cmd) const {
    auto copy = [&](const Attachment& image, VkImageAspectFlags aspect, const vk::Buffer& buffer) {
        VkBufferImageCopy region{};
        region.imageSubresource = {aspect, 0, 0, 1};
        region.imageExtent = {width_, height_, 1};
        vkCmdCopyImageToBuffer(cmd, image.image.get(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, buffer.handle(), 1,
                               &region);
    };
    copy(color_, VK_IMAGE_ASPECT_COLOR_BIT, colorCopy_);
    copy(plant_, VK_IMAGE_ASPECT_COLOR_BIT, plantCopy_);
    copy(organ_, VK_IMAGE_ASPECT_COLOR_BIT, organCopy_);
    // A multisampled target's depth is the resolved one, a colour image.
    copy(depth_, samples_ == 1 ? VK_IMAGE_ASPECT_DEPTH_BIT : VK_IMAGE_ASPECT_COLOR_BIT, depthCopy_);
}

} // namespace simeco::draw
