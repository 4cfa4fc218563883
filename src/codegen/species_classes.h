// Species that share their kernel code. An ecosystem often holds many species with the same rules (copies of
// one plant under other names, positions or derivation lengths): generating and compiling their productions
// once per copy made kernel size, and the driver's compile time, grow with the species rather than with the
// distinct rules. The kernels hold the code of one species of each class, and a plant finds its class through
// speciesOf(plant) (kernelPrelude).
#pragma once

#include <cstdint>
#include <vector>

#include "ir/grammar.h"

namespace simeco::codegen {

struct SpeciesClasses {
    // The first species of each class, in the order of the species; where the members' constants differ, with
    // those constants hoisted (hoisted_constants.h).
    std::vector<ir::Grammar> representatives;
    std::vector<uint32_t> classOf; // each species' class: an index into representatives
    // Each species' values of its class's hoisted constants, in the order of their indices (empty: none).
    std::vector<std::vector<double>> hoisted;
    // Every species is its own class: kernels need no table.
    bool distinct() const { return representatives.size() == classOf.size(); }
    bool hoists() const;
};

// Species share a class when everything their kernel code is made of is the same but for the constants in their
// productions' code: their productions and decompositions as generated code, the weights that choose among them,
// their decomposition depth, their func() tables and contour curves, and the symbols their context walks skip.
// The constants that differ among a class's members are hoisted.
SpeciesClasses classifySpecies(const std::vector<ir::Grammar>& species);

} // namespace simeco::codegen
