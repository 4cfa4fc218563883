// The skeleton as the L-Grammar Generator of seed 002 sees it: straight stems (here internodes: the segments
// between consecutive points of a polyline), each with its length (the distance of its end points), its level (the
// hops from the plant's base along the skeleton, the shortest path), its parent and children, and among the
// children the main one (the smallest angle to the parent's direction) and the branches.
#pragma once

#include <vector>

#include <glm/vec3.hpp>

#include "skeleton/skeleton.h"

namespace simeco::skeleton {

struct Internode {
    int stem = 0;         // the skeleton stem it is a segment of
    size_t segment = 0;   // from point `segment` to point `segment + 1` of that stem
    glm::dvec3 start{0.0}, end{0.0};
    double length = 0.0;
    double width = 0.0;
    int parent = -1;             // the internode it starts at the end of; -1 where it stands on the plant's base
    int level = 0;               // 0 for the internodes standing on the base
    std::vector<int> children;   // starting at its end: the main child first, then the branches in skeleton order
    std::vector<int> organs;     // the plant's organs sitting at its end
};

struct InternodeTree {
    std::vector<Internode> internodes;
    std::vector<int> roots;      // standing on the base: the trunk (the first stem's first segment) first
    std::vector<int> baseOrgans; // organs sitting on the base
    glm::dvec3 base{0.0};
    int levels = 0;              // the highest level plus one
};

// The internodes of a plant that checkPlant accepted (every stem but the roots attached to its parent).
InternodeTree internodeTree(const Plant& plant);

} // namespace simeco::skeleton
