// The light grid, last pass: each organ the turtle drew takes the light of its voxel and the direction most of it
// comes from into its module's particle (kParticleLight, kParticleLightDirection as an octahedral pair packed by
// packSnorm2x16), and its room to grow (kParticleSpace, compute/shared/light_layout.h), all as the last drawing
// left the grid; an organ outside the grid is in the open: all the light there is, from straight above. Where a
// module draws several organs of a kind (a tube's segments), its first organ of the kind writes. The light also
// goes to the particle of the derived string the module was drawn from, which grows by it in the next tick.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/light_layout.h"
#include "compute/shared/organ_layout.h"
#include "compute/shared/particle_layout.h"

layout(local_size_x = kLightWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Instances { OrganInstance instances[]; };
layout(set = 0, binding = 1, std430) readonly buffer Table { OrganTable table; };
layout(set = 0, binding = 2, std430) readonly buffer Light { vec4 light[]; };
layout(set = 0, binding = 3, std430) readonly buffer Directions { LightDirection directions[]; };
layout(set = 0, binding = 4, std430) buffer Particles { float particles[]; };
// The drawn modules' origins in the derived string, and the derived string's particles (LightGridPush::derived).
layout(set = 0, binding = 5, std430) readonly buffer Origins { uint origin[]; };
layout(set = 0, binding = 6, std430) buffer DerivedParticles { float derivedParticles[]; };
layout(set = 0, binding = 7, std430) readonly buffer Room { uvec2 room[]; };
layout(set = 0, binding = 8, std430) readonly buffer Obstacles { uint obstacle[]; };
layout(push_constant) uniform Push { LightGridPush pc; };

#include "compute/grow/light_direction.glsl"
#include "compute/grow/light_grid.glsl"

void main() {
    uint s = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    uint last = kOrganKinds - 1u;
    if (s >= table.first[last] + table.count[last]) return;
    OrganInstance o = instances[s];
    if (s > table.first[o.kind] && instances[s - 1u].module == o.module) return;
    int v = voxelAt(organCentre(o));
    vec4 l = vec4(0.0, 1.0, 0.0, 0.0);
    if (v >= 0) {
        l = light[v];
    } else {
        for (uint d = 0u; d < pc.directions; ++d) l.w += max(directions[d].towardAndIntensity.w, 0.0);
    }
    float direction = packLightDirection(l.xyz);
    // Its room to grow: none where its tip reaches into an obstacle's or (beyond its own voxel) another plant's.
    int t = voxelAt(organTip(o));
    uint plant = o.plant + pc.firstPlant + 1u;
    bool blocked = t >= 0 && (obstacle[t] != 0u || (t != v && room[t].x != kVoxelEmpty && room[t].x != plant));
    bool crowded = v >= 0 && room[v].x == kVoxelShared;
    float space = roomToGrow(blocked, crowded, v >= 0 ? room[v].y : 0u, pc.origin.w);
    uint at = kParticleStateFloats * o.module;
    particles[at + kParticleLight] = l.w;
    particles[at + kParticleLightDirection] = direction;
    particles[at + kParticleSpace] = space;
    if (pc.derived != kLightToDrawnOnly) {
        uint to = kParticleStateFloats * (pc.derived == kLightToOrigin ? origin[o.module] : o.module);
        derivedParticles[to + kParticleLight] = l.w;
        derivedParticles[to + kParticleLightDirection] = direction;
        derivedParticles[to + kParticleSpace] = space;
    }
}
