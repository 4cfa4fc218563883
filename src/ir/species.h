// Several grammars over one alphabet, so that plants of different species share one module stream.
//
// A SimEco scene holds several plants, each with its own rule set; deriving them in the same passes needs
// one symbol numbering. unifySpecies gives every grammar the union of the alphabets (symbols named alike are
// one symbol) and renumbers its axiom, productions and context filter to match. Plant p of a derivation
// over S species is of species p mod S.
#pragma once

#include <cstdint>
#include <vector>

#include "ir/grammar.h"

namespace simeco::ir {

// Copies of `grammars` sharing one alphabet; each keeps its rules, globals, blocks and settings.
std::vector<Grammar> unifySpecies(const std::vector<Grammar>& grammars);

inline uint32_t speciesOfPlant(uint32_t plant, size_t speciesCount) {
    return static_cast<uint32_t>(plant % speciesCount);
}

} // namespace simeco::ir
