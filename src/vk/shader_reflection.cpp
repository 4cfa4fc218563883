#include "vk/shader_reflection.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <unordered_map>

#include <fmt/format.h>

namespace simeco::vk {
namespace {

// The few SPIR-V opcodes, decorations and enums this parser understands (SPIR-V 1.6 specification, section 3).
constexpr std::uint32_t kMagic = 0x07230203;
enum Op : std::uint32_t {
    OpEntryPoint = 15,
    OpExecutionMode = 16,
    OpTypeBool = 20,
    OpTypeInt = 21,
    OpTypeFloat = 22,
    OpTypeVector = 23,
    OpTypeMatrix = 24,
    OpTypeImage = 25,
    OpTypeSampledImage = 27,
    OpTypeArray = 28,
    OpTypeRuntimeArray = 29,
    OpTypeStruct = 30,
    OpTypePointer = 32,
    OpConstant = 43,
    OpConstantComposite = 44,
    OpSpecConstant = 50,
    OpVariable = 59,
    OpDecorate = 71,
    OpMemberDecorate = 72,
    OpExecutionModeId = 331,
};
constexpr std::uint32_t kExecutionModelGLCompute = 5;
constexpr std::uint32_t kExecutionModeLocalSize = 17;
constexpr std::uint32_t kExecutionModeLocalSizeId = 38;
constexpr std::uint32_t kDecorationBufferBlock = 3;
constexpr std::uint32_t kDecorationArrayStride = 6;
constexpr std::uint32_t kDecorationBuiltIn = 11;
constexpr std::uint32_t kDecorationBinding = 33;
constexpr std::uint32_t kDecorationDescriptorSet = 34;
constexpr std::uint32_t kDecorationOffset = 35;
constexpr std::uint32_t kBuiltInWorkgroupSize = 25;
constexpr std::uint32_t kStorageUniformConstant = 0;
constexpr std::uint32_t kStorageUniform = 2;
constexpr std::uint32_t kStoragePushConstant = 9;
constexpr std::uint32_t kStorageStorageBuffer = 12;

struct Type {
    std::uint32_t opcode = 0;
    std::vector<std::uint32_t> operands;  // the words after the result id
};

struct Variable {
    std::uint32_t pointerType = 0;
    std::uint32_t storageClass = 0;
};

struct Module {
    std::unordered_map<std::uint32_t, Type> types;
    std::unordered_map<std::uint32_t, std::uint32_t> constants;  // 32-bit scalar constants
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> composites;
    std::unordered_map<std::uint32_t, Variable> variables;
    std::unordered_map<std::uint32_t, std::uint32_t> bindings, sets, arrayStrides;
    std::unordered_map<std::uint32_t, bool> bufferBlocks;
    std::unordered_map<std::uint32_t, std::unordered_map<std::uint32_t, std::uint32_t>> memberOffsets;
    std::optional<std::uint32_t> workgroupSizeBuiltIn;
    // The first GLCompute entry point, its name and its LocalSize execution mode (LocalSizeId: constants' ids).
    std::optional<std::uint32_t> entryId;
    std::string entryPoint;
    std::optional<std::array<std::uint32_t, 3>> localSize, localSizeIds;
};

std::uint32_t constant(const Module& m, std::uint32_t id) {
    auto it = m.constants.find(id);
    if (it == m.constants.end()) {
        throw ShaderInterfaceError(fmt::format("SPIR-V: id {} is not a 32-bit constant", id));
    }
    return it->second;
}

const Type& type(const Module& m, std::uint32_t id) {
    auto it = m.types.find(id);
    if (it == m.types.end()) {
        throw ShaderInterfaceError(fmt::format("SPIR-V: id {} is not a type", id));
    }
    return it->second;
}

// Bytes occupied by a value of type `id` under the explicit layout decorations of its block.
std::uint32_t sizeOf(const Module& m, std::uint32_t id) {
    const Type& t = type(m, id);
    switch (t.opcode) {
    case OpTypeBool:
        return 4;
    case OpTypeInt:
    case OpTypeFloat:
        return t.operands.at(0) / 8;
    case OpTypeVector:
    case OpTypeMatrix:
        return sizeOf(m, t.operands.at(0)) * t.operands.at(1);
    case OpTypeArray: {
        auto stride = m.arrayStrides.find(id);
        std::uint32_t element = stride != m.arrayStrides.end() ? stride->second : sizeOf(m, t.operands.at(0));
        return element * constant(m, t.operands.at(1));
    }
    case OpTypeRuntimeArray:
        return 0;  // only the fixed part of a block counts
    case OpTypeStruct: {
        std::uint32_t size = 0;
        auto offsets = m.memberOffsets.find(id);
        for (std::uint32_t member = 0; member < t.operands.size(); ++member) {
            std::uint32_t offset = 0;
            if (offsets != m.memberOffsets.end()) {
                auto it = offsets->second.find(member);
                offset = it != offsets->second.end() ? it->second : size;
            }
            size = std::max(size, offset + sizeOf(m, t.operands[member]));
        }
        return size;
    }
    default:
        throw ShaderInterfaceError(fmt::format("SPIR-V: cannot size type with opcode {}", t.opcode));
    }
}

// A uniform texel buffer: a sampled image of dimension Buffer over 32-bit integers or floats.
ShaderBinding texelBufferBinding(const Module& m, std::uint32_t id, const Type& sampledImage) {
    constexpr std::uint32_t kDimBuffer = 5;
    const Type* image = sampledImage.opcode == OpTypeSampledImage ? &type(m, sampledImage.operands.at(0)) : nullptr;
    // OpTypeImage operands: sampled type, dimension, depth, arrayed, multisampled, sampled (1: with a sampler).
    if (!image || image->opcode != OpTypeImage || image->operands.at(1) != kDimBuffer || image->operands.at(5) != 1)
        throw ShaderInterfaceError("kernels may bind only buffers and uniform texel buffers (found another image or a sampler)");
    const Type& texel = type(m, image->operands.at(0));
    if (texel.operands.at(0) != 32) throw ShaderInterfaceError("uniform texel buffers must hold 32-bit texels");
    ShaderBinding binding;
    binding.set = m.sets.count(id) ? m.sets.at(id) : 0;
    binding.binding = m.bindings.count(id) ? m.bindings.at(id) : 0;
    binding.type = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;
    binding.texelFormat = texel.opcode == OpTypeFloat ? VK_FORMAT_R32_SFLOAT
                          : texel.operands.at(1) != 0 ? VK_FORMAT_R32_SINT
                                                      : VK_FORMAT_R32_UINT;
    return binding;
}

void decorate(Module& m, std::span<const std::uint32_t> ops) {
    switch (ops[1]) {
    case kDecorationBinding:
        m.bindings[ops[0]] = ops[2];
        break;
    case kDecorationDescriptorSet:
        m.sets[ops[0]] = ops[2];
        break;
    case kDecorationArrayStride:
        m.arrayStrides[ops[0]] = ops[2];
        break;
    case kDecorationBufferBlock:
        m.bufferBlocks[ops[0]] = true;
        break;
    case kDecorationBuiltIn:
        if (ops[2] == kBuiltInWorkgroupSize) {
            m.workgroupSizeBuiltIn = ops[0];
        }
        break;
    default:
        break;
    }
}

// One instruction's part of the interface: entry point, execution mode, types, constants, variables, decorations.
void readInstruction(Module& m, std::uint32_t opcode, std::span<const std::uint32_t> ops) {
    switch (opcode) {
    case OpEntryPoint:
        if (!m.entryId && ops[0] == kExecutionModelGLCompute) {
            m.entryId = ops[1];
            m.entryPoint = reinterpret_cast<const char*>(&ops[2]);
        }
        break;
    case OpExecutionMode:
    case OpExecutionModeId:
        if (m.entryId && ops[0] == *m.entryId && ops[1] == kExecutionModeLocalSize) {
            m.localSize = std::array<std::uint32_t, 3>{ops[2], ops[3], ops[4]};
        } else if (m.entryId && ops[0] == *m.entryId && ops[1] == kExecutionModeLocalSizeId) {
            m.localSizeIds = std::array<std::uint32_t, 3>{ops[2], ops[3], ops[4]};
        }
        break;
    case OpTypeBool:
    case OpTypeInt:
    case OpTypeFloat:
    case OpTypeVector:
    case OpTypeMatrix:
    case OpTypeArray:
    case OpTypeRuntimeArray:
    case OpTypeStruct:
    case OpTypePointer:
    case OpTypeImage:
    case OpTypeSampledImage:
        m.types[ops[0]] = Type{opcode, std::vector<std::uint32_t>(ops.begin() + 1, ops.end())};
        break;
    case OpConstant:
    case OpSpecConstant:
        // Specialization constants keep their default here: simeco's kernels do not specialise sizes.
        m.constants[ops[1]] = ops[2];
        break;
    case OpConstantComposite:
        m.composites[ops[1]] = std::vector<std::uint32_t>(ops.begin() + 2, ops.end());
        break;
    case OpVariable:
        m.variables[ops[1]] = Variable{ops[0], ops[2]};
        break;
    case OpDecorate:
        decorate(m, ops);
        break;
    case OpMemberDecorate:
        if (ops[2] == kDecorationOffset) {
            m.memberOffsets[ops[0]][ops[1]] = ops[3];
        }
        break;
    default:
        break;
    }
}

Module readModule(std::span<const std::uint32_t> spirv) {
    if (spirv.size() < 5 || spirv[0] != kMagic) {
        throw ShaderInterfaceError("not a SPIR-V module (bad magic number)");
    }
    Module m;
    for (std::size_t at = 5; at < spirv.size();) {
        std::uint32_t wordCount = spirv[at] >> 16;
        std::uint32_t opcode = spirv[at] & 0xffff;
        if (wordCount == 0 || at + wordCount > spirv.size()) {
            throw ShaderInterfaceError(fmt::format("SPIR-V: malformed instruction at word {}", at));
        }
        readInstruction(m, opcode, spirv.subspan(at + 1, wordCount - 1));
        at += wordCount;
    }
    if (!m.entryId) {
        throw ShaderInterfaceError("SPIR-V module has no GLCompute entry point");
    }
    return m;
}

// Precedence as in the Vulkan spec: a WorkgroupSize built-in overrides the execution mode.
std::array<std::uint32_t, 3> localSizeOf(const Module& m) {
    std::array<std::uint32_t, 3> size{1, 1, 1};
    if (m.workgroupSizeBuiltIn) {
        auto it = m.composites.find(*m.workgroupSizeBuiltIn);
        if (it == m.composites.end() || it->second.size() != 3) {
            throw ShaderInterfaceError("SPIR-V: WorkgroupSize built-in is not a 3-component constant");
        }
        for (int i = 0; i < 3; ++i) {
            size[i] = constant(m, it->second[i]);
        }
    } else if (m.localSizeIds) {
        for (int i = 0; i < 3; ++i) {
            size[i] = constant(m, (*m.localSizeIds)[i]);
        }
    } else if (m.localSize) {
        size = *m.localSize;
    }
    return size;
}

// The descriptors the kernel binds, by set and binding, and the size of its push-constant block.
void readInterface(const Module& m, ShaderReflection& reflection) {
    for (const auto& [id, variable] : m.variables) {
        const Type& pointer = type(m, variable.pointerType);
        std::uint32_t pointee = pointer.operands.at(1);
        // Arrays of descriptors are not used by simeco; the block type is what matters.
        const Type* block = &type(m, pointee);
        if (variable.storageClass == kStoragePushConstant) {
            reflection.pushConstantSize = sizeOf(m, pointee);
            continue;
        }
        if (variable.storageClass == kStorageUniformConstant) {
            reflection.bindings.push_back(texelBufferBinding(m, id, *block));
            continue;
        }
        if (variable.storageClass != kStorageStorageBuffer && variable.storageClass != kStorageUniform) {
            continue;
        }
        if (block->opcode != OpTypeStruct) {
            throw ShaderInterfaceError("arrays of buffer descriptors are not supported");
        }
        ShaderBinding binding;
        binding.set = m.sets.count(id) ? m.sets.at(id) : 0;
        binding.binding = m.bindings.count(id) ? m.bindings.at(id) : 0;
        bool storage = variable.storageClass == kStorageStorageBuffer || m.bufferBlocks.count(pointee) != 0;
        binding.type = storage ? VK_DESCRIPTOR_TYPE_STORAGE_BUFFER : VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
        reflection.bindings.push_back(binding);
    }
    std::sort(reflection.bindings.begin(), reflection.bindings.end(), [](const ShaderBinding& a, const ShaderBinding& b) {
        return a.set != b.set ? a.set < b.set : a.binding < b.binding;
    });
}

} // namespace

ShaderReflection reflectComputeShader(std::span<const std::uint32_t> spirv) {
    Module m = readModule(spirv);
    ShaderReflection reflection;
    reflection.entryPoint = m.entryPoint;
    reflection.localSize = localSizeOf(m);
    readInterface(m, reflection);
    return reflection;
}

} // namespace simeco::vk
