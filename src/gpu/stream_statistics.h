// The statistics `simeco derive --format stats` reports (stream::StringStatistics), computed on the device for a
// stream left there (compute/stream/statistics.comp): only the symbol counts and one summary per
// kStatisticsChunk modules come back to the host, not the string.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "ir/grammar.h"
#include "stream/device_modules.h"
#include "stream/statistics.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::vk {
class Context;
}

namespace simeco::gpu {

class StreamStatistics {
public:
    explicit StreamStatistics(const vk::Context& context);

    // Records counting the modules of `modules` (symbols below `symbols`, the alphabet's size) into this
    // object's buffers, sizing them first (no earlier recording that uses them may still be pending). Ends with
    // the results copied where the host reads them, once the submission has completed.
    void record(VkCommandBuffer cmd, const stream::DeviceModules& modules, std::uint32_t symbols);
    // What the last recording found, named by `alphabet`.
    stream::StringStatistics read(const ir::Alphabet& alphabet) const;

    // Blocking convenience: record, submit, wait, read.
    stream::StringStatistics compute(const stream::DeviceModules& modules, const ir::Alphabet& alphabet);

private:
    const vk::Context& context_;
    vk::ComputePipeline kernel_;
    vk::Buffer counts_, summaries_, countsRead_, summariesRead_;
    std::uint32_t symbols_ = 0, chunks_ = 0, modules_ = 0, plants_ = 0;
};

} // namespace simeco::gpu
