// Layouts shared by the renderer's C++ host code, its graphics shaders and its compute kernels: the per-frame
// uniform block, push constants, the organ mesh vertex, and the indirect draw records the kernels write.
//
// Only vec4/mat4-sized members in uniform blocks and 16-byte groups in push blocks, so std140/std430 and C++
// agree without padding rules; the static_asserts at the end hold the C++ side to it.
#ifndef SIMECO_RENDER_DRAW_LAYOUT_H
#define SIMECO_RENDER_DRAW_LAYOUT_H

#include "compute/shared/organ_layout.h"
#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN
#ifdef __cplusplus
struct mat4 {
    vec4 columns[4];
};
struct uvec4 {
    uint x, y, z, w;
};
#endif

// The colour of a blossom's eye (linear RGB): the yellow of Oxalis' throat and Lantana's young florets.
SIMECO_CONST_FLOAT kBlossomEyeRed = 0.92f;
SIMECO_CONST_FLOAT kBlossomEyeGreen = 0.62f;
SIMECO_CONST_FLOAT kBlossomEyeBlue = 0.04f;

// A round stem's shadow is cast by a ribbon through its axis this many radii wide on either side: cos(pi / 12), the
// distance of the flats of the 12-sided drawn stem (kStemSides), so that the ribbon stays inside it.
SIMECO_CONST_FLOAT kStemRibbonHalfWidth = 0.96592583f;

// DrawPush.kind beyond the organ kinds: the ground plane, which reads no instance.
SIMECO_CONST kDrawGround = kOrganKinds;

// DrawPush.pass: which light a draw adds. Without shadows one pass adds both; with shadow volumes the organs' pass
// lays down the ambient colour, depth and ids, and the sun's light beside them, which the sunlit pass
// (shadows/sunlit.frag) adds where the stencil says a point is lit.
SIMECO_CONST kPassFull = 0u;
SIMECO_CONST kPassAmbient = 1u;

// DrawFrame.options.x
SIMECO_CONST kStyleLit = 0u;
SIMECO_CONST kStyleToon = 1u;
SIMECO_CONST kStyleOutline = 2u;  // toon bands; the outline kernel draws the lines
SIMECO_CONST kStylePaperCut = 3u;

// Local size of the renderer's 1D kernels and the 2D tile of the outline kernel.
SIMECO_CONST kDrawWorkgroupSize = 64u;
SIMECO_CONST kOutlineTile = 8u;

// Each shadow-casting triangle becomes a closed volume: itself as the near cap, its corners extruded away from the
// sun, one side per edge and the extruded corners as the far cap. Where the ground receives the shadows the corners
// are extruded to a plane just below it (so a volume covers the pixels between an organ and its shadow only);
// else to the point at infinity opposite the sun, where the sides meet and the far cap vanishes. A volume is
// stored as its 6 corners (kVolumeVerticesPerTriangle: the near cap's, then the far cap's) and drawn as one
// instance of an indexed draw: 8 triangles (kVolumeCorners indices) over kVolumeVertices vertices, the vertex
// shader's work per volume (shadow_volume.vert).
SIMECO_CONST kVolumeVerticesPerTriangle = 6u;
SIMECO_CONST kVolumeCorners = 24u;
SIMECO_CONST kVolumeVertices = 12u;

// A vertex of the organ meshes, in organ-local coordinates: x along the heading, y along left, z along up.
// Stem vertices carry in position.w which ring they belong to (0 bottom, 1 top) and in normal.w 1 for the end
// caps (kStemBandVertex for the far band's), so the vertex shader can taper the stem and cut its ends on the joint
// planes. Surface vertices carry
// their shape in normal.w and in position.w how far their colour turns from the organ's to a blossom's eye
// (kBlossomEye): 1 for a blossom's yellow centre, else 0.
struct MeshVertex {
    vec4 position;
    vec4 normal;
};
SIMECO_CONST_FLOAT kStemBandVertex = 2.0f;

// The per-frame uniform block of the organ shaders (std140).
struct DrawFrame {
    mat4 viewProj;
    vec4 cameraPosition;  // xyz; w: the world's size of a pixel at unit distance along the view (pixel lines)
    vec4 cameraRight;     // xyz: the image's x axis in the world, for discs that face the viewer
    vec4 cameraUp;        // xyz: the image's y axis (upwards) in the world
    vec4 sunDirection;    // xyz: unit vector towards the sun
    vec4 sunColor;        // rgb: irradiance from the sun
    vec4 skyColor;        // rgb: ambient light from above
    vec4 groundBounce;    // rgb: ambient light from below
    vec4 groundColor;     // rgb: albedo of the ground plane
    vec4 groundPlane;     // xyz: centre of the ground square; w: half its side
    vec4 background;      // rgb: what shows where nothing is drawn (and through a paper cut)
    // x: style (kStyle*); y: toon colour bands; z: paper-cut threshold (float bits); w: 1 for a parallel projection
    uvec4 options;
};

struct DrawPush {
    uint kind;  // kOrgan* or kDrawGround
    uint pass;  // kPass*
};

// draw_args.comp: the index ranges of each kind's meshes (drawn near, and far: a coarser mesh of the same organ,
// OrganMeshData::far), and how many volume vertices fit in their buffer.
struct DrawArgsPush {
    uint indexCount[kOrganKinds];
    uint firstIndex[kOrganKinds];
    int vertexOffset[kOrganKinds];
    uint farIndexCount[kOrganKinds];
    uint farFirstIndex[kOrganKinds];
    int farVertexOffset[kOrganKinds];
    uint volumeCapacity;  // vertices; a multiple of kVolumeVerticesPerTriangle
    uint leafShapes;      // shapes in the leaf mesh, each drawn by a draw of its own after the kinds' draws
};

