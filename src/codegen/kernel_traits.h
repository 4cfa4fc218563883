// What a whole kernel needs from the productions of all species: whether its loops may run long, what it reads of
// a plant, the species' traits and func() tables, and the prelude and library every generated kernel starts with.
#pragma once

#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "codegen/derive_codegen.h"
#include "codegen/production_codegen.h"
#include "codegen/species_classes.h"
#include "ir/grammar.h"

namespace simeco::codegen {

// Whether the kernels of the `kind` rules of these species may loop so long that a driver ends their loops
// (lavapipe: 65535 iterations of an invocation in all): context walks, `while` and `do` statements, binomial
// draws, or very many elementary functions. Only those kernels end with reportLoopsCut (derive_lib.glsl); the
// others loop a bounded number of times and are spared its cost. `writing`: of a writing pass, which walks only
// some contexts (contextPrefetchCode).
bool mayLoopLong(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing);

// What the productions of the `kind` rules of these species read of their plant, besides their modules, in a
// matching pass or a `writing` one: a kernel whose productions need none of it skips finding the plant, which
// costs more than the rewriting of many grammars. A writing pass applies the production the match chose, drawing
// again only what the production's code draws, and the alternative unless the match passes it on
// (`alternativesGiven`).
struct PlantInputs {
    bool plant = false;  // the plant's index: several species, random draws, globals, arrays or stop()
    bool bounds = false; // where the plant's string begins and ends: contexts, predecessors of several modules
    bool random = false; // draws from the plant's random stream (which numbers them by module within the plant)
};
PlantInputs plantInputs(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing,
                        bool alternativesGiven = false);

// `double funcValue<species>(id, x, errorSite)`: the species' func() tables, appended to `tables`.
std::string functionTableCode(const ir::Grammar& g, size_t species, std::vector<double>& tables);

// `switch (species)` with body(species) in each case.
std::string perSpecies(size_t count, const std::function<std::string(size_t)>& body);
bool isStochastic(const ir::RuleSet& rules);

// What the kernels of these species need: brackets, cuts, decomposition depth, predecessor lengths.
GeneratedKernels speciesTraits(const std::vector<ir::Grammar>& species);

// The common start of every generated kernel: version, extensions, layouts, push constants, kSpeciesCount.
std::string kernelPrelude(size_t speciesCount);

// The functions every generated kernel shares after its buffers: speciesCode, bracket matching, derive_lib.glsl
// and the contour curves' evaluation.
std::string deriveLibrary(const SpeciesClasses& classes);

// What the kernels' speciesTable buffer holds: the context filter's rows of the classes' representatives
// (contextSkipBits), then, where species share code, each species' class, then, where classes hoist constants,
// where each species' row of hoisted values begins in funcTables.
std::vector<uint32_t> speciesTable(const SpeciesClasses& classes);

// The species' rows of hoisted values, one after another: the start of the kernels' funcTables buffer.
std::vector<double> hoistedTable(const SpeciesClasses& classes);

// `uint contextSkipWord(uint word)` (contextSkipCode), `uint speciesOf(uint plant)`: the class whose code plant
// runs, which is its species where every species is its own class, and, where classes hoist constants,
// `double hoisted(uint plant, uint k)`: the value of plant's species for its class's hoisted constant k.
std::string speciesCode(const SpeciesClasses& classes);
} // namespace simeco::codegen
