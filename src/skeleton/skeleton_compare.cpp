#include "skeleton/skeleton_compare.h"

#include <algorithm>

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace simeco::skeleton {

namespace {

struct Segment {
    glm::dvec3 start, end;
    int stem = 0;
    size_t index = 0;
};

std::vector<Segment> segmentsOf(const Plant& plant) {
    std::vector<Segment> out;
    for (const Stem& s : plant.stems)
        for (size_t k = 0; k + 1 < s.points.size(); ++k) out.push_back({s.points[k], s.points[k + 1], s.id, k});
    return out;
}

} // namespace

SegmentMatch matchSegments(const Plant& a, const Plant& b, double tolerance) {
    SegmentMatch match;
    std::vector<Segment> first = segmentsOf(a), second = segmentsOf(b);
    match.segments = first.size();
    match.otherSegments = second.size();
    const double size = plantSize(a) > 0.0 ? plantSize(a) : 1.0;
    const double reach = tolerance * size;
    std::sort(second.begin(), second.end(), [](const Segment& x, const Segment& y) { return x.start.x < y.start.x; });
    std::vector<bool> taken(second.size(), false);
    for (const Segment& s : first) {
        auto from = std::lower_bound(second.begin(), second.end(), s.start.x - reach,
                                     [](const Segment& x, double v) { return x.start.x < v; });
        size_t best = second.size();
        double bestError = reach;
        for (auto it = from; it != second.end() && it->start.x <= s.start.x + reach; ++it) {
            size_t k = size_t(it - second.begin());
            double error = std::max(glm::length(it->start - s.start), glm::length(it->end - s.end));
            if (!taken[k] && error <= bestError) {
                best = k;
                bestError = error;
            }
        }
        if (best == second.size()) {
            if (match.firstUnmatched.empty())
                match.firstUnmatched = fmt::format("segment {} of stem {}, ({:.6g}, {:.6g}, {:.6g}) to ({:.6g}, "
                                                   "{:.6g}, {:.6g})",
                                                   s.index, s.stem, s.start.x, s.start.y, s.start.z, s.end.x, s.end.y,
                                                   s.end.z);
            continue;
        }
        taken[best] = true;
        ++match.matched;
        match.worst = std::max(match.worst, bestError / size);
    }
    return match;
}

} // namespace simeco::skeleton
