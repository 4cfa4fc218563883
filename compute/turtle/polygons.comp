// Turtle, pass 2: one invocation per polygon `{` walks to its `}` (polygons follow the string, not the
// branches: cpfg keeps them on a stack of their own). Segments inside a polygon still draw their stems; each
// vertex of this polygon (f, F, `.` at its own nesting level) from the third on closes a fan triangle with the first
// and the previous vertex, which this pass records. A polygon's modules are walked by one invocation; the
// polygons of a field are walked in parallel.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
layout(local_size_x = kTurtleWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 1, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 2, std430) buffer Marks { uint marks[]; };
layout(set = 0, binding = 3, std430) writeonly buffer TriangleFirst { uint triangleFirst[]; };
layout(set = 0, binding = 4, std430) writeonly buffer TrianglePrevious { uint trianglePrevious[]; };
layout(push_constant) uniform Push { TurtlePush pc; };
#define TURTLE_STATUS_BINDING 5
#include "compute/turtle/module_count.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= moduleCount() || commands[i] != kTurtlePolygonBegin) return;
    uint plant = plantOfModule[i];
    uint nested = 0u, vertices = 0u, first = kNoModule, previous = kNoModule;
    for (uint j = i + 1u; j < moduleCount() && plantOfModule[j] == plant; ++j) {
        uint command = commands[j];
        if (command == kTurtlePolygonEnd) {
            if (nested == 0u) break;
            --nested;
            continue;
        }
        if (command == kTurtlePolygonBegin) {
            ++nested;
        } else if (nested == 0u && turtleAddsVertex(command)) {
            if (vertices >= 2u) {
                triangleFirst[j] = first;
                trianglePrevious[j] = previous;
            }
            if (vertices == 0u) first = j;
            previous = j;
            ++vertices;
        }
    }
}
