// A derived field too large for one interpretation by the turtle kernels (their per-module buffers bind at most
// maxStorageBufferRange bytes): interpreted in batches of consecutive plants, each copied out of the derived
// string, standing on the grid one interpretation would have put them on, and merged into parts the renderer
// draws together (turtle::OrganMerge).
#pragma once

#include <cstdint>
#include <vector>

#include "compute/shared/turtle_state_layout.h"
#include "field/field.h"

namespace simeco::field {

// The modules one interpretation by the turtle kernels takes: half of what the turtle's largest per-module
// buffer (TurtleStep) holds in the smallest storage binding Vulkan guarantees (2^27 bytes), so that a batch
// planned by its plants' sizes may still grow. Fixed, so that a field is cut alike on every device.
inline constexpr uint64_t kBatchModules = (uint64_t(1) << 27) / sizeof(shared::TurtleStep) / 2;

// The field's organs on the device, in parts: as interpretOnDevice() writes them where the field takes one
// interpretation (of at most `batchModules` modules), else batch by batch. Valid until the field's next
// interpretation.
std::vector<const turtle::DeviceOrgans*> interpretInParts(const FieldSource& source, Field& field,
                                                          const vk::Context& context,
                                                          uint64_t batchModules = kBatchModules);

// The organs' count and bounds over every part.
OrganExtent organExtent(const vk::Context& context, const std::vector<const turtle::DeviceOrgans*>& parts);

} // namespace simeco::field
