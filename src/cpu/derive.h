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
#include "stream/plant_control.h"

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

// Derivation step by step over simulated time, the reference of GpuDeriver::begin, advance, current and drawn:
// the plants start from their axioms; advance() derives one more step of the plants `due` flags that have steps
// left (the others are copied) and returns how many derived, their random draws keyed by the count of advance()
// calls, whether any of its plants derived or none (so that a field's batches, each called at every advance of the
// field, share it); current() is the derived string, whose particle state the simulation updates between
// steps; drawn() is it under the homomorphism, and with `origins` each drawn module's index in current() (where the
// derivation carries particle state).
class SteppedDerivation {
public:
    SteppedDerivation(const std::vector<ir::Grammar>& species, const stream::DeriveOptions& options);
    uint32_t advance(const std::vector<uint8_t>& due);
    stream::ModuleString& current() { return string_; }
    const stream::ModuleString& current() const { return string_; }
    stream::ModuleString drawn(std::vector<uint32_t>* origins = nullptr) const;
    uint32_t plants() const { return control_.plants(); }
    // Where the derivation stands, and back to it (a state saved from a derivation of the same species and
    // options, on either engine).
    stream::SteppedState save() const;
    void resume(const stream::SteppedState& state);

private:
    const std::vector<ir::Grammar>& species_;
    stream::DeriveOptions options_;
    stream::PlantControl control_;
    stream::ModuleString string_;
    uint32_t fieldStep_ = 0;
};

} // namespace simeco::cpu
