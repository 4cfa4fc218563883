#include "turtle/organ_merge.h"

#include <algorithm>
#include <array>
#include <iterator>
#include <span>
#include <stdexcept>

#include <fmt/format.h>

#include "compute/shared/turtle_state_layout.h"
#include "draw/bounds.h"
#include "ir/source_loc.h"
#include "vk/barriers.h"
#include "vk/context.h"

namespace simeco::turtle {

using shared::kOrganKinds;
using shared::OrganInstance;
using shared::OrganTable;

OrganMerge::OrganMerge(const vk::Context& context)
    : context_(context), kernel_(vk::ComputePipeline::embedded(context, "turtle/organ_merge")) {}

void OrganMerge::begin() {
    kept_.clear();
    heldOrgans_ = 0;
}

void OrganMerge::keep(const DeviceOrgans& batch, uint32_t firstPlant, uint64_t firstModule) {
    Kept k;
    k.table = vk::downloadVector<OrganTable>(context_, batch.table, 1)[0];
    for (uint32_t kind = 0; kind < kOrganKinds; ++kind)
        k.organs += k.table.count[kind];
    k.first = heldOrgans_;
    k.firstPlant = firstPlant;
    k.firstModule = firstModule;
    const VkDeviceSize needed = (heldOrgans_ + k.organs) * sizeof(OrganInstance);
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        if (!held_ || held_.size() < needed) { // a larger buffer, with what was kept before
            vk::Buffer larger(context_, std::max<VkDeviceSize>(needed + needed / 2, sizeof(OrganInstance)),
                              vk::MemoryUsage::DeviceLocal);
            if (heldOrgans_ > 0) {
                VkBufferCopy old{0, 0, heldOrgans_ * sizeof(OrganInstance)};
                vkCmdCopyBuffer(cmd, held_.handle(), larger.handle(), 1, &old);
            }
            // The old buffer is released once the copy has run: keep it until the wait returns.
            std::swap(held_, larger);
            retired_ = std::move(larger);
        }
        if (k.organs > 0) {
            VkBufferCopy copy{VkDeviceSize(k.table.first[0]) * sizeof(OrganInstance),
                              heldOrgans_ * sizeof(OrganInstance), VkDeviceSize(k.organs) * sizeof(OrganInstance)};
            vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
            vkCmdCopyBuffer(cmd, batch.instances.handle(), held_.handle(), 1, &copy);
        }
    });
    retired_ = vk::Buffer();
    heldOrgans_ += k.organs;
    kept_.push_back(k);
}

const DeviceOrgans& OrganMerge::merge() {
    // Each kind's organs of every batch, one batch after the other, the kinds one after the other.
    OrganTable table{};
    for (const Kept& k : kept_)
        for (uint32_t kind = 0; kind < kOrganKinds; ++kind)
            table.count[kind] += k.table.count[kind];
    for (uint32_t kind = 1; kind < kOrganKinds; ++kind)
        table.first[kind] = table.first[kind - 1] + table.count[kind - 1];
    draw::Bounds bounds{glm::vec3(1e30f), glm::vec3(-1e30f)};
    for (const Kept& k : kept_) {
        if (k.organs == 0) continue;
        const draw::Bounds b = draw::decodeBounds(k.table);
        bounds.min = glm::min(bounds.min, b.min);
        bounds.max = glm::max(bounds.max, b.max);
    }
    draw::encodeBounds(bounds, table);
    const VkDeviceSize bytes = std::max<uint64_t>(heldOrgans_, 1) * sizeof(OrganInstance);
    // The field's instances are bound whole, here and by the renderer.
    const uint64_t limit = context_.limits().maxStorageBufferRange;
    if (bytes > limit)
        throw ir::LimitError(fmt::format("the device binds at most {} MiB per buffer; the field's {} organ instances "
                                         "need {} MiB (draw fewer plants)",
                                         limit >> 20, heldOrgans_, bytes >> 20));
    if (!field_.instances || field_.instances.size() < bytes) {
        field_.instances = vk::Buffer(context_, bytes, vk::MemoryUsage::DeviceLocal);
        field_.capacity = uint32_t(bytes / sizeof(OrganInstance));
    }
    field_.table = vk::deviceBufferWith(context_, std::span<const OrganTable>(&table, 1));
    const float spacing = 1.0f;
    field_.field = vk::deviceBufferWith(context_, std::span<const float>(&spacing, 1));
    std::array<uint32_t, kOrganKinds> next;
    std::copy(std::begin(table.first), std::end(table.first), next.begin());
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
        for (const Kept& k : kept_) {
            if (k.organs == 0) continue;
            shared::OrganMergePush push{};
            for (uint32_t kind = 0; kind < kOrganKinds; ++kind) {
                push.count[kind] = k.table.count[kind];
                push.destination[kind] = next[kind];
                next[kind] += k.table.count[kind];
            }
            push.source = uint32_t(k.first);
            push.organs = k.organs;
            push.firstPlant = k.firstPlant;
            push.firstModule = uint32_t(k.firstModule);
            kernel_.dispatch(cmd, {held_, field_.instances}, push, kernel_.groupsFor(k.organs));
        }
        vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    });
    return field_;
}

} // namespace simeco::turtle
