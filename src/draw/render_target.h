// The offscreen frame: colour (RGBA32F), plant and organ ids (R32_UINT, cleared to 0xFFFFFFFF), depth and
// stencil (the stencil counts shadow volumes), the sun's light on the visible surfaces (RGBA32F, within the render
// pass only), the render pass that draws into them, and the host-visible buffers they are copied to for reading
// back. The render pass has two subpasses: the organs and the shadow volumes, then the sunlit pass, which adds the
// sun's light where the stencil is clear.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "draw/vk_objects.h"
#include "vk/buffer.h"

namespace simeco::draw {

inline constexpr VkFormat kColorFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kIdFormat = VK_FORMAT_R32_UINT;
// A float depth, so the copy out is the value the outline kernel and the host read, with an 8-bit stencil.
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT_S8_UINT;

// Attachment order in the render pass and in the fragment shader's outputs.
enum AttachmentIndex : std::uint32_t {
    kColorAttachment = 0,
    kPlantAttachment,
    kOrganAttachment,
    kDepthAttachment,
    kSunAttachment,
    kAttachments
};
// The subpasses of the render pass.
enum SubpassIndex : std::uint32_t { kOrganSubpass = 0, kSunlitSubpass };

// Throws VulkanError when the device cannot render into the formats above.
void checkRenderFormats(const vk::Context& context);

UniqueRenderPass createRenderPass(const vk::Context& context);

class RenderTarget {
public:
    RenderTarget(const vk::Context& context, VkRenderPass renderPass, std::uint32_t width, std::uint32_t height);

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }
    VkFramebuffer framebuffer() const { return framebuffer_.get(); }
    // The sun's light attachment, which the sunlit subpass reads.
    VkImageView sunLight() const { return sun_.view.get(); }

    // Copies every attachment into its buffer; the images must be in TRANSFER_SRC_OPTIMAL (the render pass's
    // final layout). The caller orders the host or kernels reading the buffers after it.
    void cmdCopyToBuffers(VkCommandBuffer cmd) const;

    const vk::Buffer& color() const { return colorCopy_; }
    const vk::Buffer& depth() const { return depthCopy_; } // depth buffer values in [0, 1]
    const vk::Buffer& plant() const { return plantCopy_; }
    const vk::Buffer& organ() const { return organCopy_; }
    const vk::Buffer& outlined() const { return outlined_; } // toon outlines' output, same layout as color()

private:
    std::uint32_t width_ = 0;
    std::uint32_t height_ = 0;
    Attachment color_;
    Attachment plant_;
    Attachment organ_;
    Attachment depth_;
    Attachment sun_;
    UniqueFramebuffer framebuffer_;
    vk::Buffer colorCopy_;
    vk::Buffer depthCopy_;
    vk::Buffer plantCopy_;
    vk::Buffer organCopy_;
    vk::Buffer outlined_;
};

} // namespace simeco::draw
