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
    std::array<VkAttachmentDescription, kAttachments> attachments{};
    for (std::uint32_t i = 0; i < attachments.size(); ++i) {
        VkAttachmentDescription& a = attachments[i];
        a.format = i == kColorAttachment || i == kSunAttachment ? kColorFormat
                   : i == kDepthAttachment                      ? kDepthFormat
                                                                : kIdFormat;
        a.samples = VK_SAMPLE_COUNT_1_BIT;
        a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        // Only the shadow passes use the stencil, within the render pass.
        a.stencilLoadOp = i == kDepthAttachment ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        a.finalLayout = VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL;
    }
    // The sun's light lives within the render pass.
    attachments[kSunAttachment].storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
    attachments[kSunAttachment].finalLayout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;

    std::array<VkAttachmentReference, 4> organColors{{
        {kColorAttachment, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kPlantAttachment, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kOrganAttachment, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kSunAttachment, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
    }};
    VkAttachmentReference depthRef{kDepthAttachment, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    VkAttachmentReference sunlitColor{kColorAttachment, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkAttachmentReference sunlitInput{kSunAttachment, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkAttachmentReference sunlitStencil{kDepthAttachment, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    const std::array<std::uint32_t, 2> kept{kPlantAttachment, kOrganAttachment};
    std::array<VkSubpassDescription, 2> subpasses{};
    subpasses[kOrganSubpass].pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpasses[kOrganSubpass].colorAttachmentCount = static_cast<std::uint32_t>(organColors.size());
    subpasses[kOrganSubpass].pColorAttachments = organColors.data();
    subpasses[kOrganSubpass].pDepthStencilAttachment = &depthRef;
    subpasses[kSunlitSubpass].pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpasses[kSunlitSubpass].inputAttachmentCount = 1;
    subpasses[kSunlitSubpass].pInputAttachments = &sunlitInput;
    subpasses[kSunlitSubpass].colorAttachmentCount = 1;
    subpasses[kSunlitSubpass].pColorAttachments = &sunlitColor;
    subpasses[kSunlitSubpass].pDepthStencilAttachment = &sunlitStencil;
    subpasses[kSunlitSubpass].preserveAttachmentCount = static_cast<std::uint32_t>(kept.size());
    subpasses[kSunlitSubpass].pPreserveAttachments = kept.data();

    const VkPipelineStageFlags attachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                  VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                  VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
    const VkAccessFlags attachmentWrites =
        VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;
    std::array<VkSubpassDependency, 4> dependencies{};
    // The previous frame's copies out of the images finish before this frame clears them.
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = kOrganSubpass;
    dependencies[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[0].srcAccessMask = 0;
    dependencies[0].dstStageMask = attachmentStages;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    // The sunlit pass reads the sun's light and the stencil where each pixel's organs and volumes left them, and
    // blends onto their colour.
    dependencies[1].srcSubpass = kOrganSubpass;
    dependencies[1].dstSubpass = kSunlitSubpass;
    dependencies[1].srcStageMask = attachmentStages;
    dependencies[1].srcAccessMask = attachmentWrites;
    dependencies[1].dstStageMask = attachmentStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_INPUT_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    dependencies[1].dependencyFlags = VK_DEPENDENCY_BY_REGION_BIT;
    // The copies out wait for everything drawn, in either subpass.
    for (std::uint32_t subpass : {kOrganSubpass, kSunlitSubpass}) {
        VkSubpassDependency& d = dependencies[2 + subpass];
        d.srcSubpass = subpass;
        d.dstSubpass = VK_SUBPASS_EXTERNAL;
        d.srcStageMask = attachmentStages;
        d.srcAccessMask = attachmentWrites;
        d.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
        d.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    }

    VkRenderPassCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    info.attachmentCount = static_cast<std::uint32_t>(attachments.size());
    info.pAttachments = attachments.data();
    info.subpassCount = static_cast<std::uint32_t>(subpasses.size());
    info.pSubpasses = subpasses.data();
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
    sun_ = Attachment(context, kColorFormat, VK_IMAGE_ASPECT_COLOR_BIT,
                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT, width, height);

    std::array<VkImageView, kAttachments> views{color_.view.get(), plant_.view.get(), organ_.view.get(),
                                                depth_.view.get(), sun_.view.get()};
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
