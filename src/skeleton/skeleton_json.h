// The skeleton's JSON file (docs/SKELETON.md): plants, their stems as polylines with parent links, and the leaves,
// flowers and fruits on them.
#pragma once

#include <string>

#include "skeleton/skeleton.h"

namespace simeco::skeleton {

// The file's text: numbers with nine significant digits, one point per line.
std::string skeletonJson(const Skeleton& skeleton);

// Reads a skeleton from `text`; `file` names it in errors. A file that is not JSON is refused at its line and
// column; a value of the wrong type or shape, or a number that is not finite, by its place in the document (a
// JSON pointer such as /plants/0/stems/3/points/2). The stems' structure is checked by checkSkeleton.
Skeleton parseSkeletonJson(const std::string& text, const std::string& file);

// Reads the skeleton file at `path`.
Skeleton readSkeletonJson(const std::string& path);

} // namespace simeco::skeleton
