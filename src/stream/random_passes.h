// Which random stream each part of a derivation draws from, the same on every engine: the passes of a step,
// of decomposition and of the homomorphism, and the keys of the control blocks.
#pragma once

#include <algorithm>
#include <cstdint>

#include "compute/shared/derive_layout.h"
#include "stream/evaluator.h"

namespace simeco::stream {

// Random stream passes: a derivation step uses pass step * kPassesPerStep, decomposition at depth d in
// that step pass step * kPassesPerStep + 1 + d (depths past kPassesPerStep - 3 share the last one), and the
// control blocks the step's last pass.
using shared::kPassesPerStep;

inline uint32_t decompositionPass(uint32_t step, int depth) {
    return step * kPassesPerStep + 1 + uint32_t(std::min(depth, int(kPassesPerStep) - 3));
}

// The homomorphism at depth d draws from pass 1 + d of step 0, which rewrites nothing.
inline uint32_t homomorphismPass(uint32_t /*step*/, int depth) {
    return decompositionPass(0, depth);
}

// Where the control blocks draw from: Start in pass 0; StartEach (module 0) and EndEach (module 1) of a step
// in its last pass; End in step 0's last pass (module 2). The same on every engine, whatever the string.
enum class ControlBlock : uint32_t { Start, StartEach, EndEach, End };
inline RandomKey controlBlockKey(uint32_t seed, uint32_t plant, uint32_t step, ControlBlock block) {
    switch (block) {
    case ControlBlock::Start:
        return {seed, plant, 0, 0, 0};
    case ControlBlock::StartEach:
        return {seed, plant, step * kPassesPerStep + kPassesPerStep - 1, 0, 0};
    case ControlBlock::EndEach:
        return {seed, plant, step * kPassesPerStep + kPassesPerStep - 1, 1, 0};
    case ControlBlock::End:
        break;
    }
    return {seed, plant, kPassesPerStep - 1, 2, 0};
}

} // namespace simeco::stream
