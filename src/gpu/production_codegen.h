// Productions as GLSL functions, shared by the kernel generators (derive_codegen.h).
//
// A production becomes straight-line code that walks its contexts, binds its parameters, runs its statements
// and condition and writes its successor: into the successor slots (SuccessorSlots), which the kernel stores,
// or through emitModule/emitParam, which the kernel defines. Two styles: the parallel passes give every
// application fresh locals, in one function run in three modes, and use the slots; the
// sequential kernel keeps cpfg's one variable table per production (locals carry over between applications)
// and splits testing from producing so that statements with side effects run once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "gpu/derive_codegen.h"
#include "ir/grammar.h"

namespace simeco::gpu::codegen {

enum class RuleKind { Step, Decomposition };

enum class FrameStyle {
    Fresh,      // `bool NAME(..., uint mode, out uint outCount)`: mode 0 tests, 1 also runs the after-statements
                // and sets outCount, 2 also writes the successor into the slots
    Persistent, // `bool NAMETest(..., uint frame)` and `void NAMEProduce(..., uint frame, out uint outCount)`
                // with the locals in frames[frame ...], the successor emitted at positions 0, 1, ...
};

// The storage buffer declarations of a kernel, bound in the order they are added.
class Bindings {
public:
    // `texelInputs`: inputs are uniform texel buffers rather than storage buffers. On lavapipe a texel fetch is
    // a gather, while a storage buffer load runs a loop over the subgroup's invocations.
    explicit Bindings(bool texelInputs) : texelInputs_(texelInputs) {}

    void add(const char* access, const char* type, const char* name);
    // A read-only array of 32-bit `type` (uint, int or float) that the kernel reads through `NAMEAt(uint i)`.
    void addInput(const char* type, const char* name);
    // A read-only array of vectors of `width` floats (2 or 4) that the kernel reads through `NAMEAt(uint i)`.
    void addVectorInput(uint32_t width, const char* name);
    // The first bindings of every derivation kernel: the string being rewritten, its brackets, the plants'
    // state (written only by the sequential kernel), function tables, the context filter, the error word and
    // the frozen plants.
    void addShared(bool stateWritable);
    const std::string& text() const { return text_; }

private:
    bool texelInputs_;
    std::string text_;
    int next_ = 0;
};

// A double literal with every digit of the value.
std::string literal(double v);

std::string functionName(size_t species, RuleKind kind, size_t index);

// Words of one species' row in the context filter buffer (derive_lib.glsl's skipped()).
uint32_t skipWords(const ir::Grammar& g);

// Production `index` of species `species`. Persistent frames live at frames[frameOffset + slot] of the plant's
// frame block (`frame` argument). Error sites are appended to `errors`.
void emitProduction(const ir::Grammar& g, size_t species, const ir::Production& p, RuleKind kind, size_t index,
                    FrameStyle style, std::vector<ErrorSite>& errors, std::string& out);

// `void prefetchContexts(uint i, uint species, uint sym, int ctxLeft, uint ctxRight, uint pBegin, uint pEnd)`: the
// first walk of the context patterns of the `kind` rules of all species, which their FrameStyle::Fresh functions
// read from firstRight, firstRightBranch and firstLeft (derive_lib.glsl) instead of walking. Every kernel calling
// those functions calls it first, with module i and its symbol: only modules with such patterns walk, and of a
// step's, only those whose own parameters (ownParam) pass the comparisons of them that the production's condition
// makes before anything that may draw or fail.
// `writing`: only the walks a writing pass runs (of patterns whose parameters its statements or successors read).
std::string contextPrefetchCode(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing);

// Whether a string whose plants are balanced stays so, its brackets paired as before or within one successor:
// every successor is balanced, no production rewrites a bracket, and no context asks for the end of a branch
// (`=`, which needs the bracket tree). A step's write pass can then give the brackets it writes their partners
// (GeneratedKernels::carriesPartners).
bool successorsKeepBracketsBalanced(const std::vector<ir::Grammar>& species);

// Whether the kernels of the `kind` rules of these species may loop so long that a driver ends their loops
// (lavapipe: 65535 iterations of an invocation in all): context walks, `while` and `do` statements, binomial
// draws, or very many elementary functions. Only those kernels end with reportLoopsCut (derive_lib.glsl); the
// others loop a bounded number of times and are spared its cost. `writing`: of a writing pass, which walks only
// some contexts (contextPrefetchCode).
bool mayLoopLong(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing);

// What the productions of the `kind` rules of these species read of their plant, besides their modules, in a
// matching pass or a `writing` one: a kernel whose productions need none of it skips finding the plant, which
// costs more than the rewriting of many grammars.
struct PlantInputs {
    bool plant = false;  // the plant's index: several species, random draws, globals, arrays or stop()
    bool bounds = false; // where the plant's string begins and ends: contexts, predecessors of several modules
    bool random = false; // draws from the plant's random stream (which numbers them by module within the plant)
};
PlantInputs plantInputs(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing);

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

// One row of bits per species, set for the symbols its context walks skip (derive_lib.glsl's skipped()).
std::vector<uint32_t> contextSkipBits(const std::vector<ir::Grammar>& species);

// `double funcValue<species>(id, x, errorSite)`: the species' func() tables, appended to `tables`.
std::string functionTableCode(const ir::Grammar& g, size_t species, std::vector<double>& tables);

// `switch (species)` with body(species) in each case.
std::string perSpecies(size_t count, const std::function<std::string(size_t)>& body);

bool isStochastic(const ir::RuleSet& rules);

// What the kernels of these species need: brackets, cuts, decomposition depth, predecessor lengths.
GeneratedKernels speciesTraits(const std::vector<ir::Grammar>& species);

// The common start of every generated kernel: version, extensions, layouts, push constants, kSpeciesCount.
std::string kernelPrelude(size_t speciesCount);

// The functions every generated kernel shares after its buffers: the species' context filter, bracket matching,
// derive_lib.glsl and the contour curves' evaluation.
std::string deriveLibrary(const std::vector<ir::Grammar>& species);

} // namespace simeco::gpu::codegen
