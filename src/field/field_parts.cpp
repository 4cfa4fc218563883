#include "field/field_parts.h"

#include <algorithm>
#include <span>

#include <fmt/format.h>

#include "compute/shared/turtle_state_layout.h"
#include "ir/source_loc.h"
#include "turtle/organ_merge.h"
#include "vk/barriers.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace simeco::field {

namespace {

// Plants [first, first + count) of `modules`, copied into `into` (whose buffers grow as needed), their plant
// table starting at 0.
stream::DeviceModules slicePlants(const vk::Context& context, const stream::DeviceModules& modules,
                                  const std::vector<uint32_t>& starts, uint32_t first, uint32_t count,
                                  FieldBatchBuffers& into) {
    const uint64_t begin = starts[first], end = starts[first + count];
    const VkDeviceSize words = std::max<VkDeviceSize>((end - begin) * 4, 4);
    const VkDeviceSize params = std::max<VkDeviceSize>((end - begin) * modules.stride * 4, 4);
    if (!into.symbols || into.symbols.size() < words)
        into.symbols = vk::Buffer(context, words, vk::MemoryUsage::DeviceLocal);
    if (!into.params || into.params.size() < params)
        into.params = vk::Buffer(context, params, vk::MemoryUsage::DeviceLocal);
    std::vector<uint32_t> table(count + 1);
    for (uint32_t p = 0; p <= count; ++p) table[p] = uint32_t(starts[first + p] - begin);
    into.plantStarts = vk::deviceBufferWith(context, std::span<const uint32_t>(table));
    context.submitAndWait([&](VkCommandBuffer cmd) {
        vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
        if (end > begin) {
            const VkBufferCopy sym{begin * 4, 0, (end - begin) * 4};
            vkCmdCopyBuffer(cmd, modules.symbols->handle(), into.symbols.handle(), 1, &sym);
            const VkBufferCopy par{begin * modules.stride * 4, 0, (end - begin) * modules.stride * 4};
            vkCmdCopyBuffer(cmd, modules.params->handle(), into.params.handle(), 1, &par);
        }
        vk::memoryBarrier(cmd, vk::Hazard::TransferToAny);
    });
    return stream::DeviceModules{&into.symbols, &into.params, &into.plantStarts, uint32_t(end - begin), count,
                                 modules.stride, nullptr};
}

} // namespace

std::vector<const turtle::DeviceOrgans*> interpretInParts(const FieldSource& source, Field& field,
                                                          const vk::Context& context, uint64_t batchModules) {
    if (!field.deriver || field.modules <= batchModules) return {&interpretOnDevice(source, field, context)};
    if (!field.turtle) field.turtle = std::make_unique<turtle::GpuTurtle>(context, field.commands, field.turtles);
    const stream::DeviceModules modules = field.deriver->lastString();
    const std::vector<uint32_t> starts =
        vk::downloadVector<uint32_t>(context, *modules.plantStarts, modules.plants + 1);
    // Batches of consecutive plants, each of at most batchModules modules.
    std::vector<std::pair<uint32_t, uint32_t>> batches; // first plant, plants
    for (uint32_t first = 0; first < modules.plants;) {
        uint32_t count = 0;
        while (first + count < modules.plants && starts[first + count + 1] - starts[first] <= batchModules) ++count;
        if (count == 0)
            throw ir::LimitError(fmt::format("plant {} alone has {} modules, more than the turtle interprets at once "
                                             "({})",
                                             first, starts[first + 1] - starts[first], batchModules));
        batches.emplace_back(first, count);
        first += count;
    }
    // The field one interpretation would lay: spaced by the first batch's widest plant, unless the source says.
    float spacing = field.options.spacing;
    if (spacing <= 0.0f) {
        const auto [first, count] = batches.front();
        const turtle::DeviceOrgans& gridded =
            field.turtle->interpret(slicePlants(context, modules, starts, first, count, field.batch), {});
        spacing = vk::downloadVector<float>(context, gridded.field, 1)[0];
    }
    if (!field.merge) field.merge = std::make_unique<turtle::OrganMerge>(context);
    field.merge->begin();
    for (const auto& [first, count] : batches) {
        turtle::FieldOptions where;
        where.spacing = spacing;
        for (uint32_t p = first; p < first + count; ++p)
            where.placements.push_back(
                field.options.scattered
                    ? turtle::scatteredPlacement(p, modules.plants, spacing)
                    : turtle::placementAt(turtle::fieldCell(p, modules.plants) * spacing, {0.0f, 1.0f, 0.0f}, 0.0f));
        const turtle::DeviceOrgans& organs =
            field.turtle->interpret(slicePlants(context, modules, starts, first, count, field.batch), where);
        field.merge->keep(organs, first, starts[first]);
    }
    return field.merge->mergeParts();
}

OrganExtent organExtent(const vk::Context& context, const std::vector<const turtle::DeviceOrgans*>& parts) {
    OrganExtent extent;
    extent.bounds = draw::Bounds{glm::vec3(1e30f), glm::vec3(-1e30f)};
    for (const turtle::DeviceOrgans* part : parts) {
        const OrganExtent e = organExtent(context, *part);
        extent.organs += e.organs;
        if (e.organs == 0) continue;
        extent.bounds.min = glm::min(extent.bounds.min, e.bounds.min);
        extent.bounds.max = glm::max(extent.bounds.max, e.bounds.max);
    }
    if (extent.organs == 0) extent.bounds = draw::Bounds{};
    return extent;
}

} // namespace simeco::field
