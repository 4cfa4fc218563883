// What a description gives a bare skeleton (a polyline drawing has neither leaves nor widths): leaves at its nodes
// in the described arrangement, and widths that taper from the base to the tips as the pipe model has it (a stem's
// cross-section carries the tips above it, da Vinci's rule with the exponent 2.5 measured on trees), thicker for
// a tree than for a herb.
#pragma once

#include "skeleton/plant_description.h"
#include "skeleton/skeleton.h"

namespace simeco::skeleton {

// Adds leaves where `plant` (checked) has no organs and the description names a phyllotaxy; sets the widths of a
// plant whose stems all have width 0. Returns what it did, for the script's comment ("" for nothing).
std::string dressPlant(Plant& plant, const PlantDescription& description);

} // namespace simeco::skeleton
