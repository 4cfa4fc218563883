// The growth tick on the CPU: plain loops over the same state as the device's kernels (compute/grow/tick.comp and
// grown_sizes.comp), the reference the tests compare them with.
#pragma once

#include <cstdint>
#include <vector>

#include "compute/shared/organ_layout.h"
#include "grow/growth_tables.h"
#include "stream/module_string.h"

namespace simeco::grow {

// What a tick needs besides the string: the tables, the species' count (plant p is of species p mod it), the
// seconds it advances, the ticks before it, the field's seed, the scene's gravity as a multiple of Earth's and
// each plant's vigour. The device's GpuGrowth holds the vigour of its plants instead.
struct TickSettings {
    const GrowthTables* tables = nullptr;
    uint32_t species = 1;
    float dt = 0.0f;
    uint32_t tick = 0;
    uint32_t seed = 0;
    float gravity = 1.0f;
    const std::vector<float>* vigour = nullptr; // per plant: a factor on its GrowRate and BroadenRate (none: 1)
    float openLight = 0.0f; // the light in the open where a light grid runs (organs grow by their light), else 0
    // per plant: where it stands (the light's direction turns into its own frame for phototropism; none: as is)
    const std::vector<shared::PlantPlacement>* placements = nullptr;
    // The number of plant 0's random stream: a batch of a larger field draws what its plants draw in the whole.
    uint32_t firstPlant = 0;
};

// One tick of every particle of the derived string `s` (which carries particle state): the modules that continue
// a particle and those born (compute/shared/growth_layout.h), aging, each living organ's growth by its stage's
// GrowRate and BroadenRate for its GrowTime, its cone noise every NoiseTime while it grows,
// and the seconds it stands in deep shade.
void tickCpu(const TickSettings& settings, stream::ModuleString& s);

// The drawn string's kGrownValue codes replaced with its particles' values; `deriveTimes` per plant.
void growSizesCpu(const TickSettings& settings, const std::vector<float>& deriveTimes, stream::ModuleString& drawn);

} // namespace simeco::grow