// Leaf shapes a frame draws apart (the built-in ones and the models after them): each shape's leaves are drawn with
// that shape's triangles alone.
SIMECO_CONST kDrawMaxLeafShapes = 128u;

// A frame's organs are drawn from lists (organs/draw_lists.comp): one per organ kind and one per leaf shape (a
// slot), each at two levels of detail, near (the drawn meshes) and far (coarser ones, for organs a few pixels
// across); organs wholly outside the view are in none. A list's draw reads its instances through the frame's
// order, where each list has its places (draw_args.comp lays them out from the counts). A bucket is a slot at a
// level: slot + level * kDrawSlots. The leaf kind's own slot stays empty.
SIMECO_CONST kDrawSlots = kOrganKinds + kDrawMaxLeafShapes;
SIMECO_CONST kDrawLevelNear = 0u;
SIMECO_CONST kDrawLevelFar = 1u;
SIMECO_CONST kDrawBuckets = 2u * kDrawSlots;

// organs/draw_lists.comp: counts each bucket's organs (kDrawListsCount), then, once draw_args.comp has made the
// counts into each bucket's first place in the order, writes every organ's instance there (kDrawListsScatter).
SIMECO_CONST kDrawListsCount = 0u;
SIMECO_CONST kDrawListsScatter = 1u;
struct DrawListsPush {
    uint pass;
    uint shapes;
    uint levels;  // 1: organs a few pixels across are drawn far; 0: all near
    uint cull;    // 1: organs wholly outside the view are left out
    // Far below these sizes on screen, in pixels: a stem's width, a leaf's length or width, a sphere's or disc's
    // diameter.
    float farStemPixels;
    float farLeafPixels;
    float farRoundPixels;
    uint pad0;
};

// The indirect draw of the shadow volumes, preceded by the counter the volume kernel allocates with.
struct VolumeDraw {
    uint allocated;  // vertices claimed by the volume kernel (may exceed the capacity: those were dropped)
    // The rest: VkDrawIndexedIndirectCommand of kVolumeCorners indices, an instance per volume.
    uint pad0;
    uint pad1;
    uint pad2;
    uint indexCount;  // VkDrawIndexedIndirectCommand, at byte 16
    uint instanceCount;
    uint firstIndex;
    int vertexOffset;
    uint firstInstance;
};

// shadow_volumes.comp: one dispatch per organ kind, one invocation per instance of it.
struct ShadowVolumePush {
    vec4 awayFromSun;  // xyz: unit direction the sunlight travels; w: open surfaces' push along it, per organ size
    vec4 cameraRight;  // xyz: as DrawFrame, so viewer-facing discs cast the shadow of what is drawn
    vec4 cameraUp;
    uint kind;
    uint firstIndex;     // the kind's hull triangles in the mesh index buffer
    uint triangleCount;
    int vertexOffset;
    uint capacity;       // vertices in the volume buffer
    uint closedHull;     // 1: a closed hull (casts from the faces turned away from the sun); 0: an open surface
    uint capped;         // 1: extrude to the plane y = capHeight below the ground; 0: to infinity
    float capHeight;
    uint window;         // vertices in each of the volume buffer's kVolumeWindows bindings (a multiple of 6)
    // A leaf whose length and width are under farLeafPixels on screen casts from its shape's far cut: a pixel's
    // size there is pixelAtUnitDepth times the organ's depth, dot(viewDepth, (position, 1)) (viewProj's last row).
    // farLeafPixels 0: every leaf from its shadow cut.
    float pixelAtUnitDepth;
    float farLeafPixels;
    uint cull;  // 1: organs whose volumes lie wholly outside the view (by the frame's DrawFrame) cast none
    vec4 viewDepth;
};

// The volume buffer is written through this many storage bindings of one window each, so that it may hold more than
// one binding does (maxStorageBufferRange: 128 MiB on lavapipe); it is drawn from as one vertex buffer.
SIMECO_CONST kVolumeWindows = 4u;

// present/display_bytes.comp: a frame's colours as bytes for a window.
struct DisplayPush {
    uint pixels;
    uint encodeSrgb; // 0 where the window's format encodes sRGB itself
    uint pad0;
    uint pad1;
};

// toon_outline.comp: dark lines where depth or plant changes, over the copied frame buffers.
struct OutlinePush {
    vec4 lineColor;   // rgb, linear
    uint width;
    uint height;
    uint radius;      // line half-width in pixels
    float threshold;  // relative change of the depth's second difference that makes an edge
    float nearPlane;
    float farPlane;
    uint parallel;    // 1: a parallel projection, whose depth is affine across any plane already
    uint pad1;
};

#ifdef __cplusplus
static_assert(sizeof(MeshVertex) == 32);
static_assert(sizeof(DrawFrame) == 64 + 11 * 16);
static_assert(sizeof(DisplayPush) == 16);
static_assert(sizeof(DrawPush) == 8);
static_assert(sizeof(DrawArgsPush) == 128);
static_assert(sizeof(DrawListsPush) == 32);
static_assert(sizeof(VolumeDraw) == 36);
static_assert(sizeof(ShadowVolumePush) == 112);
static_assert(sizeof(OutlinePush) == 48);
#endif
SIMECO_SHARED_END

#endif
