// Turtle: writes each organ instance at its place (plant-local positions) and grows its plant's bounds.
// Mirrors the organs turtle/turtle_cpu.cpp emits: stems and tubes, spheres, discs, leaves and fan triangles.
#version 450
#extension GL_GOOGLE_include_directive : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "compute/turtle/turtle_buffers.glsl"
layout(set = 0, binding = 5, std430) readonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 6, std430) readonly buffer Parents { uint parents[]; };
layout(set = 0, binding = 7, std430) readonly buffer Plants { uint plantOfModule[]; };
layout(set = 0, binding = 8, std430) readonly buffer States { TurtleState states[]; };
layout(set = 0, binding = 9, std430) readonly buffer Kinds { uint kinds[]; };
layout(set = 0, binding = 10, std430) readonly buffer Offsets { uint offsets[]; };
layout(set = 0, binding = 11, std430) readonly buffer TriangleFirst { uint triangleFirst[]; };
layout(set = 0, binding = 12, std430) readonly buffer TrianglePrevious { uint trianglePrevious[]; };
layout(set = 0, binding = 13, std430) readonly buffer CylinderAnchors { uint cylinderAnchors[]; };
layout(set = 0, binding = 14, std430) readonly buffer Palettes { vec4 palettes[]; };
layout(set = 0, binding = 15, std430) readonly buffer SurfaceScales { float surfaceScales[]; };
layout(set = 0, binding = 16, std430) readonly buffer SurfaceShapes { uint surfaceShapes[]; };
layout(set = 0, binding = 17, std430) buffer Instances { OrganInstance instances[]; };
layout(set = 0, binding = 18, std430) writeonly buffer Slots { uint slots[]; };
// Each plant's box in plant-local coordinates: minima of plant p at 4p, maxima at 4 (plants + p).
layout(set = 0, binding = 19, std430) buffer PlantBounds { int plantBounds[]; };
// The last instance each module wrote (its first is in slots): a tube's last segment, which the next joins.
layout(set = 0, binding = 20, std430) writeonly buffer LastSlots { uint lastSlots[]; };
#define TURTLE_STATUS_BINDING 21
#include "compute/turtle/module_count.glsl"
// Generalized cylinders drawn as meshes: the marks, each species' contours, and each module's nearest setters of
// the cylinder's settings (kNoModule: none).
layout(set = 0, binding = 22, std430) readonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 23, std430) readonly buffer ContourRings { vec4 contourRings[]; };
layout(set = 0, binding = 24, std430) readonly buffer ContourSetters { uint contourSetters[]; };
layout(set = 0, binding = 25, std430) readonly buffer TangentSetters { uint tangentSetters[]; };
layout(set = 0, binding = 26, std430) readonly buffer RadiusScaleSetters { uint radiusScaleSetters[]; };
layout(set = 0, binding = 27, std430) readonly buffer RadiusTangentSetters { uint radiusTangentSetters[]; };

#include "compute/turtle/turtle_math.glsl"
#include "compute/turtle/turtle_modules.glsl"
#include "compute/turtle/organ_bounds.glsl"
#include "compute/turtle/plant_bounds.glsl"
#include "compute/turtle/cylinder_mesh.glsl"

// An up vector for a segment along `heading`: the turtle's up with its heading component removed.
vec3 perpendicularUp(vec3 heading, TurtleState s) {
    vec3 u = s.up.xyz - heading * dot(s.up.xyz, heading);
    if (length(u) < 1e-6) u = s.left.xyz - heading * dot(s.left.xyz, heading);
    return normalize(u);
}

const uint kNoOrgan = 0xFFFFFFFFu;

// The fan triangle vertex i closes: the polygon's first vertex, the one before i, and i (after it moved).
OrganInstance triangleOf(OrganInstance o, uint i, TurtleState after) {
    o.position = vec4(states[triangleFirst[i]].position.xyz, 0);
    o.heading = vec4(states[trianglePrevious[i]].position.xyz, 0);
    o.up = vec4(after.position.xyz, 0);
    return o;
}

