// The dispatch helper and SPIR-V reflection against the embedded scan kernels and a texel-buffer kernel.
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "codegen/glsl_compiler.h"
#include "compute/shaders.h"
#include "compute/shared/config.h"
#include "gpu_fixture.h"
#include "vk/barriers.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::test {
namespace {

using DispatchTest = GpuTest;

TEST(ShaderReflectionTest, ReadsLocalSizeBindingsAndPushConstants) {
    vk::ShaderReflection r = vk::reflectComputeShader(shaders::spirv("scan/downsweep"));
    EXPECT_EQ(r.entryPoint, "main");
    EXPECT_EQ(r.localSize[0], shared::kScanWorkgroupSize);
    EXPECT_EQ(r.localSize[1], 1u);
    EXPECT_EQ(r.localSize[2], 1u);
    ASSERT_EQ(r.bindings.size(), 4u);
    for (std::uint32_t i = 0; i < 4; ++i) {
        EXPECT_EQ(r.bindings[i].set, 0u);
        EXPECT_EQ(r.bindings[i].binding, i);
        EXPECT_EQ(r.bindings[i].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    }
    EXPECT_EQ(r.pushConstantSize, sizeof(shared::ScanDownsweepPush));
}

TEST(ShaderReflectionTest, RejectsWordsThatAreNotSpirv) {
    const std::uint32_t words[] = {0xdeadbeef, 0, 0, 0, 0};
    EXPECT_THROW(vk::reflectComputeShader(words), vk::ShaderInterfaceError);
}

TEST(EmbeddedShadersTest, UnknownNameThrows) {
    EXPECT_THROW(shaders::spirv("scan/no_such_kernel"), std::out_of_range);
}

TEST_F(DispatchTest, RejectsMismatchedPushConstantSize) {
    vk::ComputePipeline reduce = vk::ComputePipeline::embedded(context(), "scan/reduce");
    vk::Buffer a(context(), 64, vk::MemoryUsage::DeviceLocal);
    vk::Buffer b(context(), 64, vk::MemoryUsage::DeviceLocal);
    // The downsweep's push block is 16 bytes; the reduce kernel declares 8.
    shared::ScanDownsweepPush wrongPush{16, 1, 0, 0};
    context().submitAndWait([&](VkCommandBuffer cmd) {
        EXPECT_THROW(reduce.dispatch(cmd, {a, b}, wrongPush, 1), vk::DispatchMismatch);
        EXPECT_THROW(reduce.dispatch(cmd, {a, b}, 1), vk::DispatchMismatch);  // no push constants at all
    });
}

TEST_F(DispatchTest, RejectsMismatchedBindingCount) {
    vk::ComputePipeline reduce = vk::ComputePipeline::embedded(context(), "scan/reduce");
    vk::Buffer a(context(), 64, vk::MemoryUsage::DeviceLocal);
    shared::ScanReducePush push{16, 1};
    context().submitAndWait([&](VkCommandBuffer cmd) {
        EXPECT_THROW(reduce.dispatch(cmd, {a}, push, 1), vk::DispatchMismatch);
        EXPECT_THROW(reduce.dispatch(cmd, {a, a, a}, push, 1), vk::DispatchMismatch);
    });
}

TEST_F(DispatchTest, GroupCountsComeFromTheKernelsLocalSize) {
    vk::ComputePipeline reduce = vk::ComputePipeline::embedded(context(), "scan/reduce");
    EXPECT_EQ(reduce.groupsFor(0), 0u);
    EXPECT_EQ(reduce.groupsFor(1), 1u);
    EXPECT_EQ(reduce.groupsFor(shared::kScanWorkgroupSize), 1u);
    EXPECT_EQ(reduce.groupsFor(shared::kScanWorkgroupSize + 1), 2u);
    EXPECT_EQ(reduce.groupsFor(shared::kScanTileSize, shared::kScanValuesPerInvocation * shared::kScanRounds), 1u);
}

// More workgroups than the x dimension allows (65535 on lavapipe, 2^31 - 1 on NVIDIA) go out as a 2D grid;
// every workgroup index below the count must still come up exactly once. Each workgroup sets its index's bit,
// so the grid needs a bit per workgroup (256 MiB at NVIDIA's limit), not a word.
TEST_F(DispatchTest, SplitsLargeDispatchesIntoTwoDimensions) {
    const std::string index(shaders::glslSource("compute/scan/workgroup_index.glsl"));
    const std::string source = "#version 460\n" + index + R"(
layout(local_size_x = 1) in;
layout(set = 0, binding = 0, std430) buffer Seen { uint seen[]; };
layout(push_constant) uniform Push { uint groups; } pc;
void main() {
    uint group = linearWorkgroupIndex();
    if (group < pc.groups) atomicOr(seen[group >> 5u], 1u << (group & 31u));
}
)";
    vk::ComputePipeline mark(context(), codegen::compileComputeKernel(source, "test/mark_groups"), "test/mark_groups");
    const std::uint64_t groups = std::uint64_t{context().limits().maxComputeWorkGroupCount[0]} + 1000;
    ASSERT_LE(groups, std::uint64_t{UINT32_MAX});
    const std::uint64_t words = (groups + 31) / 32 + 1;  // one word past the last group stays clear
    vk::Buffer seen(context(), words * 4, vk::MemoryUsage::DeviceLocal);
    const std::uint32_t count = static_cast<std::uint32_t>(groups);
    context().submitAndWait([&](VkCommandBuffer cmd) {
        vk::cmdFill(cmd, seen, 0u);
        vk::memoryBarrier(cmd, vk::Hazard::TransferToCompute);
        mark.dispatch(cmd, {seen}, count, count);
    });
    std::vector<std::uint32_t> bits = vk::downloadVector<std::uint32_t>(context(), seen, words);
    std::uint64_t marked = 0, firstMissing = groups;
    for (std::uint64_t word = 0; word < words; ++word) {
        marked += static_cast<std::uint64_t>(std::popcount(bits[word]));
        std::uint64_t firstClear = word * 32 + static_cast<std::uint64_t>(std::countr_one(bits[word]));
        if (bits[word] != ~0u && firstClear < groups && firstMissing == groups) firstMissing = firstClear;
    }
    EXPECT_EQ(firstMissing, groups) << "workgroup " << firstMissing << " never ran";
    EXPECT_EQ(marked, groups);
}

// Uniform texel buffers: reflected with the format of their texels, and read through views of the buffer
// ranges the dispatch is given.
TEST_F(DispatchTest, ReadsUniformTexelBuffersThroughViewsOfTheGivenRanges) {
    const char* source = R"(#version 460
layout(local_size_x = 64) in;
layout(set = 0, binding = 0) uniform usamplerBuffer words;
layout(set = 0, binding = 1) uniform samplerBuffer values;
layout(set = 0, binding = 2, std430) writeonly buffer Out { float result[]; };
layout(push_constant) uniform Push { uint count; } pc;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i < pc.count) result[i] = float(texelFetch(words, int(i)).x) + texelFetch(values, int(i)).x;
}
)";
    vk::ComputePipeline kernel(context(), codegen::compileComputeKernel(source, "test/texel_read"), "test/texel_read");
    const std::vector<vk::ShaderBinding>& bindings = kernel.reflection().bindings;
    ASSERT_EQ(bindings.size(), 3u);
    EXPECT_EQ(bindings[0].type, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    EXPECT_EQ(bindings[0].texelFormat, VK_FORMAT_R32_UINT);
    EXPECT_EQ(bindings[1].type, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER);
    EXPECT_EQ(bindings[1].texelFormat, VK_FORMAT_R32_SFLOAT);
    EXPECT_EQ(bindings[2].type, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);

    constexpr std::uint32_t kCount = 100, kSkipped = 8; // the words' view starts 32 bytes in
    std::vector<std::uint32_t> words(kCount + kSkipped);
    std::vector<float> values(kCount);
    for (std::uint32_t i = 0; i < words.size(); ++i) words[i] = 1000 + i;
    for (std::uint32_t i = 0; i < kCount; ++i) values[i] = 0.5f * float(i);
    vk::Buffer wordBuffer = vk::deviceBufferWith(context(), std::span<const std::uint32_t>(words));
    vk::Buffer valueBuffer = vk::deviceBufferWith(context(), std::span<const float>(values));
    vk::Buffer result(context(), kCount * 4, vk::MemoryUsage::DeviceLocal);
    const std::uint32_t count = kCount;
    context().submitAndWait([&](VkCommandBuffer cmd) {
        kernel.dispatch(cmd, {vk::BufferRange(wordBuffer, kSkipped * 4, kCount * 4), valueBuffer, result}, count,
                        kernel.groupsFor(kCount));
    });
    std::vector<float> got = vk::downloadVector<float>(context(), result, kCount);
    for (std::uint32_t i = 0; i < kCount; ++i)
        ASSERT_EQ(got[i], float(1000 + kSkipped + i) + 0.5f * float(i)) << "at " << i;
}

