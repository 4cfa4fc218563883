// The light grid, second pass: the light reaching each voxel's centre from every direction light comes from,
// through the leaf area of the voxels on the way (Beer–Lambert, compute/shared/light_layout.h), and the direction
// most of it comes from. A ray steps a voxel's length at a time from the voxel's centre until it leaves the grid,
// through the leaf area of the voxels it lands in (counted in voxels, where the CPU reference counts too); the
// voxel's own does not shade it (the organs in a voxel share its light, as in Palubicki's shadow propagation); a
// voxel an obstacle fills stops it. Above the highest layer with leaf area or an obstacle a rising ray meets nothing
// more, and stops.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/light_layout.h"
#include "compute/shared/organ_layout.h"

layout(local_size_x = kLightWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Occupancy { uint occupancy[]; };
layout(set = 0, binding = 1, std430) readonly buffer Obstacles { uint obstacle[]; };
layout(set = 0, binding = 2, std430) readonly buffer Directions { LightDirection directions[]; };
layout(set = 0, binding = 3, std430) writeonly buffer Light { vec4 light[]; }; // xyz: most light from; w: light
layout(set = 0, binding = 4, std430) readonly buffer Holders { uint holder[]; };
// Each voxel's holder and splatted area, kept for the next drawing's gather.
layout(set = 0, binding = 5, std430) writeonly buffer Room { uvec2 room[]; };
layout(set = 0, binding = 6, std430) readonly buffer Top { uint top; }; // the splat's
layout(push_constant) uniform Push { LightGridPush pc; };

#include "compute/grow/light_grid.glsl"

void main() {
    uint v = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (v >= pc.sizeX * pc.sizeY * pc.sizeZ) return;
    room[v] = uvec2(holder[v], occupancy[v]);
    if (obstacle[v] != 0u) {
        light[v] = vec4(0.0, 1.0, 0.0, 0.0);
        return;
    }
    float side = pc.origin.w;
    // Leaf area density times the extinction, per unit of path, of a voxel's area count.
    float perUnit = kLeafExtinction / (kAreaFixedPoint * side * side * side);
    uvec3 cell = uvec3(v % pc.sizeX, (v / pc.sizeX) % pc.sizeY, v / (pc.sizeX * pc.sizeY));
    vec3 centre = vec3(cell) + 0.5; // in voxels
    precise float total = 0.0;
    precise vec3 most = vec3(0.0);
    float filled = float(max(top, pc.obstacleTop)); // layers at or above it are empty
    for (uint d = 0u; d < pc.directions; ++d) {
        vec4 from = directions[d].towardAndIntensity;
        if (from.w <= 0.0) continue;
        precise float depth = 0.0;
        bool blocked = false;
        for (uint step = 1u; step < 4096u; ++step) {
            precise vec3 at = centre + from.xyz * float(step);
            vec3 landed = floor(at);
            if (from.y > 0.0 && landed.y >= filled) break;
            int u = voxelOfCell(landed);
            if (u < 0) break;
            if (obstacle[u] != 0u) {
                blocked = true;
                break;
            }
            depth += side * perUnit * float(occupancy[u]);
        }
        float reaching = blocked ? 0.0 : from.w * exp(-depth);
        total += reaching;
        most += reaching * from.xyz;
    }
    light[v] = vec4(dot(most, most) > 0.0 ? normalize(most) : vec3(0.0, 1.0, 0.0), total);
}
