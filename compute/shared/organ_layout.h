// Organ instances: what turtle interpretation writes and the renderer draws, shared by C++ and GLSL.
//
// One instance per drawn organ (a stem segment, a sphere, a disc, a leaf, a polygon triangle). The turtle
// kernels write them grouped by kind into one buffer: kind k occupies instances [first[k], first[k] + count[k])
// as told by an OrganTable in a second buffer, so the renderer draws each kind with one indirect draw and the
// host never reads the instances.
#ifndef SIMECO_SHARED_ORGAN_LAYOUT_H
#define SIMECO_SHARED_ORGAN_LAYOUT_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

// Organ kinds, each drawn with its own mesh.
SIMECO_CONST kOrganStem = 0u;     // F/G segment: a (tapered) cylinder from position along heading, mitred at joints
SIMECO_CONST kOrganSphere = 1u;   // @O: a sphere of diameter radiusBase * 2 centred on position
SIMECO_CONST kOrganDisc = 2u;     // @c: a disc in the heading-left plane; @o: the same disc turned to the viewer
SIMECO_CONST kOrganLeaf = 3u;     // ~name: a leaf blade along heading, in the heading-left plane (shape in `shape`)
SIMECO_CONST kOrganTriangle = 4u; // one triangle of a filled polygon `{ ... }`; vertices in the three vectors
SIMECO_CONST kOrganKinds = 5u;

// Surface shapes (OrganInstance.shape for kOrganLeaf, the kind `~` draws), chosen from a surface's name: leaf
// blades, then blossoms (in the heading's direction, a flower's face turned along it), then any models.
SIMECO_CONST kLeafLanceolate = 0u;
SIMECO_CONST kLeafOvate = 1u;
SIMECO_CONST kLeafCordate = 2u;
SIMECO_CONST kLeafCompound = 3u;   // pinnate: leaflets in pairs along a rachis (Rosa)
SIMECO_CONST kLeafTrifoliate = 4u; // three obcordate leaflets at the end of a long petiole (Oxalis, clover)
SIMECO_CONST kLeafSerrate = 5u;    // ovate with a toothed margin (Lantana)
SIMECO_CONST kLeafLastShape = kLeafSerrate;
SIMECO_CONST kBlossomStar = 6u; // five spreading obovate petals around a yellow eye (Oxalis)
SIMECO_CONST kBlossomHead = 7u; // a dome of small four-lobed florets, yellow at its centre (Lantana)
SIMECO_CONST kBlossomRose = 8u; // a cup of rounded petals in three rings (Rosa)
SIMECO_CONST kSurfaceLastShape = kBlossomRose; // models are shapes kSurfaceLastShape + 1 + k
// OrganInstance.previousHeading.w of a leaf whose surface reaches around its base (a cpfg surface).
SIMECO_CONST_FLOAT kLeafAroundBase = 1.0f;
// OrganInstance.shape for kOrganDisc: faces the viewer (@o) rather than lying in the heading-left plane (@c).
SIMECO_CONST kDiscFacesViewer = 1u;
// OrganInstance.shape for kOrganStem, how its line is drawn (ir::LineStyle): a shaded cylinder; a flat band facing
// the viewer, its radii in world units; or a flat line facing the viewer, its radii in pixels. Only the picture
// changes: the organ's radii are its width in world units for every other use (bounds, light, mesh export).
SIMECO_CONST kLineCylinder = 0u;
SIMECO_CONST kLinePolygon = 1u;
SIMECO_CONST kLinePixel = 2u;
// OrganInstance.shape for kOrganTriangle: a triangle of a generalized cylinder's mesh (cpfg's `line style:
// cylinder`), not of a polygon. Its corners' normals, across the cylinder's surface (zero where none is defined),
// are in previousHeading.xyz, nextHeading.xyz and (position.w, heading.w, up.w), so it is shaded smooth.
SIMECO_CONST kTriangleOfCylinder = 1u;

// OrganInstance.color.w: kColorUntextured for an organ drawn in its colour, kColorFirstTexture + k for one whose
// colour tints texture layer k (a SimEco stage's Texture; ir::DrawAssets).
SIMECO_CONST_FLOAT kColorUntextured = 1.0f;
SIMECO_CONST_FLOAT kColorFirstTexture = 2.0f;

// A triangle stores its vertices in position.xyz, heading.xyz and up.xyz; the other kinds a frame.
struct OrganInstance {
    vec4 position; // xyz: base (stem, leaf) or centre (sphere, disc); w: length along heading (stem, leaf)
    vec4 heading;  // xyz: unit heading H; w: radius at the base (stem), radius (sphere, disc), width (leaf)
    vec4 up;       // xyz: unit up U (left is U x H); w: radius at the top (stem)
    vec4 color;    // linear RGB and alpha
    // Stem joints: the heading of the segment below (xyz, zero at a branch's first segment) and of the segment
    // continuing this one (zero at a tip); the ends are cut on the bisecting planes, so a bent stem is closed.
    // A leaf's previousHeading.w: kLeafAroundBase where its surface reaches around its base (a cpfg surface, from
    // its contact point), else zero: it lies along its heading within half its width of it (a blade, a model).
    vec4 previousHeading;
    vec4 nextHeading;
    uint plant;    // plant index in the field
    uint kind;     // kOrgan*
    uint shape;    // leaf shape, disc orientation
    uint module;   // index of the interpreted module that drew it (the organ id in images)
};

// Per kind: instances written and where they start. Followed by the bounds of everything drawn, as
// order-preserving integers of floats (see boundsKey in turtle kernels) so kernels can reduce them with atomics.
struct OrganTable {
    uint count[kOrganKinds];
    uint first[kOrganKinds];
    uint pad0;
    uint pad1;
    int boundsMin[4];
    int boundsMax[4];
};

// Where a plant stands and which way it grows: the rows of an affine map from the plant's own frame (drawn at the
// origin, growing along +y) into the field: a rotation in xyz, the plant's place in w.
struct PlantPlacement {
    vec4 x;
    vec4 y;
    vec4 z;
};

#ifdef __cplusplus
inline bool operator==(const PlantPlacement& a, const PlantPlacement& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
}
static_assert(sizeof(PlantPlacement) == 48);
static_assert(sizeof(OrganInstance) == 112);
static_assert(sizeof(OrganTable) == 80);
#endif
SIMECO_SHARED_END

#endif
