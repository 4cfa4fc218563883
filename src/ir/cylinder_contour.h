// A generalized cylinder's cross-section: a cpfg view's `contour: id file` line names a file of control points
// of a uniform cubic B-spline (cpfg's cylinder contours), which `@#(id)` selects for the cylinder's next rings.
#pragma once

#include <array>
#include <vector>

namespace simeco::ir {

struct CylinderContour {
    int id = 0;
    bool closed = true;
    // 3 where the file gives z: a ring vertex then also moves along the cylinder's heading by its z.
    int dimension = 2;
    // The control points, each repeated as often as its multiplicity says (a triple end point ends the curve
    // there).
    std::vector<std::array<float, 3>> points;
};

} // namespace simeco::ir
