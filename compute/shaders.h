// The compute kernels compiled at build time, embedded as SPIR-V words and looked up by name.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace simeco::shaders {

// The SPIR-V of a kernel, named by its path under compute/ without ".comp" (e.g. "scan/reduce").
// Throws std::out_of_range for an unknown name: a typo is a programming error, found on first use.
std::span<const std::uint32_t> spirv(std::string_view name);

// The text of a GLSL file kept for kernels generated at run time, e.g. "derive/derive_lib.glsl".
std::string_view glslSource(std::string_view name);

// Every embedded kernel's name, in build order.
std::vector<std::string_view> names();

} // namespace simeco::shaders
