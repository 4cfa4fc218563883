// The CPU reference engine: derives a grammar exactly as cpfg does.
//
// Parallel rewriting with branch-aware left and right context (a closed branch is skipped, the end of a
// branch ends the right context, a `[` is passed on the way left), ignore/consider, the first applicable
// production in file order (or a weighted draw among applicable ones in stochastic L-systems), decomposition
// applied to every module produced in a step, cut `%`, and parameters stored as 32-bit floats.
#pragma once

#include <vector>

#include "ir/grammar.h"
#include "stream/derive_options.h"
#include "stream/module_string.h"

namespace simeco::cpu {

// Throws ir::InputError for evaluation errors (division by zero, ...) and ir::LimitError when the string
// outgrows the module budget.
stream::DeriveResult deriveCpu(const ir::Grammar& g, const stream::DeriveOptions& options);

// Plants of several species in one string: `species` share one alphabet (ir::unifySpecies) and plant p is of
// species p mod species.size(). Each species derives its own derivation length unless options.steps is set;
// the seed is options.seed, else the first species'. The stride is the largest of the species'.
stream::DeriveResult deriveSpeciesCpu(const std::vector<ir::Grammar>& species, const stream::DeriveOptions& options);

// The string the turtle reads for a string derived elsewhere (on the GPU): each plant's modules under its
// species' homomorphism, with the globals as the Start block sets them.
stream::ModuleString applyHomomorphismCpu(const std::vector<ir::Grammar>& species, const stream::ModuleString& derived,
                                  const stream::DeriveOptions& options);

} // namespace simeco::cpu
