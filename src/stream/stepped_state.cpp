#include "stream/stepped_state.h"

#include <stdexcept>

#include <fmt/format.h>

namespace simeco::stream {

SteppedState joinPlants(const std::vector<SteppedState>& parts) {
    SteppedState whole;
    whole.string.plantStart.push_back(0);
    if (parts.empty()) return whole;
    whole.fieldStep = parts.front().fieldStep;
    whole.string.stride = parts.front().string.stride;
    for (const SteppedState& part : parts) {
        if (part.fieldStep != whole.fieldStep || part.string.stride != whole.string.stride)
            throw std::invalid_argument(fmt::format("joinPlants: a part at step {} with stride {}, the first at {} "
                                                    "with {}",
                                                    part.fieldStep, part.string.stride, whole.fieldStep,
                                                    whole.string.stride));
        const uint64_t offset = whole.string.size();
        whole.string.append(part.string, 0, part.string.size());
        for (size_t p = 1; p < part.string.plantStart.size(); ++p)
            whole.string.plantStart.push_back(offset + part.string.plantStart[p]);
        whole.plants.insert(whole.plants.end(), part.plants.begin(), part.plants.end());
    }
    return whole;
}

SteppedState plantsOf(const SteppedState& state, uint32_t first, uint32_t count) {
    if (uint64_t(first) + count > state.plants.size() || state.string.plantStart.size() != state.plants.size() + 1)
        throw std::invalid_argument(fmt::format("plantsOf: plants {} to {} of a state of {}", first, first + count,
                                                state.plants.size()));
    SteppedState part;
    part.fieldStep = state.fieldStep;
    part.string.stride = state.string.stride;
    const uint64_t begin = state.string.plantStart[first], end = state.string.plantStart[first + count];
    part.string.append(state.string, begin, end);
    for (uint32_t p = first; p <= first + count; ++p)
        part.string.plantStart.push_back(state.string.plantStart[p] - begin);
    part.plants.assign(state.plants.begin() + first, state.plants.begin() + first + count);
    return part;
}

} // namespace simeco::stream
