// Productions as GLSL functions, shared by the kernel generators (derive_codegen.h).
//
// A production becomes straight-line code that walks its contexts, binds its parameters, runs its statements
// and condition and writes its successor: into the successor slots (SuccessorSlots), which the kernel stores,
// or through emitModule/emitParam, which the kernel defines. Two styles: the parallel passes give every
// application fresh locals, in one function run in four modes, and use the slots; the
// sequential kernel keeps cpfg's one variable table per production (locals carry over between applications)
// and splits testing from producing so that statements with side effects run once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "codegen/derive_codegen.h"
#include "ir/grammar.h"

namespace simeco::codegen {

enum class RuleKind { Step, Decomposition };

enum class FrameStyle {
    Fresh,      // `bool NAME(..., uint mode, out uint outCount)`: mode 0 tests, 1 also runs the after-statements,
                // draws the alternative and sets outCount, 2 also writes the successor into the slots, 3 does
                // what 2 does with the alternative the match pass drew (givenAlternative) instead of drawing it
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

} // namespace simeco::codegen
