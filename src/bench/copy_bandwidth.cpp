#include "bench/copy_bandwidth.h"

#include <algorithm>
#include <cstdint>
#include <optional>

#include "bench/timing.h"
#include "vk/barriers.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/timestamps.h"

namespace simeco::bench {
namespace {

struct CopyPush {
    std::uint32_t count;         // uvec4 elements
    std::uint32_t perInvocation; // uvec4 elements per invocation
};

constexpr std::uint64_t kElementBytes = 16; // one uvec4
constexpr std::uint32_t kElementsPerInvocation = 16;

} // namespace

CopyBandwidth measureCopyBandwidth(const vk::Context& context, int warmUp, int repeat) {
    CopyBandwidth result;
    result.limitBytes = context.limits().maxStorageBufferRange;
    std::uint64_t bytes = std::min<std::uint64_t>(kCopyBufferBytes, result.limitBytes);
    bytes = bytes / kElementBytes * kElementBytes;
    result.bufferBytes = bytes;

    vk::Buffer source(context, bytes, vk::MemoryUsage::DeviceLocal);
    vk::Buffer destination(context, bytes, vk::MemoryUsage::DeviceLocal);
    // Touch both buffers once, so that no run pays for first-use page faults (lavapipe's memory is host memory).
    context.submitAndWait([&](VkCommandBuffer cmd) {
        vk::cmdFill(cmd, source, 0x5eedc0deu);
        vk::cmdFill(cmd, destination, 0);
    });

    auto push = CopyPush{static_cast<std::uint32_t>(bytes / kElementBytes), kElementsPerInvocation};
    std::optional<vk::Timestamps> timestamps;
    if (context.timestampValidBits() != 0) {
        timestamps.emplace(context, 2);
    }
    result.timestamps = timestamps.has_value();
    auto runs = [&](const vk::ComputePipeline& copy) {
        std::uint64_t groups = copy.groupsFor(push.count, push.perInvocation);
        return repeatRuns(warmUp, repeat, [&] {
            Clock::time_point start = Clock::now();
            context.submitAndWait([&](VkCommandBuffer cmd) {
                if (timestamps) {
                    timestamps->cmdReset(cmd);
                }
                vk::memoryBarrier(cmd, vk::Hazard::TransferToCompute);
                if (timestamps) {
                    timestamps->cmdWrite(cmd, 0, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
                }
                copy.dispatch(cmd, {source, destination}, push, groups);
                if (timestamps) {
                    timestamps->cmdWrite(cmd, 1, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
                }
            });
            return timestamps ? timestamps->elapsedNs(0, 1) * 1e-6 : secondsSince(start) * 1e3;
        });
    };
    auto rate = [&](const std::vector<double>& millis) {
        double m = median(millis);
        return m > 0 ? 2.0 * static_cast<double>(bytes) / (m * 1e-3) : 0.0;
    };
    std::vector<double> storage = runs(vk::ComputePipeline::embedded(context, "bench/copy"));
    // Devices whose texel buffers hold fewer elements than the copy get the storage kernel's figure alone.
    std::vector<double> texel;
    if (bytes / 4 <= context.limits().maxTexelBufferElements)
        texel = runs(vk::ComputePipeline::embedded(context, "bench/copy_texel"));
    bool texelFaster = !texel.empty() && rate(texel) > rate(storage);
    result.kernel = texelFaster ? "texel buffer" : "storage buffer";
    result.runMillis = texelFaster ? texel : storage;
    result.otherBytesPerSecond = rate(texelFaster ? storage : texel);
    result.medianMillis = median(result.runMillis);
    result.bytesPerSecond = rate(result.runMillis);
    return result;
}

nlohmann::json copyBandwidthSummary(const CopyBandwidth& c) {
    return {{"bytes_per_second", c.bytesPerSecond},
            {"median_ms", c.medianMillis},
            {"timer", c.timestamps ? "gpu timestamps" : "host wall clock"}};
}

} // namespace simeco::bench
