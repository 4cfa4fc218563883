// What the GPU strategies can derive exactly as the CPU reference does (derive_support.cpp says why).
#pragma once

#include <optional>
#include <string>

#include "ir/grammar.h"

namespace simeco::codegen {

// Why a grammar cannot be derived on the GPU at all, or nothing when it can.
std::optional<std::string> gpuUnsupportedReason(const ir::Grammar& g);
// Why a grammar needs the sequential strategy rather than the parallel passes, or nothing.
std::optional<std::string> gpuParallelUnsupportedReason(const ir::Grammar& g);

} // namespace simeco::codegen
