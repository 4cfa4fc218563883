// Turtle: every linear module's state, from its anchor's state (or the plant's initial one) and the composed
// steps. The non-linear modules' states are already there.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "compute/turtle/turtle_buffers.glsl"
layout(set = 0, binding = 5, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 6, std430) readonly buffer Targets { uint targets[]; };
layout(set = 0, binding = 7, std430) readonly buffer ChunkSteps { TurtleStep chunkSteps[]; };
layout(set = 0, binding = 8, std430) readonly buffer ChunkPointers { uint chunkPointers[]; };
layout(set = 0, binding = 9, std430) readonly buffer JumpedSteps { TurtleStep jumpedSteps[]; };
layout(set = 0, binding = 10, std430) readonly buffer JumpedPointers { uint jumpedPointers[]; };
layout(set = 0, binding = 11, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 12, std430) buffer States { TurtleState states[]; };
#define TURTLE_STATUS_BINDING 13
#include "compute/turtle/module_count.glsl"

#include "compute/turtle/turtle_math.glsl"
#include "compute/turtle/turtle_modules.glsl"
#include "compute/turtle/turtle_anchors.glsl"

void main() {
    uint i = invocationIndex();
    if (i >= moduleCount() || (marks[i] & kMarkNonlinear) != 0u) return;
    states[i] = linearState(i);
}
