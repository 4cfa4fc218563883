// Turtle: every linear module's state, its anchor's state (or the plant's initial one) advanced by its
// composed step. The non-linear modules' states are already there.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "shared/derive_layout.h"
#include "shared/turtle_layout.h"
#include "shared/turtle_state_layout.h"
#include "turtle/turtle_buffers.glsl"
layout(set = 0, binding = 5, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 6, std430) readonly buffer Steps { TurtleStep steps[]; };
layout(set = 0, binding = 7, std430) readonly buffer Anchors { uint anchors[]; };
layout(set = 0, binding = 8, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 9, std430) buffer States { TurtleState states[]; };

#include "turtle/turtle_math.glsl"
#include "turtle/turtle_modules.glsl"

void main() {
    uint i = invocationIndex();
    if (i >= pc.count || (marks[i] & kMarkNonlinear) != 0u) return;
    uint anchor = anchors[i];
    // (if/else, not ?:, which glslang compiles to a store of mismatched struct types)
    TurtleState base;
    if (anchor == kNoModule) base = initialState(speciesTable[speciesOf(plantOfModule[i])]);
    else base = states[anchor];
    states[i] = applyStep(base, steps[i]);
}
