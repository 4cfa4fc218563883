// A botanical description's keywords, as seed 002 reads them (section 3.1), in English or in the thesis' Chinese
// terms: the leaf arrangement (phyllotaxy), the leaf's shape and the plant's habit. They choose where leaves go on a
// skeleton that has none, which leaf the script draws, and how stems of no given width broaden.
#pragma once

#include <string>
#include <vector>

namespace simeco::skeleton {

enum class Phyllotaxy {
    Unsaid,
    Alternate, // 互生: one leaf per node, each turned by the golden angle from the last
    Opposite,  // 對生: two leaves per node, opposite, each pair turned a right angle from the last (decussate)
    Whorled,   // 輪生: three leaves per node, 120 degrees apart, each whorl turned by 60 degrees
    Basal,     // 基生: a rosette of leaves at the plant's base
    Clustered, // 叢生: bunches of leaves at the tips
};

enum class Habit { Unsaid, Herb, Shrub, Tree };

struct PlantDescription {
    Phyllotaxy phyllotaxy = Phyllotaxy::Unsaid;
    std::string leafShape; // simeco's leaf shape word (turtle::surfaceShapeOf): ovate, lanceolate, ...; empty: unsaid
    Habit habit = Habit::Unsaid;
    std::vector<std::string> understood; // the keywords read, in English, for the script's comment
};

// Reads the comma- or space-separated words of `text` ("opposite, ovate, shrub", "對生 卵形 灌木"). A word it does not
// know is refused with std::invalid_argument naming it and the known words.
PlantDescription describePlant(const std::string& text);

const char* phyllotaxyName(Phyllotaxy p);
const char* habitName(Habit h);

} // namespace simeco::skeleton
