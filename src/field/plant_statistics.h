// What the growth simulation reports of each plant (compute/shared/plant_statistics_layout.h), from the organs the
// turtle drew: on the device (compute/grow/plant_statistics.comp), with the host reading back a few words per
// plant, and by the CPU reference the tests compare it with.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "compute/shared/particle_layout.h"
#include "compute/shared/plant_statistics_layout.h"
#include "ir/leaf_model.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_gpu.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::field {

// The area of a leaf blade of each surface shape at unit length and width: the leaf mesh's (draw/organ_meshes.h),
// 0 for the blossoms, and after the built-in shapes each model's that a leaf stage names.
std::vector<float> leafShapeAreas(const std::vector<ir::LeafModel>& leafModels = {});

// `baseHeights`: the height each plant stands at; `drawnParticles`: the drawn string's particle state, one per
// module (the light), or empty; `shapeAreas`: leafShapeAreas() (a leaf of a shape past them has no area).
std::vector<shared::PlantStatistics> plantStatisticsCpu(const turtle::Interpretation& organs,
                                                        const std::vector<float>& baseHeights,
                                                        const std::vector<shared::ParticleState>& drawnParticles,
                                                        const std::vector<float>& shapeAreas);

class GpuPlantStatistics {
public:
    GpuPlantStatistics(const vk::Context& context, const std::vector<float>& shapeAreas);
    // Records the statistics of the plants `organs` hold, and their copy and the organs' table's for the host, into
    // `cmd`. `drawnParticles`: the drawn string's particle state, or null.
    void record(VkCommandBuffer cmd, const turtle::DeviceOrgans& organs, const vk::Buffer* drawnParticles,
                const std::vector<float>& baseHeights);
    // After the recording's submission has completed: the statistics, and the table of the organs counted (their
    // count by kind, for keeping them in a field's merge without another read-back).
    std::vector<shared::PlantStatistics> read() const;
    shared::OrganTable organTable() const;

private:
    const vk::Context& context_;
    vk::ComputePipeline kernel_;
    vk::Buffer shapeAreas_, bases_, statistics_, readback_, noParticles_, tableReadback_;
    std::vector<float> uploadedBases_;
    uint32_t plants_ = 0;
};

} // namespace simeco::field