// A tube from the last control point along the curve the headings there and here describe (tubeCurve), in
// the segments the point asks for, joined to each other; the join to the tube before is links.comp's. cpfg's
// (turtle_cpu.cpp): `@Gc(n)`'s n pieces through the points a mesh's rings would have, as wide as the last control
// point, the last narrowing to this one's where polygons taper, drawn in the line style.
void emitTube(OrganInstance o, uint i, uint slot, TurtleState after, TurtleSpecies sp) {
    bool cpfg = (sp.cylinders & kCylinderCpfgTubes) != 0u;
    uint segments = cpfg ? cylinderRings(i) : tubeSegments(paramAt(i, 0u, 1.0));
    if (slot + segments > pc.organCapacity) return; // the organs outgrew their buffer (field.comp tells)
    uint anchorModule = cylinderAnchors[i];
    TurtleState anchor = states[anchorModule];
    vec3 chord = after.position.xyz - anchor.position.xyz;
    float len = length(chord);
    float r0 = 0.5 * anchor.heading.w, r1 = 0.5 * after.heading.w;
    CylinderCurve curve;
    if (cpfg) {
        curve = cylinderCurve(controlPointAt(anchorModule, anchor, sp), controlPointAt(i, after, sp));
        o.shape = sp.lineStyle;
    }
    bool lastTapers = sp.lineStyle == kLinePolygon && sp.taperedLines != 0u;
    float step = 1.0 / float(segments), r = step;
    vec3 from = anchor.position.xyz;
    vec3 previous = vec3(0);
    for (uint k = 0u; k < segments; ++k) {
        float t0 = float(k) / float(segments), t1 = float(k + 1u) / float(segments);
        vec3 to;
        if (k + 1u == segments) {
            to = after.position.xyz;
        } else if (cpfg) {
            to = curvePoint(curve, curveParameter(curve, r));
            r += step;
        } else {
            to = tubeCurve(anchor.position.xyz, anchor.heading.xyz, after.position.xyz, after.heading.xyz, len, t1);
        }
        vec3 d = to - from;
        float l = length(d);
        vec3 heading = l > 0.0 ? d / l : chord / len;
        o.position = vec4(from, l);
        if (cpfg) {
            o.heading = vec4(heading, r0);
            o.up = vec4(perpendicularUp(heading, after), k + 1u == segments && lastTapers ? r1 : r0);
        } else {
            o.heading = vec4(heading, r0 + (r1 - r0) * t0);
            o.up = vec4(perpendicularUp(heading, after), r0 + (r1 - r0) * t1);
        }
        o.previousHeading = vec4(previous, 0);
        o.nextHeading = vec4(0);
        if (k > 0u) instances[slot + k - 1u].nextHeading = vec4(heading, 0);
        instances[slot + k] = o;
        growPlantBounds(o.plant, o);
        previous = heading;
        from = to;
    }
    slots[i] = slot;
    lastSlots[i] = slot + segments - 1u;
}

// The mesh from the last control point to this one (classify.comp counted its triangles).
void emitCylinderMesh(OrganInstance o, uint i, uint slot, TurtleState after, TurtleSpecies sp) {
    uint rings = cylinderRings(i);
    uint count = rings * cylinderSides(sp) * 2u;
    if (slot + count > pc.organCapacity) return; // the organs outgrew their buffer (field.comp tells)
    uint anchor = cylinderAnchors[i];
    CylinderPoint a = controlPointAt(anchor, states[anchor], sp), b = controlPointAt(i, after, sp);
    float twist = 0.0;
    if ((sp.cylinders & kCylinderTwist) != 0u) {
        twist = cylinderTwist(a, b);
    } else { // the frames carried from the cylinder's start
        a.up = carriedUp(anchor);
        a.left = cross(a.heading, a.up);
        b.up = turnedWithHeading(a.heading, b.heading, a.up, 0.0);
        b.left = cross(b.heading, b.up);
    }
    o.shape = kTriangleOfCylinder;
    cylinderMesh(o, slot, a, b, rings, twist, sp);
    slots[i] = slot;
    lastSlots[i] = slot + count - 1u;
}

