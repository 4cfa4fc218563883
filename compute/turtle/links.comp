// Turtle: joins each stem segment or tube to the one it continues (found by the searches up the tree), so the
// renderer mitres their common end: this segment (a tube's first) learns the heading below it, the one below
// (a tube's last) learns this one's.
// A segment is continued by at most one other (a branch starts afresh), so no two invocations write the same
// field.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 1, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 2, std430) readonly buffer Kinds { uint kinds[]; };
layout(set = 0, binding = 3, std430) readonly buffer Slots { uint slots[]; };
layout(set = 0, binding = 4, std430) readonly buffer StemBelow { uint stemBelow[]; };
layout(set = 0, binding = 5, std430) readonly buffer TubeBelow { uint tubeBelow[]; };
layout(set = 0, binding = 6, std430) buffer Instances { OrganInstance instances[]; };
layout(set = 0, binding = 7, std430) readonly buffer LastSlots { uint lastSlots[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 8
#include "compute/turtle/module_count.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount() || kinds[i] != kOrganStem) return;
    bool tube = commands[i] == kTurtleCylinderPoint;
    uint below = tube ? tubeBelow[i] : stemBelow[i];
    uint joined = tube ? kMarkTube : kMarkStem;
    if (below == kNoModule || (marks[below] & joined) == 0u) return;
    uint self = slots[i], other = lastSlots[below]; // a tube's first segment joins the last one before
    if (max(self, other) >= pc.organCapacity) return; // not written: the organs outgrew their buffer
    instances[self].previousHeading = vec4(instances[other].heading.xyz, 0);
    instances[other].nextHeading = vec4(instances[self].heading.xyz, 0);
}
