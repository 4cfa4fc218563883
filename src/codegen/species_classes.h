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
    std::vector<ir::Grammar> representatives; // the first species of each class, in the order of the species
    std::vector<uint32_t> classOf;            // each species' class: an index into representatives
    // Every species is its own class: kernels need no table.
    bool distinct() const { return representatives.size() == classOf.size(); }
};

// Species share a class when everything their kernel code is made of is the same: their productions and
// decompositions as generated code, the weights that choose among them, their decomposition depth, their
// func() tables and contour curves, and the symbols their context walks skip.
SpeciesClasses classifySpecies(const std::vector<ir::Grammar>& species);

} // namespace simeco::codegen
