// The graphics pipelines of a frame, for a render pass of one sample a pixel or several (draw/render_pass.h). All
// share one layout — push descriptors for the instance buffer (binding 0), the DrawFrame uniform block (binding 1),
// the textures (2), the draw lists' order (3) and the input attachments (4: the sun's light; 5 and 6: a
// multisampled frame's colour and id samples), and DrawPush constants — so the descriptors are pushed once per
// frame.
//
//   base     depth LESS with writes, all attachments written (the lit pass, or before shadows the ambient colour,
//            ids and the sun's light)
//   volume   shadow volumes: no colour or depth writes, depth clamp, z-fail stencil counting on both faces
//   sunlit   the second subpass: a full-frame triangle, stencil EQUAL 0, the sun's light added to the colour (per
//            sample where there are several)
//   resolve  with several samples, the third subpass: a full-frame triangle writing each pixel from its samples
#pragma once

#include <cstdint>
#include <span>

#include <vulkan/vulkan.h>

#include "draw/vk_objects.h"
#include "vk/handle.h"

namespace simeco::vk {
class Buffer;
class Context;
} // namespace simeco::vk

namespace simeco::draw {

class RenderTarget;

enum class Culling {
    Back, // closed meshes (stems, spheres)
    None, // single sheets (leaves, discs, triangles, the ground)
};

class DrawPipelines {
public:
    // `renderPass` is createRenderPass(context, samples)'s.
    DrawPipelines(const vk::Context& context, VkRenderPass renderPass, std::uint32_t samples = 1);

    VkPipelineLayout layout() const { return layout_.get(); }
    VkPipeline base(Culling culling) const { return culling == Culling::Back ? baseCulled_.get() : base_.get(); }
    // The sunlit pass (the render pass's second subpass): the sun's light added where the stencil is clear.
    VkPipeline sunlit() const { return sunlit_.get(); }
    VkPipeline volume() const { return volume_.get(); }
    // The resolve subpass of a multisampled render pass (none with one sample).
    VkPipeline resolve() const { return resolve_.get(); }

    // The organs' instances, the frame's constants, the textures (draw::TextureArray) and the frame's order of the
    // instances by draw list (organs/draw_lists.comp) for the draws after it.
    void pushDescriptors(VkCommandBuffer cmd, const vk::Buffer& instances, const vk::Buffer& frameConstants,
                         const VkDescriptorImageInfo& textures, const vk::Buffer& order) const;
    // The target's sun's light attachment for the sunlit pass.
    void pushSunLight(VkCommandBuffer cmd, const RenderTarget& target) const;
    // A multisampled target's samples for the resolve.
    void pushSamples(VkCommandBuffer cmd, const RenderTarget& target) const;

private:
    static constexpr std::uint32_t kFirstInputBinding = 4;
    void pushInputs(VkCommandBuffer cmd, std::span<const VkImageView> inputs) const;

    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet_ = nullptr;
    vk::UniqueDescriptorSetLayout setLayout_;
    vk::UniquePipelineLayout layout_;
    vk::UniquePipeline base_;
    vk::UniquePipeline baseCulled_;
    vk::UniquePipeline sunlit_;
    vk::UniquePipeline volume_;
    vk::UniquePipeline resolve_;
};

} // namespace simeco::draw
