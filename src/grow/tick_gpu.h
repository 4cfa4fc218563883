// The growth tick on the device: compute/grow/tick.comp over the derived string's particles, and
// compute/grow/grown_sizes.comp over the drawn string, recorded into the caller's command buffer (a blocking
// convenience beside each). The same state as the CPU reference's (grow/tick_cpu.h), which the tests compare.
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "grow/growth_tables.h"
#include "grow/tick_cpu.h"
#include "stream/device_modules.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::vk {
class Context;
}

namespace simeco::grow {

class GpuGrowth {
public:
    // The tables, each plant's DeriveTime, each plant's vigour (a factor on its growth rates; empty: 1) and where
    // each stands (which turns the light's direction into its own frame; empty: as drawn) go to the device once.
    GpuGrowth(const vk::Context& context, const GrowthTables& tables, const std::vector<float>& deriveTimes,
              const std::vector<float>& vigour = {}, const std::vector<shared::PlantPlacement>& placements = {});

    // One tick of `derived`'s particles (which it must carry), in place: the next states are written beside them
    // and copied back. `settings.tables` is not read (the device's copy is). A string counted only on the device
    // (`countOnDevice`: a derivation step recorded before in `cmd` writes it) is ticked as far as its plant table
    // counts, `count` bounding it. The buffer of next states grows to `derived`'s count here, replacing the one a
    // tick recorded before may still use: one tick of this growth in a submission.
    void recordTick(VkCommandBuffer cmd, const stream::DeviceModules& derived, const TickSettings& settings);
    // The drawn string's kGrownValue codes replaced with its particles' values, in place.
    void recordSizes(VkCommandBuffer cmd, const stream::DeviceModules& drawn, const TickSettings& settings);

    // A copy of `modules` in this growth's own buffers (valid until the next copy): what a grammar without a
    // homomorphism draws, so that its segments are shortened without touching its derived string.
    stream::DeviceModules copyForDrawing(const stream::DeviceModules& modules);
    // The same copy recorded into `cmd`: the buffers it returns hold it once the submission has run.
    stream::DeviceModules recordCopyForDrawing(VkCommandBuffer cmd, const stream::DeviceModules& modules);

    void tick(const stream::DeviceModules& derived, const TickSettings& settings);

    // New stage rows (the same tables' shape: a viewer's factors on stage properties) and plant vigours, for the
    // ticks after; waits for nothing, so the caller's submissions reading the old ones must have completed.
    void setRows(const GrowthTables& tables);
    void setVigour(const std::vector<float>& vigour);
    void growSizes(const stream::DeviceModules& drawn, const TickSettings& settings);

private:
    const vk::Context& context_;
    uint32_t symbols_, atSymbol_;
    vk::ComputePipeline tickKernel_, sizesKernel_;
    // A string counted on the device: its tick's workgroups, counted there, and the copy back.
    vk::ComputePipeline groupsKernel_, copyKernel_;
    vk::Buffer groups_;
    vk::Buffer classes_, species_, rows_, deriveTimes_, vigour_, placements_;
    vk::Buffer nextStates_; // the tick's output, copied back into the string's particles
    vk::Buffer drawnSymbols_, drawnParams_, drawnStarts_, drawnParticles_; // copyForDrawing's
};

} // namespace simeco::grow
