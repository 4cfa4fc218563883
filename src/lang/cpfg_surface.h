// cpfg surface files (`.s`): bicubic Bezier patches that `~id` draws where a model's view names them
// (`surface: id file.s size [s t]`), tessellated as cpfg tessellates them.
#pragma once

#include <string>

#include "ir/leaf_model.h"

namespace simeco::lang {

// cpfg's most steps across a patch in either direction, and how many it takes when neither the view nor the file
// says.
inline constexpr int kSurfaceMostSteps = 10;
inline constexpr int kSurfaceDefaultSteps = 5;

// Reads a `.s` file: its control points moved to its contact point, turned from its own heading and up into the
// turtle's, scaled so that its SIZE becomes `size`, and each patch cut into `sSteps` x `tSteps` quads (0: the
// file's PRECISION line; cpfg then takes the S precision for both). A malformed file throws ir::InputError at
// the file, line and column.
ir::SurfaceModel readCpfgSurface(const std::string& path, float size, int sSteps = 0, int tSteps = 0);

// The same from the file's text.
ir::SurfaceModel parseCpfgSurface(const std::string& text, const std::string& file, float size, int sSteps = 0,
                                  int tSteps = 0);

} // namespace simeco::lang
