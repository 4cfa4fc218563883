// The CPU reference engine: derives a grammar exactly as cpfg does.
//
// Parallel rewriting with branch-aware left and right context (a closed branch is skipped, the end of a
// branch ends the right context, a `[` is passed on the way left), ignore/consider, the first applicable
// production in file order (or a weighted draw among applicable ones in stochastic L-systems), decomposition
// applied to every module produced in a step, cut `%`, and parameters stored as 32-bit floats.
#pragma once

#include <cstdint>

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
};

struct DeriveResult {
    ModuleString string; // all plants, one segment each
    int steps = 0;       // steps performed (fewer than asked when a model called stop())
};

// Throws ir::InputError for evaluation errors (division by zero, ...) and ir::LimitError when the string
// outgrows the module budget.
DeriveResult deriveCpu(const ir::Grammar& g, const DeriveOptions& options);

// Random stream passes: a derivation step uses pass step * kPassesPerStep, decomposition at depth d in
// that step pass step * kPassesPerStep + 1 + d.
inline constexpr uint32_t kPassesPerStep = 1024;

} // namespace simeco::cpu
