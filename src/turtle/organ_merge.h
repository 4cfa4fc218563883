// A field interpreted in batches of plants, each small enough for the turtle's buffer bindings: each batch's organs
// are kept (copied out of the turtle's buffers, which the next batch's interpretation overwrites, or left in buffers
// of the batch's own), then merged into the field's instances (compute/turtle/organ_merge.comp), grouped by kind and
// in plant order within a kind as one interpretation of the whole field writes them, their plant and module indices
// the field's. A field whose organs need more than one buffer binding holds comes in parts, each the merge of
// consecutive batches, which the renderer draws together (draw::OrganPart).
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
    // `maxPartBytes`: the most bytes of instances one part holds; 0: as many as the device binds in one buffer
    // (maxStorageBufferRange).
    explicit OrganMerge(const vk::Context& context, uint64_t maxPartBytes = 0);

    // Starts a field: nothing kept.
    void begin();
    // Keeps the organs of a batch whose plants start at the field's plant `firstPlant` and whose drawn string
    // starts at the field's module `firstModule` (the batches' strings one after the other). A batch whose organs
    // would take its part past the most a part holds starts another part.
    void keep(const DeviceOrgans& batch, uint32_t firstPlant, uint64_t firstModule);
    // The same without a copy, the batch's table already read back: its organs stay in the batch's own buffers,
    // which must hold them until mergeParts() has run (a batch's turtle::TurtleTarget).
    void keepInPlace(const DeviceOrgans& batch, const shared::OrganTable& table, uint32_t firstPlant,
                     uint64_t firstModule);
    // The field's organs in parts, each the merge of consecutive batches, its table counting and bounding them;
    // valid until the next merge. One part where they fit in one.
    std::vector<const DeviceOrgans*> mergeParts();
    // The same where the field is one part; throws ir::LimitError when it needs more.
    const DeviceOrgans& merge();

private:
    struct Kept {
        shared::OrganTable table;
        const vk::Buffer* source = nullptr; // where its instances are: its own buffer, or (null) its part's held one
        uint64_t first = 0;                 // its first instance there
        uint32_t organs = 0;
        uint32_t firstPlant = 0;
        uint64_t firstModule = 0;
    };
    struct Part {
        std::vector<Kept> kept;
        vk::Buffer held;         // the instances of the batches kept by a copy, one after the other
        uint64_t heldOrgans = 0;
        uint64_t organs = 0;     // of all its batches
        DeviceOrgans field;      // merged
    };
    // A batch's table counted, and the part it goes to (another where it would take the last past the most a part
    // holds).
    Kept counted(const shared::OrganTable& table, uint32_t firstPlant, uint64_t firstModule) const;
    Part& partFor(const Kept& kept);
    void mergePart(Part& part);

    const vk::Context& context_;
    uint64_t maxPartBytes_;
    vk::ComputePipeline kernel_;
    std::vector<Part> parts_;
    size_t used_ = 0; // parts of the current field; the others keep their buffers for the next
    vk::Buffer retired_;
};

} // namespace simeco::turtle
