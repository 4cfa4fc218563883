// cpfg's generalized-cylinder contour files (`contour: id file` lines of a view file): `cver 1 1`, `cver 1 2` and
// `cver 1 3` (`name:`, `points: N M`, `type: o|c r`, `samples:` — read and ignored, as cpfg does — then N lines
// `x y z multiplicity` whose multiplicities sum to M), or the older `N dimension open|closed` then N points.
#pragma once

#include <string>

#include "ir/cylinder_contour.h"

namespace simeco::lang {

// Throws ir::InputError at the line and column of anything malformed.
ir::CylinderContour parseCylinderContour(const std::string& text, const std::string& file);

// Reads the file at `path` (ir::InputError for a missing or unreadable one).
ir::CylinderContour readCylinderContour(const std::string& path);

} // namespace simeco::lang
