// The offscreen frame: colour (RGBA32F), plant and organ ids (R32_UINT, cleared to 0xFFFFFFFF), depth, and
// their host-visible copies for reading back; with one sample a pixel or several (draw/render_pass.h): a
// multisampled target draws into images of samples within the render pass, and its pixels are the resolved ones.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "draw/render_pass.h"
#include "draw/vk_objects.h"
#include "vk/buffer.h"

namespace simeco::draw {

class RenderTarget {
public:
    // `renderPass` is createRenderPass(context, samples)'s.
    RenderTarget(const vk::Context& context, VkRenderPass renderPass, std::uint32_t width, std::uint32_t height,
                 std::uint32_t samples = 1);

    std::uint32_t width() const { return width_; }
    std::uint32_t height() const { return height_; }
    std::uint32_t samples() const { return samples_; }
    VkFramebuffer framebuffer() const { return framebuffer_.get(); }
    // The sun's light attachment (its samples, with their depth in alpha, in a multisampled target), which the
    // sunlit subpass reads, and the resolve subpass too.
    VkImageView sunLight() const { return sun_.view.get(); }
    // A multisampled target's colour and id samples, which the resolve subpass reads.
    VkImageView colorSamples() const { return colorSamples_.view.get(); }
    VkImageView idSamples() const { return idSamples_.view.get(); }

    // Copies every pixel attachment into its buffer; the images must be in TRANSFER_SRC_OPTIMAL (the render
    // pass's final layout). The caller orders the host or kernels reading the buffers after it.
    void cmdCopyToBuffers(VkCommandBuffer cmd) const;

    const vk::Buffer& color() const { return colorCopy_; }
    const vk::Buffer& depth() const { return depthCopy_; } // depth buffer values in [0, 1]
    const vk::Buffer& plant() const { return plantCopy_; }
    const vk::Buffer& organ() const { return organCopy_; }
    const vk::Buffer& outlined() const { return outlined_; } // toon outlines' output, same layout as color()

private:
    std::uint32_t width_ = 0;
    std::uint32_t height_ = 0;
    std::uint32_t samples_ = 1;
    // The pixels: drawn into with one sample, resolved into with several (then depth_ is kResolvedDepthFormat).
    Attachment color_;
    Attachment plant_;
    Attachment organ_;
    Attachment depth_;
    Attachment sun_;
    Attachment colorSamples_;
    Attachment idSamples_;
    Attachment depthSamples_;
    UniqueFramebuffer framebuffer_;
    vk::Buffer colorCopy_;
    vk::Buffer depthCopy_;
    vk::Buffer plantCopy_;
    vk::Buffer organCopy_;
    vk::Buffer outlined_;
};

} // namespace simeco::draw
