// Which stem grows from which, found from where loose polylines touch (an OBJ file's lines, three views drawn
// without parents). This follows the L-grammar generator's thesis (seed 002, section 3.3): a stem's level is its
// number of hops from the root along the shortest path, and of two touching stems the one of lower level is the
// parent.
#pragma once

#include "skeleton/skeleton.h"

namespace simeco::skeleton {

// Whether a stem's points are known to run from its base (views drawn base to tip), or either end may be its base
// (an OBJ file's polylines, in whatever direction the modeller drew them).
enum class StemDirection { Unknown, BaseFirst };

// Gives the stems of `plant` their parents and, where their direction is Unknown, turns each to run from the end
// where it grows. The plant's base is the lowest end point (least y) of all stems; the stem that has it is the
// root (parent -1), turned to start there. Then level by level, breadth first: a stem with an end (its first
// point where BaseFirst) within `tolerance` of a stem of the level before (of one of its points or segments)
// becomes the child of the nearest such stem and starts at that end. Stems that never touch keep parent -1, so
// that checkPlant reports that the plant falls apart. `attach` is left as it is (-1: checkPlant finds the
// parent's point, inserting one where the base lies on a segment).
void linkStemsByGeometry(Plant& plant, double tolerance, StemDirection direction = StemDirection::Unknown);

} // namespace simeco::skeleton
