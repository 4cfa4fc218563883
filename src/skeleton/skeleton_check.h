// What makes a skeleton one plant: stems of two or more distinct finite points, parents that exist and do not
// loop, each stem starting on its parent, and every stem without a parent starting at the plant's base.
#pragma once

#include <string>

#include "skeleton/skeleton.h"

namespace simeco::skeleton {

// Checks plant `index` of the skeleton read from `file`, and completes it: a stem whose `attach` is -1 gets the
// parent's point its base lies on (a point inserted into the parent where the base lies on a segment). Refuses a
// malformed plant with an ir::InputError naming the stem and what is wrong: a stem of fewer than two points, two
// consecutive points that coincide (a segment of no length), a point that is not finite, an id used twice, a
// parent that does not exist or parents that loop back, a stem that does not start on its parent, a stem without
// a parent away from the plant's base (the plant falls apart), or an organ on a point that does not exist.
void checkPlant(Plant& plant, const std::string& file, size_t index);

// Checks every plant of the skeleton (checkPlant); refuses a skeleton without plants.
void checkSkeleton(Skeleton& skeleton, const std::string& file);

// How close two points must be to count as one, for a plant of `size`.
inline double samePointTolerance(double size) { return 1e-5 * (size > 0.0 ? size : 1.0); }

} // namespace simeco::skeleton
