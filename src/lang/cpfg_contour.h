// cpfg contour curve files (`.con`, named by `curve:` lines of a view file), read as cpfg's CCurveXYZ
// reads them: `version:`, `contact:`, `end:`, `heading:`, `up:`, `size:`, `range:` header lines,
// `points: N`, `dimension: D` (2 to 4, default 2), `type: bspline | bspline-closed | bspline-endpoint |
// bspline-phantom | bezier`, then N lines `x y [z [multiplicity]]` with D numbers each.
#pragma once

#include <string>

#include "ir/contour_curve.h"
#include "ir/source_loc.h"

namespace simeco::lang {

// Reads a `.con` file and samples it with cpfg's default of 100 samples (call ir::sampleContourCurve again
// for the count a `curve: FILE SAMPLES` line gives). Throws ir::InputError for a missing or malformed file.
ir::ContourCurve parseContourFile(const std::string& path);

} // namespace simeco::lang
