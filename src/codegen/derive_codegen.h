// Grammar-specialised derivation kernels: the IR compiled to GLSL.
//
// Each production becomes a function that walks its contexts, binds its parameters, runs its statements and
// condition as straight-line code and, when asked, writes its successor (production_codegen.h). The parallel
// strategy rewrites every module at once with four kernels: the match and write passes of a derivation step,
// and the match and write passes of a decomposition depth; its productions only read globals. The sequential
// strategy covers the rest. The host's control blocks (Start, StartEach, ...) stay on the CPU.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ir/grammar.h"

namespace simeco::codegen {

// A place in the grammar where evaluation can fail on the device (division by zero, an array index out of
// range, an endless loop, an unknown function id); kernels report the index of the first one they hit.
struct ErrorSite {
    ir::SourceLoc loc;
    std::string message;
};

struct GeneratedKernels {
    std::string match;              // derivation step: choose productions, count successors
    std::string write;              // derivation step: write successors at their offsets
    std::string decompositionMatch; // one decomposition depth: choose, count
    std::string decompositionWrite; // one decomposition depth: write
    std::string sequential;         // the sequential strategy: one invocation per plant rewrites it in order
    uint32_t frameSlots = 0;        // sequential: persistent locals per plant
    uint32_t stackWidth = 1;        // sequential: the longest successor (modules per decomposition stack level)
    std::vector<ErrorSite> errors;
    bool needsBrackets = false;     // contexts, cuts or `=` need matching brackets
    bool mayCut = false;            // a `%` can appear in the string
    bool hasDecomposition = false;
    int maxDecompositionDepth = 0;  // the deepest of the species' decompositions
    uint32_t longestPredecessor = 1; // > 1: the greedy walk decides which modules start a rewrite
    // The step's scan is fused into match and write (see generateDeriveKernels): match also writes each
    // tile's sum of counts, and write takes the scanned sums and counts instead of offsets. Match then
    // stores one word per module, the counts before it in its tile above its choice's choiceBits bits (the
    // production and, where the write pass is given it, the alternative the match drew).
    bool fusedScan = false;
    uint32_t choiceBits = 1;
    // The step's write pass also writes the partners of the brackets of the string it writes
    // (codegen::carriesBracketPartners), into the binding after its own outputs.
    bool carriesPartners = false;
    // The step's match pass (with a fused scan) finds its productions' first context modules by chunks of
    // kContextChunk modules an invocation (compute/derive/context_chunks.glsl), which are then its tiles: where
    // asked and every module of some symbol walks (codegen::everyModuleOfASymbolWalks).
    bool chunkedMatch = false;
    // The step's match and write passes find each module's plant for their productions (codegen::plantInputs);
    // otherwise only the match pass does while some plant is frozen (pc.frozenPlants), and the plant hints are
    // needed only then. Both passes have a variant specialised for a stream of one plant (kSinglePlant), which
    // finds nothing.
    bool matchFindsPlants = false;
    bool writeFindsPlants = false;
    std::vector<double> functionTables; // hoisted constants, the sampled func() tables and contour curves, concatenated
    // The speciesTable buffer the kernels read (codegen::speciesTable): the context filter's rows of the classes
    // of species that share code (species_classes.h) and, where some do, each species' class.
    std::vector<uint32_t> speciesTable;
    // Parameter slots per module that the step's write pass was generated for (it stores them as vectors where
    // it can): the species' most parameters, at least 1, the host's stride.
    uint32_t stride = 1;
    // The step's match and write passes read a module's own parameters as one vector of `stride` floats
    // (codegen::parameterVectorWidth), from a binding after plantHints: the parameters viewed as such vectors.
    bool matchReadsParameterVectors = false;
    bool writeReadsParameterVectors = false;
    // The productions call light(): the step's and decomposition's passes read the particles of the string being
    // rewritten, from a binding after all their others (moduleLightCode).
    bool readsLight = false;
};

// The GLSL of the kernels for plants of the given species (one alphabet: ir::unifySpecies); plant p is of
// species p mod species.size(). Species with the same rules share their code (classifySpecies). Parameter slots per module come at run time, in the push constants. Every
// species must be supported (gpuUnsupportedReason empty). `texelInputs`: the kernels read the string and the
// per-module results of earlier passes through uniform texel buffers (codegen::Bindings), which the host
// binds as such (the dispatch reads the binding types from the kernels). `contextChunks`: the step's match pass
// finds first context modules by chunks where its productions read them (GeneratedKernels::chunkedMatch).
// `sensesLight`: light() reads the particles (a derivation's kernels); else it is 1 (the homomorphism's, as the
// CPU's drawing).
GeneratedKernels generateDeriveKernels(const std::vector<ir::Grammar>& species, bool texelInputs = false,
                                       bool contextChunks = false, bool sensesLight = true);

// light(), as the generated kernels define it before their productions: with `particles`, the light of module
// `lightModule`'s particle times pc.lightScale (1 where the scale is 0 or the particle is not yet born), from
// the binding `particles`; without, 1.
std::string moduleLightCode(bool particles);

// The sequential strategy's kernel (sequential_codegen.cpp): one invocation per plant walks the plant's string
// in order, exactly as the CPU reference does, so productions may write globals and arrays, locals carry over
// between applications, stop() works and decomposition runs depth-first with an explicit stack. Run twice
// per step: mode 0 counts each plant's modules (on copies of the state), mode 1 writes them and the state.
GeneratedKernels generateSequentialKernel(const std::vector<ir::Grammar>& species, bool texelInputs = false);

} // namespace simeco::codegen
