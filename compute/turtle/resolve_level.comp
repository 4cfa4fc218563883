// Turtle, one dispatch per level (pc.first, its workgroups from level_layout.comp): the states of the level's
// non-linear modules, from the state their parent's composed steps lead to (the anchors on its path lie on
// earlier levels, or are the plant's root).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "compute/turtle/turtle_buffers.glsl"
layout(set = 0, binding = 5, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 6, std430) readonly buffer Parents { uint parents[]; };
layout(set = 0, binding = 7, std430) readonly buffer Targets { uint targets[]; };
layout(set = 0, binding = 8, std430) readonly buffer ChunkSteps { TurtleStep chunkSteps[]; };
layout(set = 0, binding = 9, std430) readonly buffer ChunkPointers { uint chunkPointers[]; };
layout(set = 0, binding = 10, std430) readonly buffer JumpedSteps { TurtleStep jumpedSteps[]; };
layout(set = 0, binding = 11, std430) readonly buffer JumpedPointers { uint jumpedPointers[]; };
layout(set = 0, binding = 12, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 13, std430) buffer States { TurtleState states[]; };
layout(set = 0, binding = 14, std430) readonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 15, std430) readonly buffer Order { uint order[]; };
// The levels' sizes (level_count.comp) and their cursors, which level_scatter.comp left at the slices' ends.
layout(set = 0, binding = 16, std430) readonly buffer Counts { uint counts[]; };
layout(set = 0, binding = 17, std430) readonly buffer Cursors { uint cursors[]; };

#include "compute/turtle/turtle_math.glsl"
#include "compute/turtle/turtle_modules.glsl"
#include "compute/turtle/turtle_anchors.glsl"

void main() {
    uint k = invocationIndex(), items = counts[pc.first];
    if (k >= items) return;
    uint m = order[cursors[pc.first] - items + k];
    TurtleSpecies sp = speciesTable[speciesOf(plantOfModule[m])];
    uint parent = parents[m];
    TurtleState before;
    if (parent == kNoModule) before = initialState(sp);
    else if ((marks[parent] & kMarkNonlinear) != 0u) before = states[parent];
    else before = linearState(parent);
    states[m] = applyNonlinear(before, commands[m], m, sp);
}
