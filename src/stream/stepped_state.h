// Where a derivation step by step stands (gpu::GpuDeriver::begin, cpu::SteppedDerivation): everything its next
// steps depend on, so that a saved field goes on exactly as it would have.
#pragma once

#include <cstdint>
#include <vector>

#include "stream/module_string.h"

namespace simeco::stream {

// A plant's variables: its globals and arrays as its control blocks left them, and whether it called stop().
struct PlantVariables {
    std::vector<double> globals;
    std::vector<std::vector<double>> arrays;
    bool stopRequested = false;
    int stepsDerived = 0;
    bool operator==(const PlantVariables&) const = default;
};

struct SteppedState {
    ModuleString string;                  // the derived string, with its particle state
    uint32_t fieldStep = 0;               // advances that derived: the random streams' step
    std::vector<PlantVariables> plants;   // per plant
};

} // namespace simeco::stream
