// Turtle, last pass: moves each instance to its plant's place in the field (its PlantPlacement, its cell of the
// grid, or its scattered place about that cell) and grows the table's bounds.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/field_scatter.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Total { uint total; };
layout(set = 0, binding = 1, std430) readonly buffer Field { float spacing; };
layout(set = 0, binding = 2, std430) buffer Instances { OrganInstance instances[]; };
layout(set = 0, binding = 3, std430) buffer Table { OrganTable table; };
layout(set = 0, binding = 4, std430) readonly buffer Placements { PlantPlacement placements[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#include "compute/turtle/turtle_math.glsl"
#include "compute/turtle/organ_bounds.glsl"

// turtle/interpretation.cpp's scatteredPlacement.
PlantPlacement scatteredPlacement(uint plant, uint plants, float spacing) {
    vec3 cell = fieldCell(plant, plants);
    float x = (cell.x + fieldScatterOffset(plant, 0u)) * spacing;
    float z = (cell.z + fieldScatterOffset(plant, 1u)) * spacing;
    float c = cos(fieldScatterYaw(plant)), s = sin(fieldScatterYaw(plant));
    return PlantPlacement(vec4(c, 0.0, s, x), vec4(0.0, 1.0, 0.0, 0.0), vec4(-s, 0.0, c, z));
}

void main() {
    uint s = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (s >= min(total, pc.organCapacity)) return;
    OrganInstance o = instances[s];
    if (pc.placed != kFieldOnGrid) {
        // A triangle's three vectors are its corners; every other organ's are a point and directions.
        // (Assigned apart: a buffer's struct and a function's are of different SPIR-V types to a `?:`.)
        PlantPlacement m = scatteredPlacement(o.plant, pc.plants, spacing);
        if (pc.placed == kFieldPlaced) m = placements[o.plant];
        o.position.xyz = placePoint(m, o.position.xyz);
        if (o.kind == kOrganTriangle) {
            o.heading.xyz = placePoint(m, o.heading.xyz);
            o.up.xyz = placePoint(m, o.up.xyz);
            if (o.shape == kTriangleOfCylinder) { // its corners' normals
                o.previousHeading.xyz = turnDirection(m, o.previousHeading.xyz);
                o.nextHeading.xyz = turnDirection(m, o.nextHeading.xyz);
                vec3 n = turnDirection(m, vec3(o.position.w, o.heading.w, o.up.w));
                o.position.w = n.x;
                o.heading.w = n.y;
                o.up.w = n.z;
            }
        } else {
            o.heading.xyz = turnDirection(m, o.heading.xyz);
            o.up.xyz = turnDirection(m, o.up.xyz);
            o.previousHeading.xyz = turnDirection(m, o.previousHeading.xyz);
            o.nextHeading.xyz = turnDirection(m, o.nextHeading.xyz);
        }
    } else {
        vec3 d = fieldCell(o.plant, pc.plants) * spacing;
        o.position.xyz += d;
        if (o.kind == kOrganTriangle) {
            o.heading.xyz += d;
            o.up.xyz += d;
        }
    }
    instances[s] = o;
    Box b = organBox(o);
    for (uint axis = 0u; axis < 3u; ++axis) {
        atomicMin(table.boundsMin[axis], boundsKey(b.lo[axis]));
        atomicMax(table.boundsMax[axis], boundsKey(b.hi[axis]));
    }
}
