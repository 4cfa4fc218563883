#include "draw/draw_pipelines.h"

#include <array>
#include <span>
#include <string_view>
#include <vector>

#include "compute/shaders.h"
#include "draw/render_target.h"
#include "render/shared/draw_layout.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/layouts.h"
#include "vk/vk_error.h"

namespace simeco::draw {
namespace {

enum class PassKind { Base, Volume, Sunlit };

vk::UniqueShaderModule shaderModule(VkDevice device, std::string_view name) {
    std::span<const std::uint32_t> words = shaders::spirv(name);
    VkShaderModuleCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    info.codeSize = words.size_bytes();
    info.pCode = words.data();
    VkShaderModule module = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device, &info, nullptr, &module));
    return vk::UniqueShaderModule(device, module);
}

// The base pass writes depth; shadow volumes count their faces in the stencil (Carmack's reverse); the sunlit pass
// adds the sun's light to the pixels whose stencil count is zero.
VkPipelineDepthStencilStateCreateInfo depthStencilState(PassKind pass) {
    VkPipelineDepthStencilStateCreateInfo depth{};
    depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
    depth.depthTestEnable = pass == PassKind::Sunlit ? VK_FALSE : VK_TRUE;
    depth.depthWriteEnable = pass == PassKind::Base ? VK_TRUE : VK_FALSE;
    depth.depthCompareOp = VK_COMPARE_OP_LESS;
    if (pass == PassKind::Volume) {
        // Carmack's reverse: count the volume faces behind the visible surface, back faces up, front faces down.
        depth.stencilTestEnable = VK_TRUE;
        depth.front = {VK_STENCIL_OP_KEEP,
                       VK_STENCIL_OP_KEEP,
                       VK_STENCIL_OP_DECREMENT_AND_WRAP,
                       VK_COMPARE_OP_ALWAYS,
                       0xFF,
                       0xFF,
                       0};
        depth.back = {VK_STENCIL_OP_KEEP,
                      VK_STENCIL_OP_KEEP,
                      VK_STENCIL_OP_INCREMENT_AND_WRAP,
                      VK_COMPARE_OP_ALWAYS,
                      0xFF,
                      0xFF,
                      0};
    } else if (pass == PassKind::Sunlit) {
        depth.stencilTestEnable = VK_TRUE;
        depth.front = {VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_STENCIL_OP_KEEP, VK_COMPARE_OP_EQUAL, 0xFF, 0, 0};
        depth.back = depth.front;
    }
    return depth;
}

// The base pass writes its four colour attachments (colour, ids, the sun's light); volumes write none; the sunlit
// pass, in the next subpass, adds the sun's light to the colour, its only attachment.
std::vector<VkPipelineColorBlendAttachmentState> colorBlendAttachments(PassKind pass) {
    const VkColorComponentFlags all =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    std::vector<VkPipelineColorBlendAttachmentState> blend(pass == PassKind::Sunlit ? 1 : 4);
    for (VkPipelineColorBlendAttachmentState& b : blend) {
        b.colorWriteMask = pass == PassKind::Base ? all : 0;
    }
    if (pass == PassKind::Sunlit) {
        VkPipelineColorBlendAttachmentState& add = blend[0];
        add.blendEnable = VK_TRUE;
        add.srcColorBlendFactor = VK_BLEND_FACTOR_ONE;
        add.dstColorBlendFactor = VK_BLEND_FACTOR_ONE;
        add.colorBlendOp = VK_BLEND_OP_ADD;
        add.srcAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        add.dstAlphaBlendFactor = VK_BLEND_FACTOR_ONE;
        add.alphaBlendOp = VK_BLEND_OP_ADD;
        add.colorWriteMask = all;
    }
    return blend;
}

