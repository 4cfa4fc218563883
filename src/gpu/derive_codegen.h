// Grammar-specialised derivation kernels: the IR compiled to GLSL.
//
// Each production becomes a function that walks its contexts, binds its parameters, runs its statements and
// condition as straight-line code and, when asked, writes its successor. Four kernels use them: the match and
// write passes of a derivation step, and the match and write passes of a decomposition depth. The host's
// control blocks (Start, StartEach, ...) stay on the CPU; productions only read globals.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ir/grammar.h"

namespace simeco::gpu {

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
    std::vector<ErrorSite> errors;
    bool needsBrackets = false;     // contexts, cuts or `=` need matching brackets
    bool mayCut = false;            // a `%` can appear in the string
    bool hasDecomposition = false;
    uint32_t longestPredecessor = 1; // > 1: the greedy walk decides which modules start a rewrite
    std::vector<double> functionTables; // the sampled func() tables, concatenated
};

// The GLSL of the kernels for grammar g (parameter slots per module come at run time, in the push constants).
// The grammar must be supported (gpuUnsupportedReason(g) empty).
GeneratedKernels generateDeriveKernels(const ir::Grammar& g);

} // namespace simeco::gpu
