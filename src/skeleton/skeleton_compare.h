// Whether two skeletons are the same plant: their segments (consecutive points of a stem) matched one to one by
// their end points, however the segments are grouped into stems.
#pragma once

#include <string>

#include "skeleton/skeleton.h"

namespace simeco::skeleton {

struct SegmentMatch {
    size_t segments = 0;      // of the first plant
    size_t otherSegments = 0; // of the second
    size_t matched = 0;       // pairs found within the tolerance, each segment in one pair at most
    double worst = 0.0;       // the largest end-point distance among the pairs, relative to the first plant's size
    std::string firstUnmatched; // a segment of the first plant without a partner, for messages

    bool same() const { return matched == segments && matched == otherSegments; }
};

// Matches every segment of `a` with one of `b` whose start and end lie within `tolerance` times a's size of its
// own.
SegmentMatch matchSegments(const Plant& a, const Plant& b, double tolerance = 1e-4);

} // namespace simeco::skeleton
