// Compute pipelines and the one dispatch helper every pass goes through. The helper checks the host's
// push-constant struct and buffer list against the kernel's own SPIR-V, so a C++/GLSL mismatch throws at the
// first dispatch instead of reading garbage on the GPU.
#pragma once

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <memory>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <type_traits>

#include <vulkan/vulkan.h>

#include "vk/handle.h"
#include "vk/kernel_cache.h"
#include "vk/shader_reflection.h"

namespace simeco::vk {

class Buffer;
class Context;

// The host called a kernel with a different interface than the kernel declares.
class DispatchMismatch : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

// A buffer, or a range of one, bound to the next binding of a dispatch.
struct BufferRange {
    BufferRange(const Buffer& whole);  // NOLINT(google-explicit-constructor): whole buffers read naturally
    BufferRange(const Buffer& viewed, VkDeviceSize first, VkDeviceSize bytes);

    // The same range read as texels of `format` by a uniform texel buffer binding, where the binding reads more
    // than one 32-bit component per texel: reflection gives only the texels' numeric type.
    BufferRange viewedAs(VkFormat format) const;

    const Buffer* source = nullptr; // for the views of uniform texel buffer bindings
    VkBuffer buffer = VK_NULL_HANDLE;
    VkDeviceSize offset = 0;
    VkDeviceSize size = VK_WHOLE_SIZE;
    VkFormat texelFormat = VK_FORMAT_UNDEFINED; // VK_FORMAT_UNDEFINED: one 32-bit component, as reflected
};

class ComputePipeline {
public:
    // `name` appears in error messages. Bindings go through push descriptors (set 0 only). `specialization`
    // gives the specialization constants with constant_id 0, 1, ... their values (32-bit each, VkBool32 for bools).
    // Pipelines of the same SPIR-V and specialization on one context share one compiled kernel (KernelCache).
    ComputePipeline(const Context& context, std::span<const std::uint32_t> spirv, std::string name,
                    std::span<const std::uint32_t> specialization = {});

    // A kernel compiled into simeco_shaders, e.g. embedded(context, "scan/reduce").
    static ComputePipeline embedded(const Context& context, std::string_view name,
                                    std::span<const std::uint32_t> specialization = {});

    ComputePipeline(ComputePipeline&&) noexcept = default;
    ComputePipeline& operator=(ComputePipeline&&) noexcept = default;

    const ShaderReflection& reflection() const { return reflection_; }
    const std::string& name() const { return name_; }
    VkPipeline handle() const { return compiled_->pipeline.get(); }

    // Workgroups that cover `items` when each invocation handles `itemsPerInvocation` of them (1D kernels).
    std::uint64_t groupsFor(std::uint64_t items, std::uint32_t itemsPerInvocation = 1) const;

    // Binds the buffers to bindings 0..n-1 in order, pushes `push` and dispatches `groups` workgroups.
    // More groups than the device allows along x are laid out as a 2D grid; kernels then number their group
    // gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x and return when it is past their work.
    template <typename Push>
    void dispatch(VkCommandBuffer cmd, std::initializer_list<BufferRange> buffers, const Push& push,
                  std::uint64_t groups) const {
        static_assert(std::is_trivially_copyable_v<Push>, "push constants are copied bytewise");
        dispatchBytes(cmd, std::span(buffers.begin(), buffers.size()), std::as_bytes(std::span(&push, 1)), groups);
    }

    // For kernels without push constants.
    void dispatch(VkCommandBuffer cmd, std::initializer_list<BufferRange> buffers, std::uint64_t groups) const {
        dispatchBytes(cmd, std::span(buffers.begin(), buffers.size()), {}, groups);
    }

    // The untyped form behind dispatch(), for callers whose push layout is only known at run time.
    void dispatchBytes(VkCommandBuffer cmd, std::span<const BufferRange> buffers, std::span<const std::byte> push,
                       std::uint64_t groups) const;

    // As dispatch(), with the workgroup counts (x, y, z) that an earlier kernel wrote to `arguments` at `offset`,
    // for work whose size only the device knows when the command buffer is recorded. The writer splits large
    // counts over y as dispatch() does (the kernels number their groups the same way), and a barrier
    // (Hazard::ComputeToIndirect) orders its write before this.
    template <typename Push>
    void dispatchIndirect(VkCommandBuffer cmd, std::initializer_list<BufferRange> buffers, const Push& push,
                          const Buffer& arguments, VkDeviceSize offset) const {
        static_assert(std::is_trivially_copyable_v<Push>, "push constants are copied bytewise");
        dispatchIndirectBytes(cmd, std::span(buffers.begin(), buffers.size()), std::as_bytes(std::span(&push, 1)),
                              arguments, offset);
    }
    void dispatchIndirectBytes(VkCommandBuffer cmd, std::span<const BufferRange> buffers,
                               std::span<const std::byte> push, const Buffer& arguments, VkDeviceSize offset) const;

private:
    // The layouts and pipeline of this kernel, compiled (the cache's `compile`).
    std::shared_ptr<const CompiledKernel> compile(const Context& context, std::span<const std::uint32_t> spirv,
                                                  std::span<const std::uint32_t> specialization) const;
    void checkInterface(std::span<const BufferRange> buffers, std::span<const std::byte> push) const;
    // Binds the pipeline, pushes the buffers' descriptors and the push constants.
    void bind(VkCommandBuffer cmd, std::span<const BufferRange> buffers, std::span<const std::byte> push) const;
    VkBufferView texelView(const BufferRange& range, VkFormat format) const;

    const Context* context_ = nullptr; // for its kernel profile
    std::string name_;
    ShaderReflection reflection_;
    std::uint32_t maxGroupsX_ = 0;
    std::uint32_t maxGroupsY_ = 0;
    std::uint32_t maxTexelElements_ = 0;
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet_ = nullptr;
    std::shared_ptr<const CompiledKernel> compiled_;
};

} // namespace simeco::vk
