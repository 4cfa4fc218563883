// A plant's skeleton from a Wavefront OBJ file of polylines, as modelling tools export curves: each line element
// is one stem, and which stem grows from which is found from where they touch.
#pragma once

#include <string>

#include "skeleton/skeleton.h"

namespace simeco::skeleton {

// Reads one plant from `text`; `file` names it in errors. Vertices are `v x y z` (further values, such as a
// weight or a colour, are skipped); each line element `l i j k ...` is one stem through those vertices, with id
// 0, 1, ... in the order of the file, width 0 and its parent found by linkStemsByGeometry (the lowest end point is
// the plant's base). Indices count from 1; a negative one counts back from the last vertex read before it (-1);
// `i/t` takes the vertex index. `#` starts a comment; every other statement (`o`, `g`, `f`, `vt`, `usemtl`, ...)
// is skipped. A malformed number, an index out of range, a line element of fewer than two vertices and a file
// without line elements are refused at their line and column. The stems' structure is checked by checkSkeleton.
Skeleton parseObjSkeleton(const std::string& text, const std::string& file);

// Reads the OBJ file at `path`.
Skeleton readObjSkeleton(const std::string& path);

// The plant's stems as OBJ polylines (`v` and `l`), as parseObjSkeleton reads them back.
std::string skeletonObj(const Plant& plant, const std::string& comment);

} // namespace simeco::skeleton
