// A field interpreted in batches of plants, each small enough for the turtle's buffer bindings: each batch's organs
// are kept (copied out of the turtle's buffers, which the next batch's interpretation overwrites), then merged into
// the field's instances (compute/turtle/organ_merge.comp), grouped by kind and in plant order within a kind as one
// interpretation of the whole field writes them, their plant and module indices the field's.
#pragma once

#include <cstdint>
#include <vector>

#include "compute/shared/organ_layout.h"
#include "turtle/turtle_gpu.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::vk {
class Context;
}

namespace simeco::turtle {

class OrganMerge {
public:
    explicit OrganMerge(const vk::Context& context);

    // Starts a field: nothing kept.
    void begin();
    // Keeps the organs of a batch whose plants start at the field's plant `firstPlant` and whose drawn string
    // starts at the field's module `firstModule` (the batches' strings one after the other).
    void keep(const DeviceOrgans& batch, uint32_t firstPlant, uint64_t firstModule);
    // The field's organs: every kept batch's, merged, the table counting them all and bounding them all; valid
    // until the next merge(). Throws ir::LimitError when they need more than the device binds in one buffer.
    const DeviceOrgans& merge();

private:
    struct Kept {
        shared::OrganTable table;
        uint64_t first = 0; // its first instance in held_
        uint32_t organs = 0;
        uint32_t firstPlant = 0;
        uint64_t firstModule = 0;
    };
    const vk::Context& context_;
    vk::ComputePipeline kernel_;
    std::vector<Kept> kept_;
    vk::Buffer held_, retired_;
    uint64_t heldOrgans_ = 0;
    DeviceOrgans field_;
};

} // namespace simeco::turtle
