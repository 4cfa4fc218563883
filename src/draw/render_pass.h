// The render pass an offscreen frame is drawn in, with one sample a pixel or several (multisampling).
//
// One sample: the organs and the shadow volumes, then the sunlit subpass, which adds the sun's light where the
// stencil is clear; colour, plant and organ ids, and depth are stored for the copies out.
//
// Several samples: the same two subpasses into multisampled images, then a resolve subpass that reads every
// sample of a pixel and writes the pixel: colour and alpha the samples' mean, plant, organ and depth those of the
// nearest sample (as draw::downsample does for a supersampled frame), so ids stay ids. Few devices multisample
// integer images, so the samples hold the ids as floats (their 16-bit halves, exact) and their depth beside the
// sun's light (its alpha).
#pragma once

#include <cstdint>
#include <string_view>

#include <vulkan/vulkan.h>

#include "draw/vk_objects.h"

namespace simeco::vk {
class Context;
}

namespace simeco::draw {

inline constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kIdFormat = VK_FORMAT_R32_UINT;
// A float depth, so the copy out is the value the outline kernel and the host read, with an 8-bit stencil.
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;
// A multisampled frame's ids (plant low and high half, organ low and high half) and its resolved depth.
inline constexpr VkFormat kIdSamplesFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kResolvedDepthFormat = VK_FORMAT_R32_SFLOAT;

// Attachment order in the one-sample render pass and in the organs' fragment shader's outputs.
enum AttachmentIndex : std::uint32_t {
    kColorAttachment = 0,
    kPlantAttachment,
    kOrganAttachment,
    kDepthAttachment,
    kSunAttachment,
    kAttachments
};
// Attachment order in the multisampled render pass: the samples (in the organs' outputs' order, then depth), then
// the resolved pixels (in the resolve shader's outputs' order).
enum SampledAttachmentIndex : std::uint32_t {
    kColorSamples = 0,
    kIdSamples,
    kSunSamples,
    kDepthSamples,
    kResolvedColor,
    kResolvedPlant,
    kResolvedOrgan,
    kResolvedDepth,
    kSampledAttachments
};
// The subpasses of the render pass; the resolve subpass only where there are several samples.
enum SubpassIndex : std::uint32_t { kOrganSubpass = 0, kSunlitSubpass, kResolveSubpass };

// Throws VulkanError when the device cannot render into the formats above.
void checkRenderFormats(const vk::Context& context);

// The sample counts the device draws a frame with, as VkSampleCountFlags (1 always).
VkSampleCountFlags drawableSampleCounts(const vk::Context& context);
// The samples a pixel a frame is drawn with where none were asked for: 4 where the device draws them (Vulkan
// asks it of every device that draws colour and depth), else 1.
std::uint32_t defaultSamples(const vk::Context& context);
// The same for frames drawn while a field grows live (the viewer): 1 on a CPU device, where each sample costs about
// as much as a pixel.
std::uint32_t interactiveSamples(const vk::Context& context);
// Throws std::invalid_argument, naming the counts the device has, when it cannot draw `samples` samples a pixel.
void checkSamples(const vk::Context& context, std::uint32_t samples);
// The same two from the counts drawableSampleCounts() gave, for a caller that asks at every frame (the device's
// properties are queried once).
std::uint32_t defaultSamples(VkSampleCountFlags drawable);
void checkSamples(VkSampleCountFlags drawable, std::uint32_t samples, std::string_view device);

UniqueRenderPass createRenderPass(const vk::Context& context, std::uint32_t samples = 1);

} // namespace simeco::draw
