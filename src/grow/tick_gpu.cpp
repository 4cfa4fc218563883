#include "grow/tick_gpu.h"

#include <algorithm>
#include <span>
#include <utility>
#include <stdexcept>

#include "compute/shared/growth_layout.h"
#include "compute/shared/particle_layout.h"
#include "vk/barriers.h"
#include "vk/context.h"

namespace simeco::grow {

namespace {

shared::GrowPush growPush(const stream::DeviceModules& modules, const TickSettings& s, uint32_t symbols,
                          uint32_t atSymbol) {
    return shared::GrowPush{s.dt,    s.tick,        s.seed,         modules.plants, s.species, symbols,
                            modules.count, modules.stride, s.gravity,      atSymbol,  s.openLight,
                            s.firstPlant};
}

std::vector<float> orOnes(const std::vector<float>& values, size_t count) {
    return values.empty() ? std::vector<float>(count, 1.0f) : values;
}

std::vector<shared::PlantPlacement> orAsDrawn(const std::vector<shared::PlantPlacement>& placements, size_t count) {
    const shared::PlantPlacement asDrawn{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
    return placements.empty() ? std::vector<shared::PlantPlacement>(std::max<size_t>(count, 1), asDrawn) : placements;
}

} // namespace

GpuGrowth::GpuGrowth(const vk::Context& context, const GrowthTables& tables, const std::vector<float>& deriveTimes,
                     const std::vector<float>& vigour, const std::vector<shared::PlantPlacement>& placements)
    : context_(context), symbols_(tables.symbols), atSymbol_(tables.atSymbol),
      tickKernel_(vk::ComputePipeline::embedded(context, "grow/tick")),
      sizesKernel_(vk::ComputePipeline::embedded(context, "grow/grown_sizes")),
      groupsKernel_(vk::ComputePipeline::embedded(context, "grow/tick_groups")),
      copyKernel_(vk::ComputePipeline::embedded(context, "grow/particles_copy")),
      classes_(vk::deviceBufferWith(context, std::span<const uint32_t>(tables.classes))),
      species_(vk::deviceBufferWith(context, std::span<const uint32_t>(tables.species))),
      rows_(vk::deviceBufferWith(context, std::span<const float>(tables.rows))),
      deriveTimes_(vk::deviceBufferWith(context, std::span<const float>(deriveTimes))),
      vigour_(vk::deviceBufferWith(context, std::span<const float>(orOnes(vigour, deriveTimes.size())))),
      placements_(vk::deviceBufferWith(
          context, std::span<const shared::PlantPlacement>(orAsDrawn(placements, deriveTimes.size())))) {}

void GpuGrowth::setRows(const GrowthTables& tables) {
    rows_ = vk::deviceBufferWith(context_, std::span<const float>(tables.rows));
}

void GpuGrowth::setVigour(const std::vector<float>& vigour) {
    vigour_ = vk::deviceBufferWith(context_, std::span<const float>(orOnes(vigour, vigour_.size() / sizeof(float))));
}

void GpuGrowth::recordTick(VkCommandBuffer cmd, const stream::DeviceModules& derived, const TickSettings& settings) {
    if (!derived.particles) throw std::logic_error("GpuGrowth::recordTick: the string carries no particle state");
    if (derived.count == 0) return;
    const VkDeviceSize bytes = VkDeviceSize(derived.count) * sizeof(shared::ParticleState);
    if (!nextStates_ || nextStates_.size() < bytes)
        nextStates_ = vk::Buffer(context_, bytes + bytes / 2, vk::MemoryUsage::DeviceLocal);
    // After the passes that wrote the string (a derivation step, the last tick's copy).
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
    const std::initializer_list<vk::BufferRange> tickBuffers = {
        *derived.symbols, *derived.params, *derived.plantStarts, *derived.particles, nextStates_, classes_, species_,
        rows_, vigour_};
    const shared::GrowPush push = growPush(derived, settings, symbols_, atSymbol_);
    if (!derived.countOnDevice) {
        tickKernel_.dispatch(cmd, tickBuffers, push, tickKernel_.groupsFor(derived.count));
        vk::memoryBarrier(cmd, vk::Hazard::ComputeToTransfer);
        VkBufferCopy copy{0, 0, bytes};
        vkCmdCopyBuffer(cmd, nextStates_.handle(), derived.particles->handle(), 1, &copy);
        vk::memoryBarrier(cmd, vk::Hazard::TransferToAny);
        return;
    }
    // Only the device knows the modules: their workgroups are counted there, and the copy back is a kernel's.
    if (!groups_)
        groups_ = vk::Buffer(context_, 3 * sizeof(uint32_t), vk::MemoryUsage::DeviceLocal,
                             VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
    const shared::GrowGroupsPush counted{derived.plants, derived.count, context_.limits().maxComputeWorkGroupCount[0]};
    groupsKernel_.dispatch(cmd, {*derived.plantStarts, groups_}, counted, 1);
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToIndirect);
    tickKernel_.dispatchIndirect(cmd, tickBuffers, push, groups_, 0);
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    copyKernel_.dispatchIndirect(cmd, {*derived.plantStarts, nextStates_, *derived.particles}, counted, groups_, 0);
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
}

void GpuGrowth::recordSizes(VkCommandBuffer cmd, const stream::DeviceModules& drawn, const TickSettings& settings) {
    if (!drawn.particles) throw std::logic_error("GpuGrowth::recordSizes: the string carries no particle state");
    if (drawn.count == 0) return;
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
    sizesKernel_.dispatch(cmd,
                          {*drawn.symbols, *drawn.params, *drawn.plantStarts, *drawn.particles, species_, deriveTimes_,
                           rows_, classes_, placements_},
                          growPush(drawn, settings, symbols_, atSymbol_), sizesKernel_.groupsFor(drawn.count));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
}

stream::DeviceModules GpuGrowth::copyForDrawing(const stream::DeviceModules& modules) {
    stream::DeviceModules copy;
    context_.submitAndWait([&](VkCommandBuffer cmd) { copy = recordCopyForDrawing(cmd, modules); });
    return copy;
}

stream::DeviceModules GpuGrowth::recordCopyForDrawing(VkCommandBuffer cmd, const stream::DeviceModules& modules) {
    const VkDeviceSize count = std::max<VkDeviceSize>(modules.count, 1);
    const std::pair<vk::Buffer*, VkDeviceSize> sized[] = {
        {&drawnSymbols_, count * 4},
        {&drawnParams_, count * modules.stride * 4},
        {&drawnStarts_, VkDeviceSize(modules.plants + 1) * 4},
        {&drawnParticles_, count * sizeof(shared::ParticleState)}};
    for (const auto& [buffer, bytes] : sized)
        if (!*buffer || buffer->size() < bytes) *buffer = vk::Buffer(context_, bytes, vk::MemoryUsage::DeviceLocal);
    vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
    const std::pair<const vk::Buffer*, vk::Buffer*> copies[] = {{modules.symbols, &drawnSymbols_},
                                                               {modules.params, &drawnParams_},
                                                               {modules.plantStarts, &drawnStarts_},
                                                               {modules.particles, &drawnParticles_}};
    const VkDeviceSize bytes[] = {VkDeviceSize(modules.count) * 4, VkDeviceSize(modules.count) * modules.stride * 4,
                                  VkDeviceSize(modules.plants + 1) * 4,
                                  VkDeviceSize(modules.count) * sizeof(shared::ParticleState)};
    for (size_t k = 0; k < 4; ++k) {
        if (!copies[k].first || bytes[k] == 0) continue;
        const VkBufferCopy region{0, 0, bytes[k]};
        vkCmdCopyBuffer(cmd, copies[k].first->handle(), copies[k].second->handle(), 1, &region);
    }
    vk::memoryBarrier(cmd, vk::Hazard::TransferToAny);
    stream::DeviceModules copy = modules;
    copy.symbols = &drawnSymbols_;
    copy.params = &drawnParams_;
    copy.plantStarts = &drawnStarts_;
    copy.particles = modules.particles ? &drawnParticles_ : nullptr;
    return copy;
}

void GpuGrowth::tick(const stream::DeviceModules& derived, const TickSettings& settings) {
    context_.submitAndWait([&](VkCommandBuffer cmd) { recordTick(cmd, derived, settings); });
}

void GpuGrowth::growSizes(const stream::DeviceModules& drawn, const TickSettings& settings) {
    context_.submitAndWait([&](VkCommandBuffer cmd) { recordSizes(cmd, drawn, settings); });
}

} // namespace simeco::grow
