// The quadrilateral a flat leaf a few pixels across casts its shadow from. A stencil shadow volume costs the device
// by the sides it draws, each a long sliver from the leaf to the ground, so a leaf cut into many lobes or leaflets
// casts many; at a few pixels no one sees its shadow's outline, only how much it shades. The quadrilateral has the
// leaf's own area, where its outline's convex hull is widest (a blossom's its face's, across its heading).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace simeco::draw {

// The largest quadrilateral with corners on the convex hull of `points`, scaled about its centroid to `area`: its
// corners counter-clockwise. None where the hull has fewer than four corners.
std::optional<std::array<glm::vec2, 4>> silhouetteQuad(std::vector<glm::vec2> points, float area);

// The area the triangles (three corners each, either winding) cover together, overlaps counted once: measured on a
// grid of kSilhouetteGrid cells a side over their bounds.
inline constexpr std::uint32_t kSilhouetteGrid = 128;
float coveredArea(std::span<const glm::vec2> corners);

} // namespace simeco::draw
