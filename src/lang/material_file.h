// cpfg material files (`.mat`, `cpfg -M`): up to 256 materials of 15 bytes each — index, transparency, then
// ambient, diffuse, specular and emission RGB bytes and the shininess — indexed by the turtle's `;` like a
// colour map.
#pragma once

#include <array>
#include <string>
#include <vector>

namespace simeco::lang {

// The materials' diffuse colours as linear RGB, by material index (256 entries; an index the file does not
// describe stays black). simeco's lighting is diffuse, so ambient, specular, emission and shininess are read
// past. Throws ir::InputError when the file is not a whole number of 15-byte materials.
std::vector<std::array<float, 3>> readMaterialColors(const std::string& path);

} // namespace simeco::lang