vk::UniquePipeline createPipeline(VkDevice device, VkPipelineLayout layout, VkRenderPass renderPass, PassKind pass,
                                  Culling culling) {
    bool volume = pass == PassKind::Volume;
    bool sunlit = pass == PassKind::Sunlit;
    vk::UniqueShaderModule vertex = shaderModule(device, volume   ? "shadows/shadow_volume.vert"
                                                         : sunlit ? "shadows/sunlit.vert"
                                                                  : "organs/organ.vert");
    vk::UniqueShaderModule fragment;
    std::vector<VkPipelineShaderStageCreateInfo> stages(1);
    stages[0].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex.get();
    stages[0].pName = "main";
    if (!volume) { // volumes only touch the stencil
        fragment = shaderModule(device, sunlit ? "shadows/sunlit.frag" : "organs/organ.frag");
        VkPipelineShaderStageCreateInfo stage = stages[0];
        stage.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
        stage.module = fragment.get();
        stages.push_back(stage);
    }

    // Organ meshes: position and normal (MeshVertex) per vertex; volumes: their six homogeneous corners per instance.
    VkVertexInputBindingDescription binding{
        0,
        volume ? std::uint32_t(16 * shared::kVolumeVerticesPerTriangle)
               : static_cast<std::uint32_t>(sizeof(shared::MeshVertex)),
        volume ? VK_VERTEX_INPUT_RATE_INSTANCE : VK_VERTEX_INPUT_RATE_VERTEX};
    std::array<VkVertexInputAttributeDescription, shared::kVolumeVerticesPerTriangle> attributes{};
    for (std::uint32_t k = 0; k < attributes.size(); ++k)
        attributes[k] = {k, 0, VK_FORMAT_R32G32B32A32_SFLOAT, 16 * k};
    VkPipelineVertexInputStateCreateInfo vertexInput{};
    vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
    // The sunlit pass's triangle comes from its vertex indices alone.
    vertexInput.vertexBindingDescriptionCount = sunlit ? 0u : 1u;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = sunlit ? 0u : (volume ? shared::kVolumeVerticesPerTriangle : 2u);
    vertexInput.pVertexAttributeDescriptions = attributes.data();

    VkPipelineInputAssemblyStateCreateInfo assembly{};
    assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
    assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

    VkPipelineViewportStateCreateInfo viewport{};
    viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
    viewport.viewportCount = 1;
    viewport.scissorCount = 1;

    VkPipelineRasterizationStateCreateInfo raster{};
    raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
    // Volumes reach the point at infinity; clamping keeps them from being cut at the far plane.
    raster.depthClampEnable = volume ? VK_TRUE : VK_FALSE;
    raster.polygonMode = VK_POLYGON_MODE_FILL;
    raster.cullMode = culling == Culling::Back && !volume ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
    // Meshes wind counter-clockwise seen from outside. The projection's flipped y keeps the image upright, and
    // Vulkan's "counter-clockwise" is as seen in the upright image.
    raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
    raster.lineWidth = 1.0f;

    VkPipelineMultisampleStateCreateInfo multisample{};
    multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
    multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

    VkPipelineDepthStencilStateCreateInfo depth = depthStencilState(pass);
    std::vector<VkPipelineColorBlendAttachmentState> blend = colorBlendAttachments(pass);
    VkPipelineColorBlendStateCreateInfo colorBlend{};
    colorBlend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
    colorBlend.attachmentCount = static_cast<std::uint32_t>(blend.size());
    colorBlend.pAttachments = blend.data();

    std::array<VkDynamicState, 2> dynamicStates{VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dynamic{};
    dynamic.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
    dynamic.dynamicStateCount = static_cast<std::uint32_t>(dynamicStates.size());
    dynamic.pDynamicStates = dynamicStates.data();

    VkGraphicsPipelineCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
    info.stageCount = static_cast<std::uint32_t>(stages.size());
    info.pStages = stages.data();
    info.pVertexInputState = &vertexInput;
    info.pInputAssemblyState = &assembly;
    info.pViewportState = &viewport;
    info.pRasterizationState = &raster;
    info.pMultisampleState = &multisample;
    info.pDepthStencilState = &depth;
    info.pColorBlendState = &colorBlend;
    info.pDynamicState = &dynamic;
    info.layout = layout;
    info.renderPass = renderPass;
    info.subpass = sunlit ? kSunlitSubpass : kOrganSubpass;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    return vk::UniquePipeline(device, pipeline);
}

} // namespace

DrawPipelines::DrawPipelines(const vk::Context& context, VkRenderPass renderPass)
    : cmdPushDescriptorSet_(context.cmdPushDescriptorSet()) {
    VkDevice device = context.device();
    std::array<VkDescriptorSetLayoutBinding, 5> bindings{{
        {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
        {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
        {4, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
    }};
    setLayout_ = vk::createPushDescriptorSetLayout(device, bindings);
    layout_ = vk::createPipelineLayout(device, setLayout_.get(),
                                       VkPushConstantRange{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                                           0, sizeof(shared::DrawPush)});
    VkPipelineLayout layout = layout_.get();

    base_ = createPipeline(device, layout, renderPass, PassKind::Base, Culling::None);
    baseCulled_ = createPipeline(device, layout, renderPass, PassKind::Base, Culling::Back);
    sunlit_ = createPipeline(device, layout, renderPass, PassKind::Sunlit, Culling::None);
    volume_ = createPipeline(device, layout, renderPass, PassKind::Volume, Culling::None);
}

void DrawPipelines::pushDescriptors(VkCommandBuffer cmd, const vk::Buffer& instances,
                                    const vk::Buffer& frameConstants, const VkDescriptorImageInfo& textures,
                                    const vk::Buffer& order) const {
    std::array<VkDescriptorBufferInfo, 4> infos{{
        {instances.handle(), 0, instances.bindingRange()},
        {frameConstants.handle(), 0, frameConstants.bindingRange()},
        {},
        {order.handle(), 0, order.bindingRange()},
    }};
    std::array<VkWriteDescriptorSet, 4> writes{};
    for (std::uint32_t i = 0; i < writes.size(); ++i) {
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstBinding = i;
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = i == 1   ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER
                                   : i == 2 ? VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER
                                            : VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
        if (i == 2) writes[i].pImageInfo = &textures;
        else writes[i].pBufferInfo = &infos[i];
    }
    cmdPushDescriptorSet_(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0,
                          static_cast<std::uint32_t>(writes.size()), writes.data());
}

void DrawPipelines::pushSunLight(VkCommandBuffer cmd, VkImageView sunLight) const {
    VkDescriptorImageInfo image{VK_NULL_HANDLE, sunLight, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstBinding = 4;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
    write.pImageInfo = &image;
    cmdPushDescriptorSet_(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0, 1, &write);
}

} // namespace simeco::draw
