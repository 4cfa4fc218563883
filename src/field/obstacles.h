// A scene's obstacles (ir::EcoObstacle: boxes and walls) as the renderer draws them: each an oriented box of
// twelve triangles, in the field's organs after its plants'.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "grow/light_grid.h"
#include "ir/eco_field.h"
#include "turtle/interpretation.h"

namespace simeco::field {

// The eight corners of an obstacle, in the world.
std::array<glm::vec3, 8> obstacleCorners(const ir::EcoObstacle& obstacle);

// Per voxel of `grid`, 1 where its centre lies inside an obstacle, an obstacle's thin sides widened to half a voxel
// (so that it fills at least one layer): what stops the light (grow/light_grid.h).
std::vector<uint32_t> obstacleVoxels(const grow::LightGridSpec& grid, const std::vector<ir::EcoObstacle>& obstacles);

// The obstacles' triangles, as one interpretation whose organs are of plant 0 and of module k for obstacle k:
// kept by a turtle::OrganMerge after the field's batches, they take the plant index past the field's plants.
turtle::Interpretation obstacleOrgans(const std::vector<ir::EcoObstacle>& obstacles);

} // namespace simeco::field
