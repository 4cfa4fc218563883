// The graphics pipelines of a frame. All share one layout — push descriptors for the instance buffer
// (binding 0) and the DrawFrame uniform block (binding 1), and DrawPush constants — so the descriptors are
// pushed once per frame.
//
//   base    depth LESS with writes, all attachments written (the lit pass, or the ambient pass before shadows)
//   volume  shadow volumes: no colour or depth writes, depth clamp, z-fail stencil counting on both faces
//   sun     depth EQUAL, stencil EQUAL 0, colour added, ids kept (the sun where no volume covers a point)
#pragma once

#include <vulkan/vulkan.h>

#include "draw/vk_objects.h"
#include "vk/handle.h"

namespace simeco::vk {
class Buffer;
class Context;
} // namespace simeco::vk

namespace simeco::draw {

enum class Culling {
    Back, // closed meshes (stems, spheres)
    None, // single sheets (leaves, discs, triangles, the ground)
};

class DrawPipelines {
public:
    DrawPipelines(const vk::Context& context, VkRenderPass renderPass);

    VkPipelineLayout layout() const { return layout_.get(); }
    VkPipeline base(Culling culling) const { return culling == Culling::Back ? baseCulled_.get() : base_.get(); }
    VkPipeline sun(Culling culling) const { return culling == Culling::Back ? sunCulled_.get() : sun_.get(); }
    VkPipeline volume() const { return volume_.get(); }

    // The organs' instances, the frame's constants, the textures (draw::TextureArray) and the frame's order of the
    // instances by draw list (organs/draw_lists.comp) for the draws after it.
    void pushDescriptors(VkCommandBuffer cmd, const vk::Buffer& instances, const vk::Buffer& frameConstants,
                         const VkDescriptorImageInfo& textures, const vk::Buffer& order) const;

private:
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet_ = nullptr;
    vk::UniqueDescriptorSetLayout setLayout_;
    vk::UniquePipelineLayout layout_;
    vk::UniquePipeline base_;
    vk::UniquePipeline baseCulled_;
    vk::UniquePipeline sun_;
    vk::UniquePipeline sunCulled_;
    vk::UniquePipeline volume_;
};

} // namespace simeco::draw
