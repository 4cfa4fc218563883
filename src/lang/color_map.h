// cpfg colour maps (`.map`): 256 colours of three bytes each, indexed by the turtle's `;` colour.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace simeco::lang {

// An sRGB-encoded channel in [0, 1] as linear light.
float srgbToLinear(float c);

// The map's colours as linear RGB (the file holds sRGB bytes). Throws ir::InputError when the file is not
// 768 bytes.
std::vector<std::array<float, 3>> readColorMap(const std::string& path);

} // namespace simeco::lang
