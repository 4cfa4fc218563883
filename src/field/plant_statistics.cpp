#include "field/plant_statistics.h"

#include <algorithm>
#include <cstring>
#include <span>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "draw/organ_meshes.h"
#include "turtle/turtle_cpu.h"
#include "vk/barriers.h"
#include "vk/context.h"

namespace simeco::field {

namespace {

std::array<float, shared::kSurfaceShapes> measureLeafShapes() {
    const draw::OrganMeshData meshes = draw::buildOrganMeshes();
    const draw::MeshRange& leaf = meshes.organs[shared::kOrganLeaf];
    std::array<float, shared::kSurfaceShapes> areas{};
    for (uint32_t t = 0; t < leaf.triangleCount(); ++t) {
        const shared::MeshVertex* v[3];
        for (uint32_t c = 0; c < 3; ++c)
            v[c] = &meshes.vertices[size_t(leaf.vertexOffset) + meshes.indices[leaf.firstIndex + 3 * t + c]];
        const uint32_t shape = uint32_t(v[0]->normal.w + 0.5f);
        if (shape > shared::kLeafLastShape) continue; // a blossom is no leaf: its area stays 0
        // The blade is drawn flat: x along the heading (times the length), y along left (times the width).
        const glm::vec2 a(v[1]->position.x - v[0]->position.x, v[1]->position.y - v[0]->position.y);
        const glm::vec2 b(v[2]->position.x - v[0]->position.x, v[2]->position.y - v[0]->position.y);
        areas[shape] += 0.5f * std::abs(a.x * b.y - a.y * b.x);
    }
    return areas;
}

} // namespace

std::vector<float> leafShapeAreas(const std::vector<ir::LeafModel>& leafModels) {
    // The built-in meshes are measured once.
    static const std::array<float, shared::kSurfaceShapes> builtIn = measureLeafShapes();
    std::vector<float> areas(builtIn.begin(), builtIn.end());
    for (const ir::LeafModel& model : leafModels) areas.push_back(model.leaf ? model.area : 0.0f);
    return areas;
}

std::vector<shared::PlantStatistics> plantStatisticsCpu(const turtle::Interpretation& organs,
                                                        const std::vector<float>& baseHeights,
                                                        const std::vector<shared::ParticleState>& drawnParticles,
                                                        const std::vector<float>& shapeAreas) {
    std::vector<shared::PlantStatistics> stats(baseHeights.size(), shared::PlantStatistics{0, 0, 0.0f, 0.0f, 0.0f});
    std::vector<float> top(baseHeights.size(), -1e30f);
    // A kind's instances follow the plants: each plant's are summed in order, as the kernel sums them.
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k)
        for (uint32_t i = organs.first[k]; i < organs.first[k] + organs.count[k]; ++i) {
            const shared::OrganInstance& o = organs.organs[i];
            shared::PlantStatistics& s = stats[o.plant];
            ++s.organs;
            const turtle::Bounds box = turtle::organBounds(o);
            if (glm::any(glm::greaterThan(box.max, box.min))) ++s.living;
            top[o.plant] = std::max(top[o.plant], box.max.y);
            float area = 0.0f;
            if (o.kind == shared::kOrganLeaf)
                area = o.shape < shapeAreas.size() ? o.position.w * o.heading.w * shapeAreas[o.shape] : 0.0f;
            if (o.kind == shared::kOrganTriangle) {
                const glm::vec3 p(o.position.x, o.position.y, o.position.z);
                area = 0.5f * glm::length(glm::cross(glm::vec3(o.heading.x, o.heading.y, o.heading.z) - p,
                                                     glm::vec3(o.up.x, o.up.y, o.up.z) - p));
            }
            s.leafArea += area;
            if (!drawnParticles.empty()) s.light += area * drawnParticles[o.module].value[shared::kParticleLight];
        }
    for (size_t p = 0; p < stats.size(); ++p)
        stats[p].height = stats[p].organs > 0 ? std::max(top[p] - baseHeights[p], 0.0f) : 0.0f;
    return stats;
}

namespace {

// A small buffer the host writes through its mapping, without a submission: a field has a statistics counter for
// each of its batches, and the drawing that records them is one submission.
vk::Buffer mappedBufferWith(const vk::Context& context, std::span<const float> values) {
    vk::Buffer buffer(context, std::max<VkDeviceSize>(values.size_bytes(), sizeof(float)), vk::MemoryUsage::Upload);
    if (!values.empty()) std::memcpy(buffer.mapped(), values.data(), values.size_bytes());
    return buffer;
}

} // namespace

GpuPlantStatistics::GpuPlantStatistics(const vk::Context& context, const std::vector<float>& shapeAreas)
    : context_(context), kernel_(vk::ComputePipeline::embedded(context, "grow/plant_statistics")) {
    shapeAreas_ = mappedBufferWith(context, std::span<const float>(shapeAreas));
    const float none = 0.0f;
    noParticles_ = mappedBufferWith(context, std::span<const float>(&none, 1));
    tableReadback_ = vk::Buffer(context, sizeof(shared::OrganTable), vk::MemoryUsage::Readback);
}

void GpuPlantStatistics::record(VkCommandBuffer cmd, const turtle::DeviceOrgans& organs,
                                const vk::Buffer* drawnParticles, const std::vector<float>& baseHeights) {
    plants_ = uint32_t(baseHeights.size());
    if (plants_ == 0) return;
    const VkDeviceSize bytes = VkDeviceSize(plants_) * sizeof(shared::PlantStatistics);
    if (!statistics_ || statistics_.size() < bytes) {
        statistics_ = vk::Buffer(context_, bytes, vk::MemoryUsage::DeviceLocal);
        readback_ = vk::Buffer(context_, bytes, vk::MemoryUsage::Readback);
    }
    if (!bases_ || baseHeights != uploadedBases_) {
        bases_ = mappedBufferWith(context_, std::span<const float>(baseHeights));
        uploadedBases_ = baseHeights;
    }
    const shared::PlantStatisticsPush push{plants_, drawnParticles ? 1u : 0u, 0, 0};
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
    kernel_.dispatch(cmd,
                     {organs.instances, organs.table, bases_, drawnParticles ? *drawnParticles : noParticles_,
                      shapeAreas_, statistics_},
                     push, kernel_.groupsFor(plants_));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToTransfer);
    VkBufferCopy copy{0, 0, bytes};
    vkCmdCopyBuffer(cmd, statistics_.handle(), readback_.handle(), 1, &copy);
    const VkBufferCopy table{0, 0, sizeof(shared::OrganTable)};
    vkCmdCopyBuffer(cmd, organs.table.handle(), tableReadback_.handle(), 1, &table);
    vk::memoryBarrier(cmd, vk::Hazard::TransferToHost);
}

std::vector<shared::PlantStatistics> GpuPlantStatistics::read() const {
    const auto* s = reinterpret_cast<const shared::PlantStatistics*>(readback_.mapped());
    return std::vector<shared::PlantStatistics>(s, s + plants_);
}

shared::OrganTable GpuPlantStatistics::organTable() const {
    return *reinterpret_cast<const shared::OrganTable*>(tableReadback_.mapped());
}

} // namespace simeco::field
