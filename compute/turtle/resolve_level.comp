// Turtle, one dispatch per level: the states of the level's non-linear modules, from the state their
// parent's composed step leads to (its anchor lies on an earlier level, or is the plant's root).
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/derive_layout.h"
#include "shared/turtle_layout.h"
#include "shared/turtle_state_layout.h"
#include "turtle/turtle_buffers.glsl"
layout(set = 0, binding = 5, std430) readonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 6, std430) readonly buffer Parents { uint parents[]; };
layout(set = 0, binding = 7, std430) readonly buffer Steps { TurtleStep steps[]; };
layout(set = 0, binding = 8, std430) readonly buffer Anchors { uint anchors[]; };
layout(set = 0, binding = 9, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 10, std430) readonly buffer Order { uint order[]; };
layout(set = 0, binding = 11, std430) buffer States { TurtleState states[]; };

#include "turtle/turtle_math.glsl"
#include "turtle/turtle_modules.glsl"

void main() {
    uint k = invocationIndex();
    if (k >= pc.items) return;
    uint m = order[pc.first + k];
    TurtleSpecies sp = speciesTable[speciesOf(plantOfModule[m])];
    uint parent = parents[m];
    TurtleState before = initialState(sp);
    if (parent != kNoModule) {
        uint anchor = anchors[parent];
        if (anchor != kNoModule) before = states[anchor];
        before = applyStep(before, steps[parent]);
    }
    states[m] = applyNonlinear(before, commands[m], m, sp);
}
