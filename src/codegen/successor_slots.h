// Successor slots: where the productions of the parallel passes write their successors, so that a kernel stores
// each module of a successor once, and the code that stores them.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "codegen/production_codegen.h"
#include "ir/grammar.h"

namespace simeco::codegen {

// Whether a string whose plants are balanced stays so, its brackets paired as before or within one successor:
// every successor is balanced, no production rewrites a bracket, and no context asks for the end of a branch
// (`=`, which needs the bracket tree). A step's write pass can then give the brackets it writes their partners
// (GeneratedKernels::carriesPartners).
bool successorsKeepBracketsBalanced(const std::vector<ir::Grammar>& species);

// Where the productions of FrameStyle::Fresh write their successor, so that a kernel stores each module of a
// successor once, whichever production wrote it, instead of once per production: module j of the successor goes
// to slotWord<j> (symbol | parameter count << kSymbolBits), its parameter a to slotParam<j>_<a> and, when it is a
// bracket the successor pairs, its partner's index in the successor to slotPartner<j>.
struct SuccessorSlots {
    std::vector<uint32_t> params; // per slot: the most parameters a module there has
    std::vector<bool> pairs;      // per slot: some successor pairs a bracket there
};

// The slots of the `kind` rules of these species; slot 0 has room for `copiedParams` (the module copied when no
// production applies goes there).
SuccessorSlots successorSlots(const std::vector<ir::Grammar>& species, RuleKind kind, uint32_t copiedParams);
std::string slotDeclarations(const SuccessorSlots& slots);

// `void storeSlots(uint pos, uint n, uint origin)`: the first n slots into symOut/parOut at pos, with the
// module's origin and liveness (`provenance`) and the partners of the brackets paired (`partners`).
// `paramVector` > 1: parOut is an array of vec<paramVector>, one per module (the stride), and a module's
// parameters are one store; its slots past the module's parameters get zeros.
std::string slotStoreCode(const SuccessorSlots& slots, bool provenance, bool partners, uint32_t paramVector = 1);

// The width of the vectors a kernel with this parameter stride stores a module's parameters as: 2 or 4, or 1
// where no vector type has that stride in std430 layout.
uint32_t parameterVectorWidth(uint32_t stride);

// Marks the slots that may hold paired brackets as holding none (before a production writes them).
std::string resetSlotPartners(const SuccessorSlots& slots);

} // namespace simeco::codegen
