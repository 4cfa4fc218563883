// The interface of a compute kernel read straight from its SPIR-V: local size, descriptor bindings,
// push-constant block size. The dispatch helper checks host calls against it.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace simeco::vk {

struct ShaderBinding {
    std::uint32_t set = 0;
    std::uint32_t binding = 0;
    VkDescriptorType type = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    // Uniform texel buffers (samplerBuffer, usamplerBuffer, isamplerBuffer): the one-channel 32-bit format the
    // dispatch views their buffer as.
    VkFormat texelFormat = VK_FORMAT_UNDEFINED;
};

struct ShaderReflection {
    std::string entryPoint;
    std::array<std::uint32_t, 3> localSize{1, 1, 1};
    std::vector<ShaderBinding> bindings;  // sorted by (set, binding)
    std::uint32_t pushConstantSize = 0;   // bytes; 0 when the kernel has no push-constant block
};

// A SPIR-V module simeco cannot use (malformed, not a compute kernel, or an unsupported resource kind).
class ShaderInterfaceError : public std::logic_error {
public:
    using std::logic_error::logic_error;
};

// Reads the first GLCompute entry point. Only buffers and uniform texel buffers are supported, which is all the
// kernels use.
ShaderReflection reflectComputeShader(std::span<const std::uint32_t> spirv);

} // namespace simeco::vk
