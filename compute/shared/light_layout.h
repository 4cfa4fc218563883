// The light grid of the growth simulation, shared by C++ (src/grow/light_grid.h, with its CPU reference) and GLSL
// (compute/grow/light_*.comp).
//
// A box of cubic voxels over the field. Each tick the organs the turtle drew splat their area into the voxel of
// their centre (light_splat.comp), in fixed point so that the sums need only integer atomics and come out the same
// in any order. Light then travels from the sun and from the sky's directions (LightDirection: where it comes from
// and how strong it is) through the leaf area each voxel holds, by Beer–Lambert's law: a path of length l through
// leaf area density a (area per volume) lets exp(-kLeafExtinction a l) through; a voxel an obstacle fills (a mask
// made once from the scene) lets nothing through (light_propagate.comp). Each voxel keeps the light that reaches its
// centre and the direction most of it comes from, which the organs in it take into their particles for the next
// tick (light_gather.comp).
#ifndef SIMECO_SHARED_LIGHT_LAYOUT_H
#define SIMECO_SHARED_LIGHT_LAYOUT_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kLightWorkgroupSize = 64u;
SIMECO_CONST_FLOAT kAreaFixedPoint = 4096.0f; // a voxel's splatted area counts in 1/4096 square units
// Leaves facing every way (a spherical leaf angle distribution) block half their area along any direction.
SIMECO_CONST_FLOAT kLeafExtinction = 0.5f;
SIMECO_CONST_FLOAT kOneThird = 0.333333343f; // a triangle's centroid, multiplied rather than divided (below)
// Where the gather also writes an organ's light (LightGridPush::derived): nowhere else, the derived string's
// particle of the same index (a string drawn as derived), or that of the drawn module's origin (the homomorphism's).
SIMECO_CONST kLightToDrawnOnly = 0u;
SIMECO_CONST kLightToSameModule = 1u;
SIMECO_CONST kLightToOrigin = 2u;

// Where light comes from: xyz towards it (unit length), w its intensity on a surface facing it.
struct LightDirection {
    vec4 towardAndIntensity;
};

struct LightGridPush {
    vec4 origin;    // xyz: the grid's lowest corner; w: the side of a voxel
    uint sizeX;     // voxels along x, y and z
    uint sizeY;
    uint sizeZ;
    uint directions; // LightDirection entries (the sun first, then the sky's)
    uint derived;    // gather: where the light goes besides the drawn string's particles (kLightTo*)
    uint firstPlant; // splat and gather: added to each organ's plant, the field's numbering of the batch's plants
    uint count;      // queries: the drawn modules
    uint stride;     // queries: parameters per module of the derived string
    uint obstacleTop; // propagate: the layers up to the highest an obstacle fills (0: none)
    float inverseSide; // 1 / origin.w, rounded on the host: a point's voxel is found by multiplying by it
};

// The device must find the same voxel for a point as the CPU reference, also for points on a voxel's face (a sky
// direction at 30 or 60 degrees of elevation steps onto faces, every voxel a face). So the shaders compute where
// rays and organs fall with `precise` arithmetic (no fused multiply-adds) and no division (a device may divide to
// within a few units in the last place), in the same order as src/grow/light_grid.cpp.

// Light comes from above the horizon only, so a ray that has risen past the highest layer with leaf area or an
// obstacle (the splat's `top` word, `obstacleTop`) meets nothing more: propagate stops it there.

// cpfg's environment queries (`?E(...)`, Měch and Prusinkiewicz's open L-systems), answered by the grid where one
// runs, from the light of the last drawing, as light_gather.comp gives organs theirs: after each drawing a module
// ?E's first parameter becomes the light at the turtle's position as a share of the open's (1 outside the grid),
// and with four parameters or more, the second to fourth the direction most of it comes from, in its plant's own
// frame (light_queries.comp). They are written into the derived string's module, which the next step reads.

// Space: each voxel also keeps which plant holds it (splat: the plant's number + 1 of the organs whose centres lie
// in it; kVoxelShared where several plants' do; kVoxelEmpty where none), and propagate keeps each voxel's holder
// and splatted area of the last drawing for the gather (the current one is cleared and refilled meanwhile).
// An organ's room to grow (kParticleSpace) is 0 where its tip lies in a voxel an obstacle or another plant holds
// (a voxel held by several plants counts as another's): it does not grow into it; else, in a voxel several plants
// share, 1 / (1 + the voxel's splatted area / the voxel's cross-section) (crowding); else 1.
SIMECO_CONST kVoxelEmpty = 0u;
SIMECO_CONST kVoxelShared = 0xFFFFFFFFu;
SIMECO_FN float roomToGrow(bool tipBlocked, bool crowded, uint areaUnits, float side) {
    if (tipBlocked) return 0.0f;
    if (!crowded) return 1.0f;
    return 1.0f / (1.0f + float(areaUnits) / (kAreaFixedPoint * side * side));
}

SIMECO_SHARED_END

#endif
