#include "turtle/organ_merge.h"

#include <algorithm>
#include <array>
#include <cstring>
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

OrganMerge::OrganMerge(const vk::Context& context, uint64_t maxPartBytes)
    : context_(context),
      maxPartBytes_(maxPartBytes > 0 ? maxPartBytes : context.limits().maxStorageBufferRange),
      kernel_(vk::ComputePipeline::embedded(context, "turtle/organ_merge")) {}

void OrganMerge::begin() {
    for (Part& part : parts_) {
        part.kept.clear();
        part.heldOrgans = 0;
        part.organs = 0;
    }
    used_ = 0;
}

OrganMerge::Kept OrganMerge::counted(const OrganTable& table, uint32_t firstPlant, uint64_t firstModule) const {
    Kept k;
    k.table = table;
    for (uint32_t kind = 0; kind < kOrganKinds; ++kind)
        k.organs += k.table.count[kind];
    k.firstPlant = firstPlant;
    k.firstModule = firstModule;
    const uint64_t bytes = uint64_t(k.organs) * sizeof(OrganInstance);
    if (bytes > maxPartBytes_)
        throw ir::LimitError(fmt::format("a batch's {} organ instances need {} MiB, past the {} MiB a buffer binding "
                                         "holds (draw fewer plants per batch)",
                                         k.organs, bytes >> 20, maxPartBytes_ >> 20));
    return k;
}

OrganMerge::Part& OrganMerge::partFor(const Kept& k) {
    if (used_ == 0 || (parts_[used_ - 1].organs + k.organs) * sizeof(OrganInstance) > maxPartBytes_) {
        if (used_ == parts_.size()) parts_.emplace_back();
        ++used_;
    }
    return parts_[used_ - 1];
}

void OrganMerge::keepInPlace(const DeviceOrgans& batch, const OrganTable& table, uint32_t firstPlant,
                             uint64_t firstModule) {
    Kept k = counted(table, firstPlant, firstModule);
    Part& part = partFor(k);
    k.source = &batch.instances;
    k.first = table.first[0];
    part.organs += k.organs;
    part.kept.push_back(k);
}

void OrganMerge::keep(const DeviceOrgans& batch, uint32_t firstPlant, uint64_t firstModule) {
    Kept k = counted(vk::downloadVector<OrganTable>(context_, batch.table, 1)[0], firstPlant, firstModule);
    Part& part = partFor(k);
    k.first = part.heldOrgans;
    const VkDeviceSize needed = (part.heldOrgans + k.organs) * sizeof(OrganInstance);
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        if (!part.held || part.held.size() < needed) { // a larger buffer, with what was kept before
            const VkDeviceSize size = std::min<VkDeviceSize>(needed + needed / 2, maxPartBytes_);
            vk::Buffer larger(context_, std::max<VkDeviceSize>(size, sizeof(OrganInstance)),
                              vk::MemoryUsage::DeviceLocal);
            if (part.heldOrgans > 0) {
                VkBufferCopy old{0, 0, part.heldOrgans * sizeof(OrganInstance)};
                vkCmdCopyBuffer(cmd, part.held.handle(), larger.handle(), 1, &old);
            }
            // The old buffer is released once the copy has run: keep it until the wait returns.
            std::swap(part.held, larger);
            retired_ = std::move(larger);
        }
        if (k.organs > 0) {
            VkBufferCopy copy{VkDeviceSize(k.table.first[0]) * sizeof(OrganInstance),
                              part.heldOrgans * sizeof(OrganInstance), VkDeviceSize(k.organs) * sizeof(OrganInstance)};
            vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
            vkCmdCopyBuffer(cmd, batch.instances.handle(), part.held.handle(), 1, &copy);
        }
    });
    retired_ = vk::Buffer();
    part.heldOrgans += k.organs;
    part.organs += k.organs;
    part.kept.push_back(k);
}

std::vector<const DeviceOrgans*> OrganMerge::mergeParts() {
    if (used_ == 0) { // an empty field: one empty part
        parts_.resize(std::max<size_t>(parts_.size(), 1));
        used_ = 1;
    }
    std::vector<const DeviceOrgans*> merged;
    for (size_t p = 0; p < used_; ++p) {
        mergePart(parts_[p]);
        merged.push_back(&parts_[p].field);
    }
    return merged;
}

const DeviceOrgans& OrganMerge::merge() {
    uint64_t organs = 0;
    for (size_t p = 0; p < used_; ++p) organs += parts_[p].organs;
    if (used_ > 1)
        throw ir::LimitError(fmt::format("the device binds at most {} MiB per buffer; the field's {} organ instances "
                                         "need {} MiB (draw fewer plants)",
                                         maxPartBytes_ >> 20, organs, (organs * sizeof(OrganInstance)) >> 20));
    return *mergeParts().front();
}

void OrganMerge::mergePart(Part& part) {
    // Each kind's organs of every batch, one batch after the other, the kinds one after the other.
    OrganTable table{};
    for (const Kept& k : part.kept)
        for (uint32_t kind = 0; kind < kOrganKinds; ++kind)
            table.count[kind] += k.table.count[kind];
    for (uint32_t kind = 1; kind < kOrganKinds; ++kind)
        table.first[kind] = table.first[kind - 1] + table.count[kind - 1];
    draw::Bounds bounds{glm::vec3(1e30f), glm::vec3(-1e30f)};
    for (const Kept& k : part.kept) {
        if (k.organs == 0) continue;
        const draw::Bounds b = draw::decodeBounds(k.table);
        bounds.min = glm::min(bounds.min, b.min);
        bounds.max = glm::max(bounds.max, b.max);
    }
    draw::encodeBounds(bounds, table);
    const VkDeviceSize bytes = std::max<uint64_t>(part.organs, 1) * sizeof(OrganInstance);
    DeviceOrgans& field = part.field;
    if (!field.instances || field.instances.size() < bytes) {
        field.instances = vk::Buffer(context_, bytes, vk::MemoryUsage::DeviceLocal);
        field.capacity = uint32_t(bytes / sizeof(OrganInstance));
    }
    // Written through their mapping, without a submission of their own: a field's drawing is its batches' one
    // submission and the merge's.
    field.table = vk::Buffer(context_, sizeof(OrganTable), vk::MemoryUsage::Upload);
    std::memcpy(field.table.mapped(), &table, sizeof(OrganTable));
    if (!field.field) {
        field.field = vk::Buffer(context_, sizeof(float), vk::MemoryUsage::Upload);
        const float spacing = 1.0f;
        std::memcpy(field.field.mapped(), &spacing, sizeof spacing);
    }
    if (!part.held) part.held = vk::Buffer(context_, sizeof(OrganInstance), vk::MemoryUsage::DeviceLocal);
    std::array<uint32_t, kOrganKinds> next;
    std::copy(std::begin(table.first), std::end(table.first), next.begin());
    context_.submitAndWait([&](VkCommandBuffer cmd) {
        vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
        for (const Kept& k : part.kept) {
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
            kernel_.dispatch(cmd, {k.source ? *k.source : part.held, field.instances}, push,
                             kernel_.groupsFor(k.organs));
        }
        vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
    });
}

} // namespace simeco::turtle
