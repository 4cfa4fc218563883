#include "vk/pipeline.h"

#include <vector>

#include <fmt/format.h>

#include "compute/shaders.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/kernel_profile.h"
#include "vk/layouts.h"
#include "vk/vk_error.h"

namespace simeco::vk {

BufferRange::BufferRange(const Buffer& whole) : source(&whole), buffer(whole.handle()) {}

BufferRange::BufferRange(const Buffer& viewed, VkDeviceSize first, VkDeviceSize bytes)
    : source(&viewed), buffer(viewed.handle()), offset(first), size(bytes) {}

BufferRange BufferRange::viewedAs(VkFormat format) const {
    BufferRange viewed = *this;
    viewed.texelFormat = format;
    return viewed;
}

ComputePipeline::ComputePipeline(const Context& context, std::span<const std::uint32_t> spirv, std::string name,
                                 std::span<const std::uint32_t> specialization)
    : context_(&context),
      name_(std::move(name)),
      reflection_(reflectComputeShader(spirv)),
      maxGroupsX_(context.limits().maxComputeWorkGroupCount[0]),
      maxGroupsY_(context.limits().maxComputeWorkGroupCount[1]),
      maxTexelElements_(context.limits().maxTexelBufferElements),
      cmdPushDescriptorSet_(context.cmdPushDescriptorSet()) {
    if (reflection_.pushConstantSize > context.limits().maxPushConstantsSize) {
        throw VulkanError(fmt::format("kernel {} needs {} bytes of push constants; the device allows {}", name_,
                                      reflection_.pushConstantSize, context.limits().maxPushConstantsSize),
                          VK_ERROR_FEATURE_NOT_PRESENT);
    }
    for (const ShaderBinding& b : reflection_.bindings) {
        if (b.set != 0) {
            throw ShaderInterfaceError(fmt::format("kernel {}: binding {} is in set {}; push descriptors use set 0 only",
                                                   name_, b.binding, b.set));
        }
    }
    compiled_ = context.kernelCache().get(spirv, specialization,
                                          [&] { return compile(context, spirv, specialization); });
}

std::shared_ptr<const CompiledKernel> ComputePipeline::compile(const Context& context,
                                                               std::span<const std::uint32_t> spirv,
                                                               std::span<const std::uint32_t> specialization) const {
    VkDevice device = context.device();
    auto kernel = std::make_shared<CompiledKernel>();
    std::vector<VkDescriptorSetLayoutBinding> bindings;
    for (const ShaderBinding& b : reflection_.bindings)
        bindings.push_back({b.binding, b.type, 1, VK_SHADER_STAGE_COMPUTE_BIT, nullptr});
    kernel->setLayout = createPushDescriptorSetLayout(device, bindings);
    std::optional<VkPushConstantRange> pushRange;
    if (reflection_.pushConstantSize > 0) pushRange = {VK_SHADER_STAGE_COMPUTE_BIT, 0, reflection_.pushConstantSize};
    kernel->layout = createPipelineLayout(device, kernel->setLayout.get(), pushRange);

    VkShaderModuleCreateInfo moduleInfo{};

    moduleInfo.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    moduleInfo.codeSize = spirv.size_bytes();
    moduleInfo.pCode = spirv.data();
    VkShaderModule rawModule = VK_NULL_HANDLE;
    VK_CHECK(vkCreateShaderModule(device, &moduleInfo, nullptr, &rawModule));
    UniqueShaderModule module(device, rawModule);  // only needed until the pipeline exists

    VkComputePipelineCreateInfo pipelineInfo{};

    pipelineInfo.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO;
    pipelineInfo.stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    pipelineInfo.stage.stage = VK_SHADER_STAGE_COMPUTE_BIT;
    pipelineInfo.stage.module = rawModule;
    pipelineInfo.stage.pName = reflection_.entryPoint.c_str();
    std::vector<VkSpecializationMapEntry> entries;
    for (std::uint32_t id = 0; id < specialization.size(); ++id)
        entries.push_back({id, id * std::uint32_t(sizeof(std::uint32_t)), sizeof(std::uint32_t)});
    VkSpecializationInfo specializationInfo{static_cast<std::uint32_t>(entries.size()), entries.data(),
                                           specialization.size_bytes(), specialization.data()};
    if (!specialization.empty()) pipelineInfo.stage.pSpecializationInfo = &specializationInfo;
    pipelineInfo.layout = kernel->layout.get();
    VkPipeline pipeline = VK_NULL_HANDLE;
    VK_CHECK(vkCreateComputePipelines(device, VK_NULL_HANDLE, 1, &pipelineInfo, nullptr, &pipeline));
    kernel->pipeline = UniquePipeline(device, pipeline);
    return kernel;
}

ComputePipeline ComputePipeline::embedded(const Context& context, std::string_view name,
                                          std::span<const std::uint32_t> specialization) {
    return ComputePipeline(context, shaders::spirv(name), std::string(name), specialization);
}

VkBufferView ComputePipeline::texelView(const BufferRange& range, VkFormat format) const {
    if (!range.source)
        throw DispatchMismatch(fmt::format("kernel {}: a texel buffer binding needs a vk::Buffer to view", name_));
    // The whole range in texels of 4 bytes a component, as many as the device lets one view hold; the callers
    // size the buffers their kernels read as texels within that.
    VkDeviceSize texelBytes = format == VK_FORMAT_R32G32B32A32_SFLOAT || format == VK_FORMAT_R32G32B32A32_UINT ? 16
                              : format == VK_FORMAT_R32G32_SFLOAT || format == VK_FORMAT_R32G32_UINT     ? 8
                                                                                                        : 4;
    VkDeviceSize available = range.source->size() - range.offset;
    VkDeviceSize bytes = range.size == VK_WHOLE_SIZE ? available : std::min(range.size, available);
    bytes = std::min<VkDeviceSize>(bytes, VkDeviceSize{maxTexelElements_} * texelBytes) / texelBytes * texelBytes;
    return range.source->texelView(format, range.offset, std::max<VkDeviceSize>(bytes, texelBytes));
}

std::uint64_t ComputePipeline::groupsFor(std::uint64_t items, std::uint32_t itemsPerInvocation) const {
    std::uint64_t perGroup = std::uint64_t{reflection_.localSize[0]} * reflection_.localSize[1] *
                             reflection_.localSize[2] * itemsPerInvocation;
    return (items + perGroup - 1) / perGroup;
}

void ComputePipeline::checkInterface(std::span<const BufferRange> buffers, std::span<const std::byte> push) const {
    if (push.size() != reflection_.pushConstantSize) {
        throw DispatchMismatch(fmt::format("kernel {}: push constants are {} bytes on the host but {} in the shader",
                                           name_, push.size(), reflection_.pushConstantSize));
    }
    if (buffers.size() != reflection_.bindings.size()) {
        throw DispatchMismatch(fmt::format("kernel {}: {} buffers given, the shader declares {} bindings", name_,
                                           buffers.size(), reflection_.bindings.size()));
    }
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        if (reflection_.bindings[i].binding != i) {
            throw DispatchMismatch(fmt::format("kernel {}: bindings must be numbered 0..{} (found binding {})", name_,
                                               buffers.size() - 1, reflection_.bindings[i].binding));
        }
        if (buffers[i].buffer == VK_NULL_HANDLE) {
            throw DispatchMismatch(fmt::format("kernel {}: buffer for binding {} is empty", name_, i));
        }
    }
}

