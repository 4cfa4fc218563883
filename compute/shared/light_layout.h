// The light grid of the growth simulation, shared by C++ (src/grow/light_grid.h, with its CPU reference) and GLSL
// (compute/grow/light_*.comp).
//
// A box of cubic voxels over the field. Each tick the organs the turtle drew splat their area into the voxel of
// their centre (light_splat.comp), in fixed point so that the sums need only integer atomics and come out the same
// in any order. Light then travels from the sun and from the sky's directions (LightDirection: where it comes from
// and how strong it is) through the leaf area each voxel holds, by Beer–Lambert's law: a path of length l through
// leaf area density a (area per volume) lets exp(-kLeafExtinction a l) through; a voxel an obstacle fills (a mask
// made once from the scene) lets nothing through (light_propagate.comp). Each voxel keeps the light that reaches its centre and the direction most of it
// comes from, which the organs in it take into their particles for the next tick (light_gather.comp).
#ifndef SIMECO_SHARED_LIGHT_LAYOUT_H
#define SIMECO_SHARED_LIGHT_LAYOUT_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kLightWorkgroupSize = 64u;
SIMECO_CONST_FLOAT kAreaFixedPoint = 4096.0f; // a voxel's splatted area counts in 1/4096 square units
// Leaves facing every way (a spherical leaf angle distribution) block half their area along any direction.
SIMECO_CONST_FLOAT kLeafExtinction = 0.5f;
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
    uint pad0;
    uint pad1;
    uint pad2;
};

SIMECO_SHARED_END

#endif