void main() {
    uint i = invocationIndex();
    if (i >= moduleCount()) return;
    uint kind = kinds[i];
    if (kind == kNoOrgan) return;
    uint plant = plantOfModule[i];
    uint species = speciesOf(plant);
    TurtleSpecies sp = speciesTable[species];
    uint parent = parents[i];
    TurtleState after = states[i];
    TurtleState before;
    if (parent == kNoModule) before = initialState(sp);
    else before = states[parent];
    uint command = commands[i];
    float scale = before.up.w;

    OrganInstance o;
    o.position = vec4(0);
    o.heading = vec4(0);
    o.up = vec4(0);
    o.previousHeading = vec4(0);
    o.nextHeading = vec4(0);
    o.plant = plant;
    o.kind = kind;
    o.shape = 0u;
    o.module = i;
    // No organ-drawing command changes the colour, so the state after it has the colour it is drawn in.
    float colorIndex = clamp(after.left.w, -1.0, float(kPaletteEntries));
    o.color = palettes[species * kPaletteEntries + uint(clamp(int(floor(colorIndex + 0.5)), 0, int(kPaletteEntries) - 1))];

    if (command == kTurtleCylinderPoint && (sp.cylinders & kCylinderMeshes) != 0u) {
        emitCylinderMesh(o, i, offsets[kind * pc.count + i], after, sp);
        return;
    } else if (command == kTurtleCylinderPoint) {
        emitTube(o, i, offsets[kind * pc.count + i], after, sp);
        return;
    } else if (kind == kOrganTriangle) {
        o = triangleOf(o, i, after);
    } else if (kind == kOrganStem) {
        float radius = 0.5 * before.heading.w;
        Frame f = frameOf(before);
        // cpfg's `tropism:` lines bend the heading before the segment is drawn (turtle_modules.glsl).
        if (sp.tropismRule == kTropismCpfgTropism) bendAsCpfgTropism(f, sp.tropism.xyz, before.position.w);
        rollByTorque(f, sp.torque.xyz);
        o.position = vec4(before.position.xyz, paramAt(i, 0u, sp.step) * scale);
        o.heading = vec4(f.heading, radius);
        o.up = vec4(f.up, radius);
        o.shape = sp.lineStyle;
    } else if (kind == kOrganSphere || kind == kOrganDisc) {
        float radius = 0.5 * (hasParam(i) ? paramAt(i, 0u, 0.0) * scale : before.heading.w);
        o.position = vec4(before.position.xyz, 0);
        o.heading = vec4(before.heading.xyz, radius);
        o.up = vec4(before.up.xyz, radius);
        o.shape = command == kTurtleDiscFacing ? kDiscFacesViewer : 0u;
    } else { // leaf: `~id(s)` or `~id(sx, sy, sz)`, scaled across, along and out of it (turtle_cpu.cpp)
        uint sym = symbolAt(i);
        float surfaceScale = surfaceScales[species * pc.symbols + sym] * scale;
        float first = paramAt(i, 0u, 1.0);
        bool three = paramCountAt(i) >= 3u;
        o.position = vec4(before.position.xyz, (three ? paramAt(i, 1u, 1.0) : first) * surfaceScale);
        o.heading = vec4(before.heading.xyz, first * surfaceScale);
        o.up = vec4(before.up.xyz, (three ? paramAt(i, 2u, 1.0) : first) * surfaceScale);
        o.shape = surfaceShapes[species * pc.symbols + sym];
        o.previousHeading.w = surfaceDrawing(sp, sym) == kSurfaceAroundBase ? kLeafAroundBase : 0.0;
    }

    uint slot = offsets[kind * pc.count + i];
    if (slot >= pc.organCapacity) return;
    instances[slot] = o;
    slots[i] = slot;
    lastSlots[i] = slot;
    growPlantBounds(plant, o);
    // An F inside a polygon closes the polygon's triangle too (classify.comp counted it).
    if (kind == kOrganStem && triangleFirst[i] != kNoModule) {
        OrganInstance t = triangleOf(o, i, after);
        t.kind = kOrganTriangle;
        t.shape = 0u;
        t.previousHeading = vec4(0);
        t.nextHeading = vec4(0);
        uint triangleSlot = offsets[kOrganTriangle * pc.count + i];
        if (triangleSlot >= pc.organCapacity) return;
        instances[triangleSlot] = t;
        growPlantBounds(plant, t);
    }
}
