// The renderer's shaders compiled at build time, embedded as SPIR-V words and looked up by file name.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace simeco::render_shaders {

// The SPIR-V of a shader in render/, named by its file name (e.g. "organ.vert", "draw_args.comp").
// Throws std::out_of_range for an unknown name: a typo is a programming error, found on first use.
std::span<const std::uint32_t> spirv(std::string_view name);

// Every embedded shader's name, in build order.
std::vector<std::string_view> names();

} // namespace simeco::render_shaders
