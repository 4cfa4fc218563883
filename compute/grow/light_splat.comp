// The light grid, first pass: each organ the turtle drew adds its shading area to the voxel of its centre, in
// fixed point (kAreaFixedPoint), so that the sums are exact in any order, and marks the voxel held by its plant
// (or by several: compute/shared/light_layout.h), which comes out the same in any order too.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/light_layout.h"
#include "compute/shared/organ_layout.h"

layout(local_size_x = kLightWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Instances { OrganInstance instances[]; };
layout(set = 0, binding = 1, std430) readonly buffer Table { OrganTable table; };
layout(set = 0, binding = 2, std430) readonly buffer ShapeAreas { float shapeArea[]; };
layout(set = 0, binding = 3, std430) buffer Occupancy { uint occupancy[]; };
layout(set = 0, binding = 4, std430) buffer Holders { uint holder[]; };
layout(set = 0, binding = 5, std430) buffer Top { uint top; }; // the layers up to the highest with leaf area
layout(push_constant) uniform Push { LightGridPush pc; };

#include "compute/grow/light_grid.glsl"

void main() {
    uint s = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    uint last = kOrganKinds - 1u;
    if (s >= table.first[last] + table.count[last]) return;
    OrganInstance o = instances[s];
    int v = voxelAt(organCentre(o));
    if (v < 0) return;
    float shape = o.kind == kOrganLeaf && o.shape < uint(shapeArea.length()) ? shapeArea[o.shape] : 0.0;
    // At most 2^20 units (256 square units) an organ: 4,096 of the largest fill a voxel's count.
    uint units = uint(clamp(organShadingArea(o, shape), 0.0, 256.0) * kAreaFixedPoint + 0.5);
    if (units == 0u) return;
    atomicAdd(occupancy[v], units);
    uint layer = (uint(v) / pc.sizeX) % pc.sizeY;
    if (top <= layer) atomicMax(top, layer + 1u);
    uint plant = o.plant + pc.firstPlant + 1u;
    uint was = atomicCompSwap(holder[v], kVoxelEmpty, plant);
    if (was != kVoxelEmpty && was != plant) atomicExchange(holder[v], kVoxelShared);
}
