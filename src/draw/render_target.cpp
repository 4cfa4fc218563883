#include "draw/render_target.h"

#include <array>

#include <fmt/format.h>

#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::draw {
namespace {

void requireFormat(const vk::Context& context, VkFormat format, VkFormatFeatureFlags features, const char* what) {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &properties);
    if ((properties.optimalTilingFeatures & features) != features) {
        throw vk::VulkanError(fmt::format("the device '{}' cannot render {} in format {}", context.deviceInfo().name,
                                          what, static_cast<int>(format)),
                              VK_ERROR_FORMAT_NOT_SUPPORTED);
    }
}

} // namespace

void checkRenderFormats(const vk::Context& context) {
    const VkFormatFeatureFlags copyable = VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    requireFormat(context, kColorFormat,
                  VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT | copyable,
                  "blended colour");
    requireFormat(context, kIdFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | copyable, "ids");
    requireFormat(context, kDepthFormat, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | copyable,
                  "depth and stencil");
}

UniqueRenderPass createRenderPass(const vk::Context& context) {
    std::array<VkAttachmentDescription, 4> attachments{};
    for (std::uint32_t i = 0; i < attachments.size(); ++i) {
        VkAttachmentDescription& a = attachments[i];
        a.format = i == kColorAttachment ? kColorFormat : (i == kDepthAttachment ? kDepthFormat : kIdFormat);
        a.samples = VK_SAMPLE_COUNT_1_BIT;
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        // Only the shadow passes use the stencil, within the render pass.
        a.stencilLoadOp = i == kDepthAttachment ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        a.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    }
    std::array<VkAttachmentReference, 3> colorRefs{{
        {kColorAttachment, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kPlantAttachment, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kOrganAttachment, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
    }};
    VkAttachmentReference depthRef{kDepthAttachment, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpass.colorAttachmentCount = static_cast<std::uint32_t>(colorRefs.size());
    subpass.pColorAttachments = colorRefs.data();
    subpass.pDepthStencilAttachment = &depthRef;

    const VkPipelineStageFlags attachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                  VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                  VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    std::array<VkSubpassDependency, 2> dependencies{};
    // The previous frame's copies out of the images finish before this frame clears them.
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = 0;
    dependencies[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[0].srcAccessMask = 0;
    dependencies[0].dstStageMask = attachmentStages;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    // The copies out wait for everything drawn.
    dependencies[1].srcSubpass = 0;
    dependencies[1].dstSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[1].srcStageMask = attachmentStages;
    dependencies[1].srcAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    dependencies[1].dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;

    VkRenderPassCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = 1;
    info.pSubpasses = &subpass;
    info.dependencyCount = static_cast<std::uint32_t>(dependencies.size());
    info.pDependencies = dependencies.data();
    VkRenderPass renderPass = VK_NULL_HANDLE;
    VK_CHECK(vkCreateRenderPass(context.device(), &info, nullptr, &renderPass));
    return UniqueRenderPass(context.device(), renderPass);
}

RenderTarget::RenderTarget(const vk::Context& context, VkRenderPass renderPass, std::uint32_t width,
                           std::uint32_t height)
    : width_(width), height_(height) {
    const VkImageUsageFlags colorUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
    color_ = Attachment(context, kColorFormat, VK_IMAGE_ASPECT_COLOR_BIT, colorUsage, width, height);
    plant_ = Attachment(context, kIdFormat, VK_IMAGE_ASPECT_COLOR_BIT, colorUsage, width, height);
    organ_ = Attachment(context, kIdFormat, VK_IMAGE_ASPECT_COLOR_BIT, colorUsage, width, height);
    depth_ = Attachment(context, kDepthFormat, VK_IMAGE_ASPECT_DEPTH_BIT | VK_IMAGE_ASPECT_STENCIL_BIT,
                        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT, width, height);

    std::array<VkImageView, 4> views{color_.view.get(), plant_.view.get(), organ_.view.get(), depth_.view.get()};
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
    copy(depth_, VK_IMAGE_ASPECT_DEPTH_BIT, depthCopy_);
}

} // namespace simeco::draw
