// cpfg colour maps (`.map`): 256 colours of three bytes each, indexed by the turtle's `;` colour.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ir/grammar.h"
#include "ir/picture_look.h"

namespace simeco::lang {

// An sRGB-encoded channel in [0, 1] as linear light.
float srgbToLinear(float c);

// The map's colours as linear RGB (the file holds sRGB bytes). Throws ir::InputError when the file is not
// 768 bytes.
std::vector<std::array<float, 3>> readColorMap(const std::string& path);

// The map at `path` in place of every species' own colours (cpfg's `-m` option). Throws ir::InputError as
// readColorMap does.
void useColorMap(std::vector<ir::Grammar>& species, const std::string& path);

// A picture's background by name: "sky", "paper", "colormap" or "#rrggbb" (sRGB); none for anything else.
std::optional<ir::Background> backgroundNamed(std::string_view name);

} // namespace simeco::lang
