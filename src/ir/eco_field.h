// simeco's extensions of the EcoSystem block for fields (docs/SCENES.md): populations of a species over a
// region, obstacles, and the light and ground the field is drawn with. The thesis' scripts have none of them.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "ir/source_loc.h"

namespace simeco::ir {

// How a population's plants are spread over its region.
enum class EcoPlacement { Poisson, Jittered };

// `Population "name" { Plant = "..."; Count = n; | Density = d; Center = vector(...); Size = vector(w, 0, d);
// Placement = poisson | jittered; Spacing = s; Seed = n; Variation = v; }`: plants of one Plant block's species
// over a rectangle of the ground.
struct EcoPopulation {
    std::string name;
    std::string plant;                     // the Plant block whose species it is
    SourceLoc plantLoc;
    std::optional<uint32_t> count;         // plants; or
    std::optional<float> density;          // plants per square unit of the region
    float centerX = 0.0f, centerZ = 0.0f;  // the region's centre on the ground
    float width = 20.0f, depth = 20.0f;    // its size along x and z
    EcoPlacement placement = EcoPlacement::Poisson;
    std::optional<float> spacing;          // Poisson: the least distance between plants; jittered: the grid's
    uint32_t seed = 0;                     // its placement's own random stream (with the field's seed)
    float variation = 0.0f;                // each plant's growth rates scaled by a factor in [1 - v, 1 + v]
    SourceLoc loc;
};

// `Box "name" { Min = vector(...); Max = vector(...); Color = RGBA(...); }` or `Wall "name" { From = vector(...);
// To = vector(...); Height = h; Thickness = t; Color = RGBA(...); }`: a solid block, as an oriented box.
struct EcoObstacle {
    std::string name;
    float center[3] = {0, 0, 0};
    float halfSize[3] = {0.5f, 0.5f, 0.5f}; // along its own x (a wall's length), y (up) and z (thickness)
    float yaw = 0.0f;                       // radians its x axis turns from the world's x, about y
    float color[3] = {0.55f, 0.52f, 0.48f}; // sRGB
    SourceLoc loc;
};

// The light and ground a field is drawn with (unset: the renderer's own).
struct EcoLight {
    std::optional<std::array<float, 3>> sunDirection; // towards the sun
    std::optional<float> sunIntensity;    // a factor on the sun's light
    std::optional<float> skyLight;        // a factor on the sky's light
    std::optional<float> groundSize;      // the side of the ground square
};

} // namespace simeco::ir
