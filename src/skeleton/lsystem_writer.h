// The inferred plant as a cpfg L-system (`simeco infer -o plant.l`), for users of cpfg, L-studio and L-Py: the same
// initial state as the SimEco script, a production per internode, its turns written as cpfg's roll `/` and pitch
// `&` in degrees, its length and width as `!(w)F(l)`.
#pragma once

#include <string>

#include "skeleton/infer.h"

namespace simeco::skeleton {

// `growth` must be a cpfg regrowth (Dialect::Cpfg). `source` names what the skeleton came from, for the opening
// comment.
std::string lsystemText(const Plant& plant, const Regrowth& growth, const std::string& source);

// The view file that goes beside it (same name, .v): stems drawn as cylinders of their widths in the plant's units,
// where cpfg's default would draw lines a pixel wide.
std::string lsystemView();

} // namespace simeco::skeleton
