// Turtle: cpfg's tapered lines. A segment narrows from the width it was drawn with to the width set before the
// command that ends it: a branch `[` or `]`, the next segment or move (F G f g, @M), or its plant's end. Each such
// command, and each plant's last module, finds the segment it ends by the search over those commands
// (taperBelow: the nearest segment up the tree, none past one of them) and sets the segment's top radius from the
// state just before it. Each segment is ended once, so no two invocations write the same radius.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/organ_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer PlantStarts { uint plantStarts[]; };
layout(set = 0, binding = 1, std430) readonly buffer SpeciesTable { TurtleSpecies speciesTable[]; };
layout(set = 0, binding = 2, std430) readonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 3, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 4, std430) readonly buffer Kinds { uint kinds[]; };
layout(set = 0, binding = 5, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 6, std430) readonly buffer States { TurtleState states[]; };
layout(set = 0, binding = 7, std430) readonly buffer Slots { uint slots[]; };
layout(set = 0, binding = 8, std430) readonly buffer TaperBelow { uint taperBelow[]; };
layout(set = 0, binding = 9, std430) buffer Instances { OrganInstance instances[]; };
layout(set = 0, binding = 10, std430) buffer PlantBounds { int plantBounds[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 11
#include "compute/turtle/module_count.glsl"
#include "compute/turtle/turtle_math.glsl"
#include "compute/turtle/organ_bounds.glsl"
#include "compute/turtle/plant_bounds.glsl"

const uint kEndsTaper = kMarkStem | kMarkStemBreak | kMarkBranchClose;

// Ends the narrowing of the segment module k left tapering: its top takes the width of the state after k.
void endTaper(uint k) {
    uint segment = (marks[k] & kMarkStem) != 0u ? k : (marks[k] & kEndsTaper) != 0u ? kNoModule : taperBelow[k];
    if (segment == kNoModule || (marks[segment] & kMarkStem) == 0u || kinds[segment] != kOrganStem) return;
    uint slot = slots[segment];
    if (slot >= pc.organCapacity) return; // not written: the organs outgrew their buffer
    TurtleState s = states[k];
    instances[slot].up.w = 0.5 * s.heading.w;
    growPlantBounds(plantOfModule[segment], instances[slot]);
}

void main() {
    uint j = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (j >= moduleCount()) return;
    uint plant = plantOfModule[j];
    if (speciesTable[plant % pc.species].taperedLines == 0u) return;
    if ((marks[j] & kEndsTaper) != 0u && j > plantStarts[plant]) endTaper(j - 1u);
    if (j + 1u == plantStarts[plant + 1u]) endTaper(j);
}
