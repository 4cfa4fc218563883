// The shaders of compute/ and render/, compiled at build time, embedded as SPIR-V words and looked up by name;
// and the GLSL sources that kernels generated at run time are made of.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace simeco::shaders {

// The SPIR-V of a shader, named by its path under compute/ or render/ without the `.comp` of a compute kernel
// (e.g. "scan/reduce", "organs/organ.vert"). Throws std::out_of_range for an unknown name: a typo is a
// programming error, found on first use.
std::span<const std::uint32_t> spirv(std::string_view name);

// Every embedded shader's name, in build order.
std::vector<std::string_view> names();

// The text of a GLSL file kept for kernels generated at run time, named by its path from the repository root
// (e.g. "compute/derive/derive_lib.glsl"), with the files it includes inlined where it includes them, each
// once: generated kernels are compiled from one text, which is also what their cache is keyed by. Throws
// std::out_of_range for a file that is not kept.
std::string glslSource(std::string_view name);

// The file's own text, or nothing when it is not kept.
std::optional<std::string_view> embeddedGlslText(std::string_view name);

} // namespace simeco::shaders
