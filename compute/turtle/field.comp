// Turtle: the organ table's counts and firsts from the scanned flags, the field's spacing from the plants'
// bounds (the widest plant's horizontal extent times 1.2, as turtle/interpretation.cpp's fieldSpacing), and
// empty bounds for place.comp to grow; the organs' count into the status words. Where a recording that read
// nothing back gave too little room (organs past their buffer, levels past those resolved, marks whose searches it
// left out), the table counts no organs, so that nothing wrong is drawn, lit or splatted. One workgroup.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Offsets { uint offsets[]; };
layout(set = 0, binding = 1, std430) readonly buffer Total { uint total; };
layout(set = 0, binding = 2, std430) readonly buffer PlantBounds { int plantBounds[]; };
layout(set = 0, binding = 3, std430) writeonly buffer Table { OrganTable table; };
layout(set = 0, binding = 4, std430) writeonly buffer Field { float spacing; };
layout(set = 0, binding = 5, std430) buffer Status { uint status[]; };
layout(set = 0, binding = 6, std430) readonly buffer Present { uint presentMarks; }; // setup.comp's
layout(push_constant) uniform Push { TurtlePush pc; };
#include "compute/turtle/turtle_math.glsl"

shared float widest[kTurtleWorkgroupSize];

void main() {
    uint t = gl_LocalInvocationID.x;
    float w = 0.0;
    for (uint p = t; p < pc.plants; p += kTurtleWorkgroupSize) {
        vec3 lo, hi;
        for (uint axis = 0u; axis < 3u; ++axis) {
            lo[axis] = boundsValue(plantBounds[p * 4u + axis]);
            hi[axis] = boundsValue(plantBounds[(pc.plants + p) * 4u + axis]);
        }
        if (lo.x <= hi.x) w = max(w, max(hi.x - lo.x, hi.z - lo.z));
    }
    widest[t] = w;
    barrier();
    if (t != 0u) return;
    for (uint k = 1u; k < kTurtleWorkgroupSize; ++k) w = max(w, widest[k]);
    spacing = pc.spacing > 0.0 ? pc.spacing : (w > 0.0 ? 1.2 * w : 1.0);
    status[kTurtleStatusOrgans] = total;
    // Organs past the buffer are not written, and those of modules deeper than the levels resolved, or of a string
    // with marks whose searches were left out (pc.hitMask, here), are wrong.
    bool written = total <= pc.organCapacity && status[kTurtleStatusLevels] <= pc.items &&
                   (presentMarks & pc.hitMask) == 0u;
    for (uint k = 0u; k < kOrganKinds; ++k) {
        uint first = offsets[k * pc.count];
        uint next = k + 1u < kOrganKinds ? offsets[(k + 1u) * pc.count] : total;
        table.first[k] = written ? first : 0u;
        table.count[k] = written ? next - first : 0u;
    }
    table.pad0 = 0u;
    table.pad1 = 0u;
    for (uint axis = 0u; axis < 3u; ++axis) {
        table.boundsMin[axis] = 0x7FFFFFFF;
        table.boundsMax[axis] = int(0x80000000u);
    }
    table.boundsMin[3] = boundsKey(0.0);
    table.boundsMax[3] = boundsKey(0.0);
}
