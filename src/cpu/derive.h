// The CPU reference engine: derives a grammar exactly as cpfg does.
//
// Parallel rewriting with branch-aware left and right context (a closed branch is skipped, the end of a
// branch ends the right context, a `[` is passed on the way left), ignore/consider, the first applicable
// production in file order (or a weighted draw among applicable ones in stochastic L-systems), decomposition
// applied to every module produced in a step, cut `%`, and parameters stored as 32-bit floats.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "cpu/evaluator.h"
#include "cpu/module_string.h"
#include "ir/grammar.h"

namespace simeco::cpu {

// A default module budget sized to this machine's memory.
uint64_t defaultModuleBudget(int stride);

struct DeriveOptions {
    int steps = -1;          // -1: the grammar's derivation length
    int64_t seed = -1;       // -1: the grammar's `seed:` (or 0)
    uint32_t plants = 1;     // independent copies, each with its own random stream
    uint64_t maxModules = 0; // 0: defaultModuleBudget
    bool homomorphism = false; // return the string the turtle interprets: the result under the homomorphism
    // Carry each module's particle state (shared/particle_layout.h) through the derivation, into the result's
    // string.particles. The axioms' modules, all plants' in order, start with initialParticles, or at zero
    // when it is empty.
    bool particles = false;
    std::vector<shared::ParticleState> initialParticles;
};

struct DeriveResult {
    ModuleString string; // all plants, one segment each
    int steps = 0;       // steps performed by the plant that went furthest (fewer when a model called stop())
};

// Throws ir::InputError for evaluation errors (division by zero, ...) and ir::LimitError when the string
// outgrows the module budget.
DeriveResult deriveCpu(const ir::Grammar& g, const DeriveOptions& options);

// Plants of several species in one string: `species` share one alphabet (ir::unifySpecies) and plant p is of
// species p mod species.size(). Each species derives its own derivation length unless options.steps is set;
// the seed is options.seed, else the first species'. The stride is the largest of the species'.
DeriveResult deriveSpeciesCpu(const std::vector<ir::Grammar>& species, const DeriveOptions& options);

// DeriveOptions::initialParticles cut into each plant's axiom (zeros when it is empty). Throws
// std::invalid_argument unless it has one state for each module of the plants' axioms.
std::vector<std::vector<shared::ParticleState>> splitAxiomParticles(const std::vector<ir::Grammar>& species,
                                                                   uint32_t plants,
                                                                   const std::vector<shared::ParticleState>& initial);

// The string the turtle reads for a string derived elsewhere (on the GPU): each plant's modules under its
// species' homomorphism, with the globals as the Start block sets them.
ModuleString applyHomomorphismCpu(const std::vector<ir::Grammar>& species, const ModuleString& derived,
                                  const DeriveOptions& options);

// Random stream passes: a derivation step uses pass step * kPassesPerStep, decomposition at depth d in
// that step pass step * kPassesPerStep + 1 + d (depths past kPassesPerStep - 3 share the last one), and the
// control blocks the step's last pass.
inline constexpr uint32_t kPassesPerStep = 1024;

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
    case ControlBlock::Start: return {seed, plant, 0, 0, 0};
    case ControlBlock::StartEach: return {seed, plant, step * kPassesPerStep + kPassesPerStep - 1, 0, 0};
    case ControlBlock::EndEach: return {seed, plant, step * kPassesPerStep + kPassesPerStep - 1, 1, 0};
    case ControlBlock::End: break;
    }
    return {seed, plant, kPassesPerStep - 1, 2, 0};
}

} // namespace simeco::cpu
