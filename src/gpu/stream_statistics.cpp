#include "gpu/stream_statistics.h"

#include <algorithm>
#include <cstring>
#include <stdexcept>
#include <vector>

#include "compute/shared/statistics_layout.h"
#include "vk/barriers.h"
#include "vk/context.h"

namespace simeco::gpu {

using shared::kStatisticsChunk;

StreamStatistics::StreamStatistics(const vk::Context& context)
    : context_(context), kernel_(vk::ComputePipeline::embedded(context, "stream/statistics")) {}

void StreamStatistics::record(VkCommandBuffer cmd, const stream::DeviceModules& modules, std::uint32_t symbols) {
    std::uint32_t chunks = (modules.count + kStatisticsChunk - 1) / kStatisticsChunk;
    if (!counts_ || symbols > symbols_) {
        symbols_ = std::max<std::uint32_t>(symbols, 1);
        counts_ = vk::Buffer(context_, 4ull * symbols_, vk::MemoryUsage::DeviceLocal);
        countsRead_ = vk::Buffer(context_, 4ull * symbols_, vk::MemoryUsage::Readback);
    }
    if (!summaries_ || chunks > chunks_) {
        chunks_ = std::max<std::uint32_t>(chunks, 1);
        summaries_ = vk::Buffer(context_, sizeof(shared::DepthSummary) * chunks_, vk::MemoryUsage::DeviceLocal);
        summariesRead_ = vk::Buffer(context_, sizeof(shared::DepthSummary) * chunks_, vk::MemoryUsage::Readback);
    }
    modules_ = modules.count;
    plants_ = modules.plants;
    // The stream may come from passes recorded just before.
    vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
    vk::cmdFill(cmd, counts_, 0);
    vk::memoryBarrier(cmd, vk::Hazard::TransferToCompute);
    if (chunks > 0) {
        shared::StatisticsPush push{modules.count, symbols, chunks, 0};
        kernel_.dispatch(cmd, {*modules.symbols, counts_, summaries_}, push, kernel_.groupsFor(chunks));
    }
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToTransfer);
    VkBufferCopy countsCopy{0, 0, 4ull * symbols};
    vkCmdCopyBuffer(cmd, counts_.handle(), countsRead_.handle(), 1, &countsCopy);
    if (chunks > 0) {
        VkBufferCopy summariesCopy{0, 0, sizeof(shared::DepthSummary) * chunks};
        vkCmdCopyBuffer(cmd, summaries_.handle(), summariesRead_.handle(), 1, &summariesCopy);
    }
    vk::memoryBarrier(cmd, vk::Hazard::TransferToHost);
}

stream::StringStatistics StreamStatistics::read(const ir::Alphabet& alphabet) const {
    if (alphabet.size() > symbols_) throw std::logic_error("StreamStatistics::read: a larger alphabet than counted");
    stream::StringStatistics stats;
    stats.modules = modules_;
    stats.plants = plants_;
    const auto* counts = reinterpret_cast<const std::uint32_t*>(countsRead_.mapped());
    for (std::uint32_t s = 0; s < alphabet.size(); ++s)
        if (counts[s] != 0) stats.perSymbol[alphabet.name(static_cast<ir::SymbolId>(s))] = counts[s];
    // The chunks' walks composed in order from depth 0 (statistics_layout.h), as the CPU reference walks them.
    const auto* summaries = reinterpret_cast<const shared::DepthSummary*>(summariesRead_.mapped());
    std::uint32_t chunks = (modules_ + kStatisticsChunk - 1) / kStatisticsChunk;
    std::int64_t depth = 0, deepest = 0;
    for (std::uint32_t k = 0; k < chunks; ++k) {
        const shared::DepthSummary& w = summaries[k];
        deepest = std::max({deepest, depth + w.c, std::int64_t{w.e}});
        depth = std::max(depth + w.a, std::int64_t{w.b});
    }
    stats.maxBranchDepth = static_cast<int>(deepest);
    return stats;
}

stream::StringStatistics StreamStatistics::compute(const stream::DeviceModules& modules, const ir::Alphabet& alphabet) {
    context_.submitAndWait(
        [&](VkCommandBuffer cmd) { record(cmd, modules, static_cast<std::uint32_t>(alphabet.size())); });
    return read(alphabet);
}

} // namespace simeco::gpu
