// The light grid answers cpfg's environment queries (compute/shared/light_layout.h): each drawn module the turtle
// took for `?E` gets the light at its position, from the turtle's state after it, in the derived string's module
// it was drawn from. The CPU reference is Simulation's interpretOnHost with turtle::environmentQueries.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/light_layout.h"
#include "compute/shared/organ_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"

layout(local_size_x = kLightWorkgroupSize) in;
layout(set = 0, binding = 0, std430) readonly buffer States { TurtleState states[]; };
layout(set = 0, binding = 1, std430) readonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 2, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 3, std430) readonly buffer Placements { PlantPlacement placements[]; };
layout(set = 0, binding = 4, std430) readonly buffer Light { vec4 light[]; };
layout(set = 0, binding = 5, std430) readonly buffer Directions { LightDirection directions[]; };
layout(set = 0, binding = 6, std430) readonly buffer Origins { uint origin[]; };
layout(set = 0, binding = 7, std430) readonly buffer DerivedSymbols { uint derivedSymbols[]; };
layout(set = 0, binding = 8, std430) buffer DerivedParams { float derivedParams[]; };
layout(push_constant) uniform Push { LightGridPush pc; };

#include "compute/grow/light_grid.glsl"
#include "compute/turtle/organ_bounds.glsl"

void main() {
    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (i >= pc.count || commands[i] != kTurtleQueryEnvironment) return;
    PlantPlacement m = placements[plantOfModule[i]];
    vec3 at = placePoint(m, states[i].position.xyz);
    float open = 0.0;
    for (uint d = 0u; d < pc.directions; ++d) open += max(directions[d].towardAndIntensity.w, 0.0);
    int v = voxelAt(at);
    vec4 l = v >= 0 ? light[v] : vec4(0.0, 1.0, 0.0, open);
    vec3 toward = normalize(turnIntoPlant(m, l.xyz));
    uint to = pc.derived == kLightToOrigin ? origin[i] : i;
    uint count = derivedSymbols[to] >> kSymbolBits;
    float answer[4] = float[4](open > 0.0 ? l.w / open : 1.0, toward.x, toward.y, toward.z);
    for (uint k = 0u; k < min(count, count >= 4u ? 4u : 1u); ++k) derivedParams[pc.stride * to + k] = answer[k];
}
