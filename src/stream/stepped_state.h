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
    uint32_t fieldStep = 0;               // advances, derived or not: the random streams' step
    std::vector<PlantVariables> plants;   // per plant
};

// The states of consecutive plants (a field's batches, in order) as one state of all their plants. They must be
// at the same step and of one stride. Throws std::invalid_argument otherwise.
SteppedState joinPlants(const std::vector<SteppedState>& parts);

// Plants [first, first + count) of `state` as a state of their own.
SteppedState plantsOf(const SteppedState& state, uint32_t first, uint32_t count);

} // namespace simeco::stream
