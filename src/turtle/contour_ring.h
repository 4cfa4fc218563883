// A generalized cylinder's cross-section sampled as cpfg samples it: `sides` + 1 points around the contour (the
// last a copy of the first where the contour is closed), evenly spaced along it, in the contour's own units.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "ir/cylinder_contour.h"

namespace simeco::turtle {

// The unit circle from (1, 0) counter-clockwise where `contour` is null. A closed contour is turned so that its
// curve starts on +x. An open one's last point falls a tenth of a span short of the curve's end, and a closed
// one's points in the gap its arc-length table leaves are extrapolated from the table's last step: cpfg's
// sampling, kept so that rings land where cpfg puts them.
std::vector<glm::vec3> contourRing(const ir::CylinderContour* contour, int sides);

} // namespace simeco::turtle