void ComputePipeline::bind(VkCommandBuffer cmd, std::span<const BufferRange> buffers,
                           std::span<const std::byte> push) const {
    std::vector<VkDescriptorBufferInfo> infos(buffers.size());
    std::vector<VkBufferView> views(buffers.size(), VK_NULL_HANDLE);
    std::vector<VkWriteDescriptorSet> writes(buffers.size());
    for (std::size_t i = 0; i < buffers.size(); ++i) {
        VkDeviceSize bytes = buffers[i].size;
        if (bytes == VK_WHOLE_SIZE && buffers[i].source && buffers[i].source->size() > buffers[i].offset)
            bytes = buffers[i].source->bindingRange() - buffers[i].offset;
        infos[i] = {buffers[i].buffer, buffers[i].offset, bytes};
        writes[i].sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
        writes[i].dstBinding = static_cast<std::uint32_t>(i);
        writes[i].descriptorCount = 1;
        writes[i].descriptorType = reflection_.bindings[i].type;
        writes[i].pBufferInfo = &infos[i];
        if (reflection_.bindings[i].type == VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER) {
            VkFormat format = buffers[i].texelFormat != VK_FORMAT_UNDEFINED ? buffers[i].texelFormat
                                                                            : reflection_.bindings[i].texelFormat;
            views[i] = texelView(buffers[i], format);
            writes[i].pBufferInfo = nullptr;
            writes[i].pTexelBufferView = &views[i];
        }
    }
    vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compiled_->pipeline.get());
    if (!writes.empty()) {
        cmdPushDescriptorSet_(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, compiled_->layout.get(), 0,
                              static_cast<std::uint32_t>(writes.size()), writes.data());
    }
    if (!push.empty()) {
        vkCmdPushConstants(cmd, compiled_->layout.get(), VK_SHADER_STAGE_COMPUTE_BIT, 0,
                           static_cast<std::uint32_t>(push.size()), push.data());
    }
}

void ComputePipeline::dispatchBytes(VkCommandBuffer cmd, std::span<const BufferRange> buffers,
                                    std::span<const std::byte> push, std::uint64_t groups) const {
    // Every check comes before the first recorded command, so a mismatch leaves the command buffer untouched.
    checkInterface(buffers, push);
    std::uint64_t groupsY = (groups + maxGroupsX_ - 1) / maxGroupsX_;
    if (groupsY > maxGroupsY_) {
        throw VulkanError(fmt::format("kernel {}: {} workgroups exceed the device's {} x {} grid", name_, groups,
                                      maxGroupsX_, maxGroupsY_),
                          VK_ERROR_FEATURE_NOT_PRESENT);
    }
    if (groups == 0) {
        return;
    }
    std::uint64_t groupsX = (groups + groupsY - 1) / groupsY;

    bind(cmd, buffers, push);
    vkCmdDispatch(cmd, static_cast<std::uint32_t>(groupsX), static_cast<std::uint32_t>(groupsY), 1);
    if (KernelProfile* profile = context_->kernelProfile()) profile->afterDispatch(cmd, name_);
}

void ComputePipeline::dispatchIndirectBytes(VkCommandBuffer cmd, std::span<const BufferRange> buffers,
                                            std::span<const std::byte> push, const Buffer& arguments,
                                            VkDeviceSize offset) const {
    checkInterface(buffers, push);
    bind(cmd, buffers, push);
    vkCmdDispatchIndirect(cmd, arguments.handle(), offset);
    if (KernelProfile* profile = context_->kernelProfile()) profile->afterDispatch(cmd, name_);
}

} // namespace simeco::vk
