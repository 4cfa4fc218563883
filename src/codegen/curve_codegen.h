// Contour curves in generated kernels: each species' curves become records in the tables buffer, read by
// derive/contour_curve.glsl, and one function per species that finds a curve by its id.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "ir/grammar.h"

namespace simeco::codegen {

// `double curveValue<species>(double id, int axis, double t, uint errorSite)`: axis 0, 1, 2 give curveX, Y, Z at
// t, axis 3 curveGAL. Reports errorSite for an id the view file does not define. The records are appended to
// `tables`.
std::string curveTableCode(const ir::Grammar& g, size_t species, std::vector<double>& tables);

} // namespace simeco::codegen
