#include "draw/render_pass.h"

#include <array>
#include <bit>
#include <span>
#include <stdexcept>
#include <string>

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

constexpr VkPipelineStageFlags kAttachmentStages = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT |
                                                   VK_PIPELINE_STAGE_EARLY_FRAGMENT_TESTS_BIT |
                                                   VK_PIPELINE_STAGE_LATE_FRAGMENT_TESTS_BIT;
constexpr VkAccessFlags kAttachmentWrites =
    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT;

UniqueRenderPass makeRenderPass(const vk::Context& context, std::span<const VkAttachmentDescription> attachments,
                                std::span<const VkSubpassDescription> subpasses,
                                std::span<const VkSubpassDependency> dependencies) {
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

UniqueRenderPass createOneSamplePass(const vk::Context& context) {
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

    std::array<VkSubpassDependency, 4> dependencies{};
    // The previous frame's copies out of the images finish before this frame clears them.
    dependencies[0].srcSubpass = VK_SUBPASS_EXTERNAL;
    dependencies[0].dstSubpass = kOrganSubpass;
    dependencies[0].srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
    dependencies[0].srcAccessMask = 0;
    dependencies[0].dstStageMask = kAttachmentStages;
    dependencies[0].dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
                                    VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    // The sunlit pass reads the sun's light and the stencil where each pixel's organs and volumes left them, and
    // blends onto their colour.
    dependencies[1].srcSubpass = kOrganSubpass;
    dependencies[1].dstSubpass = kSunlitSubpass;
    dependencies[1].srcStageMask = kAttachmentStages;
    dependencies[1].srcAccessMask = kAttachmentWrites;
    dependencies[1].dstStageMask = kAttachmentStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT;
    dependencies[1].dstAccessMask = VK_ACCESS_INPUT_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                                    VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT;
    dependencies[1].dependencyFlags = VK_DEPENDENCY_BY_REGION_BIT;
    // The copies out wait for everything drawn, in either subpass.
    for (std::uint32_t subpass : {kOrganSubpass, kSunlitSubpass}) {
        VkSubpassDependency& d = dependencies[2 + subpass];
        d.srcSubpass = subpass;
        d.dstSubpass = VK_SUBPASS_EXTERNAL;
        d.srcStageMask = kAttachmentStages;
        d.srcAccessMask = kAttachmentWrites;
        d.dstStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT;
        d.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    }
    return makeRenderPass(context, attachments, subpasses, dependencies);
}

UniqueRenderPass createMultisampledPass(const vk::Context& context, std::uint32_t samples) {
    std::array<VkAttachmentDescription, kSampledAttachments> attachments{};
    for (std::uint32_t i = 0; i < attachments.size(); ++i) {
        VkAttachmentDescription& a = attachments[i];
        const bool resolved = i >= kResolvedColor;
        a.format = i == kDepthSamples                           ? kDepthFormat
                   : i == kResolvedPlant || i == kResolvedOrgan ? kIdFormat
                   : i == kResolvedDepth                        ? kResolvedDepthFormat
                   : i == kIdSamples                            ? kIdSamplesFormat
                                                                : kColorFormat;
        a.samples = resolved ? VK_SAMPLE_COUNT_1_BIT : static_cast<VkSampleCountFlagBits>(samples);
        // The samples live within the render pass; the resolve subpass writes every pixel of the rest.
        a.loadOp = resolved ? VK_ATTACHMENT_LOAD_OP_DONT_CARE : VK_ATTACHMENT_LOAD_OP_CLEAR;
        a.storeOp = resolved ? VK_ATTACHMENT_STORE_OP_STORE : VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.stencilLoadOp = i == kDepthSamples ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_DONT_CARE;
        a.stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
        a.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        a.finalLayout = resolved ? VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL : VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL;
    }
    attachments[kDepthSamples].finalLayout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL;

    const std::array<VkAttachmentReference, 3> organColors{{
        {kColorSamples, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kIdSamples, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kSunSamples, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
    }};
    const VkAttachmentReference depthRef{kDepthSamples, VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference sunlitColor{kColorSamples, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    const VkAttachmentReference sunlitStencil{kDepthSamples, VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL};
    // The resolve shader's input attachments, by their input_attachment_index: the sun's light (and depth) first,
    // as in the sunlit subpass.
    const std::array<VkAttachmentReference, 3> samplesRead{{
        {kSunSamples, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {kColorSamples, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
        {kIdSamples, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL},
    }};
    const std::array<VkAttachmentReference, 4> resolvedColors{{
        {kResolvedColor, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kResolvedPlant, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kResolvedOrgan, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
        {kResolvedDepth, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL},
    }};
    const std::uint32_t kept = kIdSamples;
    std::array<VkSubpassDescription, 3> subpasses{};
    for (VkSubpassDescription& subpass : subpasses)
        subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    subpasses[kOrganSubpass].colorAttachmentCount = static_cast<std::uint32_t>(organColors.size());
    subpasses[kOrganSubpass].pColorAttachments = organColors.data();
    subpasses[kOrganSubpass].pDepthStencilAttachment = &depthRef;
    subpasses[kSunlitSubpass].inputAttachmentCount = 1;
    subpasses[kSunlitSubpass].pInputAttachments = &samplesRead[0];
    subpasses[kSunlitSubpass].colorAttachmentCount = 1;
    subpasses[kSunlitSubpass].pColorAttachments = &sunlitColor;
    subpasses[kSunlitSubpass].pDepthStencilAttachment = &sunlitStencil;
    subpasses[kSunlitSubpass].preserveAttachmentCount = 1;
    subpasses[kSunlitSubpass].pPreserveAttachments = &kept;
    subpasses[kResolveSubpass].inputAttachmentCount = static_cast<std::uint32_t>(samplesRead.size());
    subpasses[kResolveSubpass].pInputAttachments = samplesRead.data();
    subpasses[kResolveSubpass].colorAttachmentCount = static_cast<std::uint32_t>(resolvedColors.size());
    subpasses[kResolveSubpass].pColorAttachments = resolvedColors.data();

    std::array<VkSubpassDependency, 6> dependencies{};
    // The previous frame's copies out of the resolved images finish before this frame writes them.
    dependencies[0] = {VK_SUBPASS_EXTERNAL,
                       kResolveSubpass,
                       VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                       0,
                       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                       0};
    // And its resolve's reads of the samples before this frame clears them.
    dependencies[5] = {VK_SUBPASS_EXTERNAL,
                       kOrganSubpass,
                       VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                       kAttachmentStages,
                       0,
                       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                           VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                       0};
    // As in one sample: the sunlit pass reads the sun's light and the stencil the organs and volumes left.
    dependencies[1] = {kOrganSubpass,
                       kSunlitSubpass,
                       kAttachmentStages,
                       kAttachmentStages | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                       kAttachmentWrites,
                       VK_ACCESS_INPUT_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_READ_BIT |
                           VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_DEPTH_STENCIL_ATTACHMENT_READ_BIT,
                       VK_DEPENDENCY_BY_REGION_BIT};
    // The resolve reads the samples each subpass before it wrote.
    for (std::uint32_t subpass : {kOrganSubpass, kSunlitSubpass}) {
        dependencies[2 + subpass] = {subpass,
                                     kResolveSubpass,
                                     VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                                     VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                                     VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                                     VK_ACCESS_INPUT_ATTACHMENT_READ_BIT,
                                     VK_DEPENDENCY_BY_REGION_BIT};
    }
    // The copies out wait for the resolved pixels.
    dependencies[4] = {kResolveSubpass,
                       VK_SUBPASS_EXTERNAL,
                       VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                       VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT,
                       VK_ACCESS_TRANSFER_READ_BIT,
                       0};
    return makeRenderPass(context, attachments, subpasses, dependencies);
}

// The sample counts of images of `format` for `usage` on the device.
VkSampleCountFlags imageSampleCounts(const vk::Context& context, VkFormat format, VkImageUsageFlags usage) {
    VkImageFormatProperties properties{};
    if (vkGetPhysicalDeviceImageFormatProperties(context.physicalDevice(), format, VK_IMAGE_TYPE_2D,
                                                 VK_IMAGE_TILING_OPTIMAL, usage, 0, &properties) != VK_SUCCESS)
        return 0;
    return properties.sampleCounts;
}

bool hasFormatFeatures(const vk::Context& context, VkFormat format, VkFormatFeatureFlags features) {
    VkFormatProperties properties{};
    vkGetPhysicalDeviceFormatProperties(context.physicalDevice(), format, &properties);
    return (properties.optimalTilingFeatures & features) == features;
}

} // namespace

UniqueRenderPass createRenderPass(const vk::Context& context, std::uint32_t samples) {
    return samples > 1 ? createMultisampledPass(context, samples) : createOneSamplePass(context);
}

VkSampleCountFlags drawableSampleCounts(const vk::Context& context) {
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(context.physicalDevice(), &features);
    const VkPhysicalDeviceLimits& limits = context.limits();
    // The sunlit subpass adds each sample's own sun light: it runs per sample.
    if (!features.sampleRateShading ||
        !hasFormatFeatures(context, kResolvedDepthFormat,
                           VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT))
        return VK_SAMPLE_COUNT_1_BIT;
    const VkImageUsageFlags samplesUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_INPUT_ATTACHMENT_BIT |
                                           VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    const VkImageUsageFlags depthUsage =
        VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSIENT_ATTACHMENT_BIT;
    return (limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts &
            limits.framebufferStencilSampleCounts & imageSampleCounts(context, kColorFormat, samplesUsage) &
            imageSampleCounts(context, kDepthFormat, depthUsage)) |
           VK_SAMPLE_COUNT_1_BIT;
}

std::uint32_t defaultSamples(VkSampleCountFlags drawable) {
    return (drawable & VK_SAMPLE_COUNT_4_BIT) ? 4u : 1u;
}

std::uint32_t defaultSamples(const vk::Context& context) {
    return defaultSamples(drawableSampleCounts(context));
}

std::uint32_t interactiveSamples(const vk::Context& context) {
    return context.deviceInfo().type == VK_PHYSICAL_DEVICE_TYPE_CPU ? 1u : defaultSamples(context);
}

void checkSamples(VkSampleCountFlags drawable, std::uint32_t samples, std::string_view device) {
    if (std::has_single_bit(samples) && (drawable & samples) != 0) return;
    std::string counts;
    for (std::uint32_t count = 1; count <= VK_SAMPLE_COUNT_64_BIT; count *= 2)
        if (drawable & count) counts += fmt::format("{}{}", counts.empty() ? "" : ", ", count);
    throw std::invalid_argument(
        fmt::format("cannot draw {} samples a pixel: the device '{}' draws {}", samples, device, counts));
}

void checkSamples(const vk::Context& context, std::uint32_t samples) {
    checkSamples(drawableSampleCounts(context), samples, context.deviceInfo().name);
}

void checkRenderFormats(const vk::Context& context) {
    const VkFormatFeatureFlags copyable = VK_FORMAT_FEATURE_TRANSFER_SRC_BIT;
    requireFormat(context, kColorFormat,
                  VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT | copyable,
                  "blended colour");
    requireFormat(context, kIdFormat, VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | copyable, "ids");
    requireFormat(context, kDepthFormat, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | copyable,
                  "depth and stencil");
}

} // namespace simeco::draw
