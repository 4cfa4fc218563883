// A plant's skeleton: its stems as polylines from base to tip, each attached to a point of its parent, with the
// leaves, flowers and fruits that sit on them. What `simeco skeleton` writes and `simeco infer` reads
// (docs/SKELETON.md gives the file formats).
#pragma once

#include <string>
#include <vector>

#include <glm/vec3.hpp>

namespace simeco::skeleton {

// One axis of the plant: the trunk, a branch, a twig. Its points run from its base to its tip, in world units;
// its base is point `attach` of stem `parent` (-1 for a stem standing on the ground: the plant's base).
struct Stem {
    int id = 0;
    int parent = -1;
    int attach = -1; // the parent's point this stem starts at; -1 where the file does not say (found from its base)
    std::vector<glm::dvec3> points;
    double width = 0.0;          // at its base, as the turtle's `!` sets it (the diameter)
    std::vector<double> widths;  // per segment (points.size() - 1), where they differ along the stem; else empty
};

enum class OrganKind { Leaf, Flower, Fruit };

// A leaf, flower or fruit on point `point` of stem `stem`, pointing along `heading` (its blade's or stalk's
// direction), `size` across (a leaf's length, a flower's or fruit's diameter).
struct Organ {
    OrganKind kind = OrganKind::Leaf;
    int stem = 0;
    int point = 0;
    glm::dvec3 position{0.0};
    glm::dvec3 heading{0.0, 1.0, 0.0};
    double size = 0.0;
};

struct Plant {
    std::vector<Stem> stems;
    std::vector<Organ> organs;
};

struct Skeleton {
    std::string source; // what it was made from: a grammar file, an image set
    std::vector<Plant> plants;
};

const char* organKindName(OrganKind kind);

// The plant's size: the diagonal of the box its stems' points take (0 for a plant without stems).
double plantSize(const Plant& plant);

// How many segments (pairs of consecutive points) the plant's stems have.
size_t segmentCount(const Plant& plant);

} // namespace simeco::skeleton
