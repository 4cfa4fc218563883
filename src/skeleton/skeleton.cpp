#include "skeleton/skeleton.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

namespace simeco::skeleton {

const char* organKindName(OrganKind kind) {
    switch (kind) {
    case OrganKind::Leaf: return "leaf";
    case OrganKind::Flower: return "flower";
    case OrganKind::Fruit: return "fruit";
    }
    return "leaf";
}

double plantSize(const Plant& plant) {
    glm::dvec3 lo(1e300), hi(-1e300);
    bool any = false;
    for (const Stem& s : plant.stems)
        for (const glm::dvec3& p : s.points) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            any = true;
        }
    return any ? glm::length(hi - lo) : 0.0;
}

size_t segmentCount(const Plant& plant) {
    size_t n = 0;
    for (const Stem& s : plant.stems) n += s.points.empty() ? 0 : s.points.size() - 1;
    return n;
}

} // namespace simeco::skeleton
