// The context walks a kernel makes once per module ahead of its productions, and the context filter they read.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "codegen/production_codegen.h"
#include "ir/grammar.h"

namespace simeco::codegen {

// `void prefetchContexts(uint i, uint species, uint sym, int ctxLeft, uint ctxRight, uint pBegin, uint pEnd)`: the
// first walk of the context patterns of the `kind` rules of all species, which their FrameStyle::Fresh functions
// read from firstRight, firstRightBranch and firstLeft (derive_lib.glsl) instead of walking. Every kernel calling
// those functions calls it first, with module i and its symbol: only modules with such patterns walk, and of a
// step's, only those whose own parameters (ownParam) pass the comparisons of them that the production's condition
// makes before anything that may draw or fail.
// `writing`: only the walks a writing pass runs (of patterns whose parameters its statements or successors read).
std::string contextPrefetchCode(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing);

// Whether every module of some symbol walks to a first context module of the step's productions (their
// conditions do not decide it by the module's own parameters first): the walks of many modules, which the step's
// match pass may find by chunks instead (compute/derive/context_chunks.glsl). Where only modules with given
// parameters walk, few do, and finding every module's context modules costs more than their walks.
bool everyModuleOfASymbolWalks(const std::vector<ir::Grammar>& species);

// The constants context_chunks.glsl expects: which first context modules the step's productions read, and the
// words of a species' row of the context filter.
std::string contextChunkConstants(const std::vector<ir::Grammar>& species);

// One row of bits per species, set for the symbols its context walks skip (derive_lib.glsl's skipped()).
std::vector<uint32_t> contextSkipBits(const std::vector<ir::Grammar>& species);

// `uint contextSkipWord(uint word)`: the filter's words as constants, for derive_lib.glsl's skipped().
std::string contextSkipCode(const std::vector<uint32_t>& bits);

} // namespace simeco::codegen
