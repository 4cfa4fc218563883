// Compiling generated GLSL compute kernels to SPIR-V at run time with the glslang library, with a disk cache
// keyed by a hash of the source, so a grammar's kernels are compiled once per machine.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace simeco::codegen {

// Throws std::runtime_error with glslang's log when the source does not compile (a code-generation bug).
std::vector<std::uint32_t> compileComputeKernel(const std::string& source, const std::string& name);

// compileComputeKernel through the cache: $SIMECO_KERNEL_CACHE, else $XDG_CACHE_HOME/simeco/kernels, else
// ~/.cache/simeco/kernels. A cache that cannot be written is skipped silently.
std::vector<std::uint32_t> cachedComputeKernel(const std::string& source, const std::string& name,
                                               bool* fromCache = nullptr);

} // namespace simeco::codegen
