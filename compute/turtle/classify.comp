// Turtle: which organ each module draws, if any, as a count per organ kind (flags[kind * count + module]: 1,
// or a tube's segments); their exclusive scan is every organ's place in the instance buffer, grouped by kind
// and in module order within a kind. Cylinder points that draw a tube are marked, so the next one can join it.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "compute/turtle/turtle_buffers.glsl"
layout(set = 0, binding = 5, std430) readonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 6, std430) buffer Marks { uint marks[]; };
layout(set = 0, binding = 7, std430) readonly buffer TriangleFirst { uint triangleFirst[]; };
layout(set = 0, binding = 8, std430) readonly buffer CylinderAnchors { uint cylinderAnchors[]; };
layout(set = 0, binding = 9, std430) readonly buffer CylinderStarts { uint cylinderStarts[]; };
layout(set = 0, binding = 10, std430) readonly buffer States { TurtleState states[]; };
layout(set = 0, binding = 11, std430) writeonly buffer Kinds { uint kinds[]; };
layout(set = 0, binding = 12, std430) writeonly buffer Flags { uint flags[]; };
#define TURTLE_STATUS_BINDING 13
#include "compute/turtle/module_count.glsl"

#include "compute/turtle/turtle_math.glsl"
#include "compute/turtle/turtle_modules.glsl"

const uint kNoOrgan = 0xFFFFFFFFu;

void main() {
    uint i = invocationIndex();
    if (i >= pc.count) return;
    if (i >= moduleCount()) { // within the bound but past the string: draws nothing, for the scan of the flags
        for (uint k = 0u; k < kOrganKinds; ++k) flags[k * pc.count + i] = 0u;
        return;
    }
    uint command = commands[i];
    uint kind = kNoOrgan, organs = 1u;
    if (turtleDraws(command) && (marks[i] & kMarkStem) != 0u) kind = kOrganStem;
    else if (command == kTurtleSphere) kind = kOrganSphere;
    else if (command == kTurtleDisc || command == kTurtleDiscFacing) kind = kOrganDisc;
    else if (command == kTurtleSurface) {
        if (surfaceDrawn(speciesTable[speciesOf(plantOf(i))], symbolAt(i))) kind = kOrganLeaf;
    }
    else if (triangleFirst[i] != kNoModule) kind = kOrganTriangle;
    else if (command == kTurtleCylinderPoint && cylinderStarts[i] != kNoModule) {
        // A tube from the last control point, once a cylinder has started on the path to this module.
        vec3 from = states[cylinderAnchors[i]].position.xyz;
        if (length(states[i].position.xyz - from) > kTubeEpsilon * (1.0 + length(from))) {
            TurtleSpecies sp = speciesTable[speciesOf(plantOf(i))];
            if ((sp.cylinders & kCylinderMeshes) != 0u) { // a mesh (emit.comp, cylinder_mesh.glsl)
                kind = kOrganTriangle;
                organs = cylinderRings(i) * cylinderSides(sp) * 2u;
            } else {
                kind = kOrganStem;
                organs = (sp.cylinders & kCylinderCpfgTubes) != 0u ? cylinderRings(i)
                                                                     : tubeSegments(paramAt(i, 0u, 1.0));
                marks[i] |= kMarkTube;
            }
        }
    }
    kinds[i] = kind;
    for (uint k = 0u; k < kOrganKinds; ++k) flags[k * pc.count + i] = k == kind ? organs : 0u;
    // An F inside a polygon draws its segment and is a vertex too: it may close a triangle besides.
    if (kind == kOrganStem && triangleFirst[i] != kNoModule) flags[kOrganTriangle * pc.count + i] = 1u;
}
