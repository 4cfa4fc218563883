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

enum class PassKind { Base, Volume, Sunlit, Resolve };

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
    depth.depthTestEnable = pass == PassKind::Base || pass == PassKind::Volume ? VK_TRUE : VK_FALSE;
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

// The base pass writes its colour attachments (colour, ids, the sun's light: four, or three with several samples,
// whose ids are one attachment); volumes write none; the sunlit pass, in the next subpass, adds the sun's light
// to the colour, its only attachment; the resolve writes its four (colour, plant, organ, depth).
std::vector<VkPipelineColorBlendAttachmentState> colorBlendAttachments(PassKind pass, std::uint32_t samples) {
    const VkColorComponentFlags all =
        VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT | VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
    const size_t count = pass == PassKind::Sunlit ? 1 : pass == PassKind::Resolve || samples == 1 ? 4 : 3;
    std::vector<VkPipelineColorBlendAttachmentState> blend(count);
    for (VkPipelineColorBlendAttachmentState& b : blend) {
        b.colorWriteMask = pass == PassKind::Base || pass == PassKind::Resolve ? all : 0;
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

// The fragment shader of a pass; none for volumes, which only touch the stencil.
const char* fragmentShader(PassKind pass, std::uint32_t samples) {
    switch (pass) {
    case PassKind::Base: return samples == 1 ? "organs/organ.frag" : "organs/organ_samples.frag";
    case PassKind::Sunlit: return samples == 1 ? "shadows/sunlit.frag" : "shadows/sunlit_samples.frag";
    case PassKind::Resolve: return "samples/resolve_samples.frag";
    case PassKind::Volume: break;
    }
    return nullptr;
}

vk::UniquePipeline createPipeline(VkDevice device, VkPipelineLayout layout, VkRenderPass renderPass, PassKind pass,
                                  Culling culling, std::uint32_t samples) {
    bool volume = pass == PassKind::Volume;
    // The sunlit pass and the resolve draw one full-frame triangle.
    bool fullFrame = pass == PassKind::Sunlit || pass == PassKind::Resolve;
    vk::UniqueShaderModule vertex = shaderModule(device, volume      ? "shadows/shadow_volume.vert"
                                                         : fullFrame ? "shadows/sunlit.vert"
                                                                     : "organs/organ.vert");
    vk::UniqueShaderModule fragment;
    std::vector<VkPipelineShaderStageCreateInfo> stages(1);
    stages[0].sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
    stages[0].module = vertex.get();
    stages[0].pName = "main";
    // The resolve's loop over a pixel's samples.
    const VkSpecializationMapEntry sampleCountEntry{0, 0, sizeof(std::int32_t)};
    const std::int32_t sampleCount = static_cast<std::int32_t>(samples);
    const VkSpecializationInfo sampleCountInfo{1, &sampleCountEntry, sizeof(sampleCount), &sampleCount};
    if (const char* name = fragmentShader(pass, samples)) {
        fragment = shaderModule(device, name);
        VkPipelineShaderStageCreateInfo stage = stages[0];
        stage.stage = VK_SHADER_STAGE_FRAGMENT_BIT;
        stage.module = fragment.get();
        if (pass == PassKind::Resolve) stage.pSpecializationInfo = &sampleCountInfo;
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
    // A full-frame triangle comes from its vertex indices alone.
    vertexInput.vertexBindingDescriptionCount = fullFrame ? 0u : 1u;
    vertexInput.pVertexBindingDescriptions = &binding;
    vertexInput.vertexAttributeDescriptionCount = fullFrame ? 0u : (volume ? shared::kVolumeVerticesPerTriangle : 2u);
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
    // The resolve writes the pixels, one sample each; the sunlit pass runs for every sample.
    multisample.rasterizationSamples =
        static_cast<VkSampleCountFlagBits>(pass == PassKind::Resolve ? 1u : samples);
    multisample.sampleShadingEnable = pass == PassKind::Sunlit && samples > 1 ? VK_TRUE : VK_FALSE;
    multisample.minSampleShading = 1.0f;

    VkPipelineDepthStencilStateCreateInfo depth = depthStencilState(pass);
    std::vector<VkPipelineColorBlendAttachmentState> blend = colorBlendAttachments(pass, samples);
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
    info.subpass = pass == PassKind::Sunlit    ? kSunlitSubpass
                   : pass == PassKind::Resolve ? kResolveSubpass
                                               : kOrganSubpass;
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateGraphicsPipelines(device, VK_NULL_HANDLE, 1, &info, nullptr, &pipeline));
    return vk::UniquePipeline(device, pipeline);
}

} // namespace

DrawPipelines::DrawPipelines(const vk::Context& context, VkRenderPass renderPass, std::uint32_t samples)
    : cmdPushDescriptorSet_(context.cmdPushDescriptorSet()) {
    VkDevice device = context.device();
    std::array<VkDescriptorSetLayoutBinding, 7> bindings{{
        {0, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
        {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {2, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {3, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, 1, VK_SHADER_STAGE_VERTEX_BIT, nullptr},
        {4, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {5, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
        {6, VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT, 1, VK_SHADER_STAGE_FRAGMENT_BIT, nullptr},
    }};
    setLayout_ = vk::createPushDescriptorSetLayout(device, bindings);
    layout_ = vk::createPipelineLayout(device, setLayout_.get(),
                                       VkPushConstantRange{VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT,
                                                           0, sizeof(shared::DrawPush)});
    VkPipelineLayout layout = layout_.get();

    base_ = createPipeline(device, layout, renderPass, PassKind::Base, Culling::None, samples);
    baseCulled_ = createPipeline(device, layout, renderPass, PassKind::Base, Culling::Back, samples);
    sunlit_ = createPipeline(device, layout, renderPass, PassKind::Sunlit, Culling::None, samples);
    volume_ = createPipeline(device, layout, renderPass, PassKind::Volume, Culling::None, samples);
    if (samples > 1) resolve_ = createPipeline(device, layout, renderPass, PassKind::Resolve, Culling::None, samples);
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

void DrawPipelines::pushInputs(VkCommandBuffer cmd, std::span<const VkImageView> inputs) const {
    std::vector<VkDescriptorImageInfo> images(inputs.size());
    std::vector<VkWriteDescriptorSet> writes(inputs.size());
    for (size_t i = 0; i < inputs.size(); ++i) {
        images[i] = {VK_NULL_HANDLE, inputs[i], VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstBinding = kFirstInputBinding + static_cast<std::uint32_t>(i);
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = VK_DESCRIPTOR_TYPE_INPUT_ATTACHMENT;
        writes[i].pImageInfo = &images[i];
    }
    cmdPushDescriptorSet_(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, layout_.get(), 0,
                          static_cast<std::uint32_t>(writes.size()), writes.data());
}

void DrawPipelines::pushSunLight(VkCommandBuffer cmd, const RenderTarget& target) const {
    const std::array<VkImageView, 1> inputs{target.sunLight()};
    pushInputs(cmd, inputs);
}

void DrawPipelines::pushSamples(VkCommandBuffer cmd, const RenderTarget& target) const {
    const std::array<VkImageView, 3> inputs{target.sunLight(), target.colorSamples(), target.idSamples()};
    pushInputs(cmd, inputs);
}

} // namespace simeco::draw
