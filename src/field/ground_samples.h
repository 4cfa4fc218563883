// Points spread over a rectangle of the ground, for the plants of a population: Poisson-disk (no two closer than
// a least distance, placed one by one at uniformly random spots) or a jittered grid. Deterministic in `seed` and
// `key` (the counter-based random streams).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec2.hpp>

namespace simeco::field {

struct GroundRect {
    glm::vec2 center{0.0f};
    glm::vec2 size{1.0f}; // along x and z
};

// Up to `count` points at least `distance` apart (fewer where the rectangle has no room for more: the caller
// says so); 0 takes 0.75 x sqrt(area / count), which leaves room for all.
std::vector<glm::vec2> poissonDiskPoints(const GroundRect& rect, uint32_t count, float distance, uint32_t seed,
                                         uint32_t key);
// `count` points, one in each of `count` cells of a grid as square as the rectangle allows (the cells chosen at
// random where the grid has more), each moved by up to 0.35 of a cell.
std::vector<glm::vec2> jitteredPoints(const GroundRect& rect, uint32_t count, uint32_t seed, uint32_t key);

} // namespace simeco::field
