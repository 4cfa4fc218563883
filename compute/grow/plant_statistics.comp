// Each plant's statistics (compute/shared/plant_statistics_layout.h) from the turtle's organs: one invocation per
// plant finds its organs of each kind by a binary search (a kind's instances follow the plants) and sums them in
// order, so the sums are the same at every run. The CPU reference is src/field/plant_statistics.cpp.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/organ_layout.h"
#include "compute/shared/particle_layout.h"
#include "compute/shared/plant_statistics_layout.h"

layout(local_size_x = kPlantStatisticsWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Instances { OrganInstance instances[]; };
layout(set = 0, binding = 1, std430) readonly buffer Table { OrganTable table; };
layout(set = 0, binding = 2, std430) readonly buffer Bases { float baseHeight[]; };
layout(set = 0, binding = 3, std430) readonly buffer Particles { float particles[]; };
layout(set = 0, binding = 4, std430) readonly buffer ShapeAreas { float shapeArea[]; };
layout(set = 0, binding = 5, std430) writeonly buffer Statistics { PlantStatistics statistics[]; };
layout(push_constant) uniform Push { PlantStatisticsPush pc; };

#include "compute/turtle/organ_bounds.glsl"

// The first instance of kind k whose plant is at least `plant`.
uint lowerBound(uint k, uint plant) {
    uint lo = table.first[k], hi = table.first[k] + table.count[k];
    while (lo < hi) {
        uint mid = (lo + hi) / 2u;
        if (instances[mid].plant < plant) lo = mid + 1u;
        else hi = mid;
    }
    return lo;
}

float leafArea(OrganInstance o) {
    if (o.kind == kOrganLeaf)
        return o.shape < uint(shapeArea.length()) ? o.position.w * o.heading.w * shapeArea[o.shape] : 0.0;
    if (o.kind == kOrganTriangle) return 0.5 * length(cross(o.heading.xyz - o.position.xyz, o.up.xyz - o.position.xyz));
    return 0.0;
}

void main() {
    uint p = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (p >= pc.plants) return;
    PlantStatistics s = PlantStatistics(0u, 0u, 0.0, 0.0, 0.0);
    float top = -1e30;
    for (uint k = 0u; k < kOrganKinds; ++k) {
        uint end = lowerBound(k, p + 1u);
        for (uint i = lowerBound(k, p); i < end; ++i) {
            OrganInstance o = instances[i];
            s.organs += 1u;
            Box box = organBox(o);
            if (any(greaterThan(box.hi, box.lo))) s.living += 1u;
            top = max(top, box.hi.y);
            float area = leafArea(o);
            s.leafArea += area;
            if (pc.particles != 0u) s.light += area * particles[kParticleStateFloats * o.module + kParticleLight];
        }
    }
    s.height = s.organs > 0u ? max(top - baseHeight[p], 0.0) : 0.0;
    statistics[p] = s;
}