// Pipelines made from the same SPIR-V and specialization on one context share one compiled pipeline (a field's
// batches each make the same kernels); another specialization, or the same kernel once none holds it, compiles
// its own; each computes as its own specialization says.
TEST_F(DispatchTest, PipelinesOfTheSameKernelAndSpecializationShareOneCompiledPipeline) {
    const char* source = R"(#version 460
layout(local_size_x = 1) in;
layout(constant_id = 0) const uint kAdded = 0;
layout(set = 0, binding = 0, std430) buffer Out { uint result[]; };
void main() { result[0] += kAdded; }
)";
    const std::vector<std::uint32_t> spirv = codegen::compileComputeKernel(source, "test/add_constant");
    const std::uint32_t three[] = {3}, five[] = {5};
    vk::Buffer result(context(), 4, vk::MemoryUsage::DeviceLocal);
    auto run = [&](const vk::ComputePipeline& kernel) {
        context().submitAndWait([&](VkCommandBuffer cmd) {
            vk::cmdFill(cmd, result, 100u);
            vk::memoryBarrier(cmd, vk::Hazard::TransferToCompute);
            kernel.dispatch(cmd, {result}, 1);
        });
        return vk::downloadVector<std::uint32_t>(context(), result, 1)[0];
    };
    {
        vk::ComputePipeline a(context(), spirv, "test/add_three", three);
        vk::ComputePipeline b(context(), spirv, "test/add_three_again", three);
        vk::ComputePipeline c(context(), spirv, "test/add_five", five);
        EXPECT_EQ(a.handle(), b.handle());
        EXPECT_NE(a.handle(), c.handle());
        EXPECT_EQ(b.name(), "test/add_three_again");
        EXPECT_EQ(run(a), 103u);
        EXPECT_EQ(run(b), 103u);
        EXPECT_EQ(run(c), 105u);
        vk::ComputePipeline moved = std::move(a);
        EXPECT_EQ(run(moved), 103u); // the first holder moved away, the second still holds the kernel
        EXPECT_EQ(moved.handle(), b.handle());
    }
    vk::ComputePipeline again(context(), spirv, "test/add_five", five);
    EXPECT_EQ(run(again), 105u);
}

} // namespace
} // namespace simeco::test
