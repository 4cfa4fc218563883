// The parallel turtle's data, shared by C++ and GLSL (kernels in compute/turtle, host in gpu/turtle_gpu).
//
// Every module has a parent: the module whose state it continues (the one before it, or for `]` the one before
// its matching `[`), so a plant's modules form a tree whose root is the plant's initial state. A module's
// command is a TurtleStep relative to its parent's state; steps compose (TurtleStep is a monoid), so states are
// found by composing steps up the tree: first within chunks of kTurtleChunk modules by one invocation each,
// then by pointer jumping among the modules that chunks point at (the work stays near linear). Commands that depend on the absolute state (`$`,
// `@R`, `@M`, world rotations, tropism after a segment) cannot be steps: they are resolved one level at a time
// (their level is how many of them lie on the path from the root), each from the state the steps lead to.
#ifndef SIMECO_SHARED_TURTLE_STATE_LAYOUT_H
#define SIMECO_SHARED_TURTLE_STATE_LAYOUT_H

#include "compute/shared/organ_layout.h"
#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kTurtleWorkgroupSize = 64u;
// Modules one invocation composes in order before the pointer jumping, which then runs only over the modules
// that other chunks point at (see chunk_steps.comp).
SIMECO_CONST kTurtleChunk = 32u;
// Where the plants stand (TurtlePush::placed): on the grid, each at its PlantPlacement, or scattered about the grid
// (shared/field_scatter.h).
SIMECO_CONST kFieldOnGrid = 0u;
SIMECO_CONST kFieldPlaced = 1u;
SIMECO_CONST kFieldScattered = 2u;
SIMECO_CONST kPaletteEntries = 256u;

// The turtle after a module: its frame (heading, left, up), position and scalars.
struct TurtleState {
    vec4 heading;  // w: width, in world units (`!` and `#` apply the scale of their time, as cpfg)
    vec4 left;     // w: colour index
    vec4 up;       // w: scale
    vec4 position; // w: elasticity
};

// A module's effect relative to the state before it: the frame turns by the rotation whose columns are
// heading, left and up (in the turtle's own coordinates); the position moves by translation + scale *
// scaledTranslation (turtle coordinates, the scale before the module); each scalar x becomes a x + b, the width
// a x + b + c times the scale before the module (c in translation.w).
struct TurtleStep {
    vec4 heading;           // xyz: the rotation's first column
    vec4 left;              // xyz: second column
    vec4 up;                // xyz: third column
    vec4 translation;       // xyz; w: the width's share of the scale
    vec4 scaledTranslation; // xyz
    vec4 widthColor;        // width a, b; colour a, b
    vec4 scaleElasticity;   // scale a, b; elasticity a, b
};

// A species' turtle settings (turtle/turtle_settings.h).
struct TurtleSpecies {
    float angleDegrees;
    float step;
    float width;
    float widthIncrement;
    float colorIncrement;
    float initialColor;
    float elasticity;
    float elasticityIncrement;
    vec4 tropism; // xyz: unit direction; w: 1 when segments may bend (elasticity can be non-zero)
    vec4 torque;  // xyz: cpfg's torque (TurtleSettings::torque); w: 1 when it is not zero
    uint taperedLines; // 1: a segment narrows to the width set before the command that ends it (cpfg's)
    uint dollar;       // kDollar*: what `$` does
    uint tropismRule;  // kTropism*
    uint lineStyle;    // kLine*: how its F and G segments are drawn
    // Where its `~` surfaces start in the command table: kSurfaceWords per symbol, the end point a surface moves
    // the turtle to per unit of its first scale (float bits, in heading, left and up) and how it draws (kSurface*).
    uint surfaces;
    float initialScale; // the scale before any `@D` (cpfg's `initial scale:`)
    // Generalized cylinders (TurtleSettings): kCylinderMeshes, kCylinderTwist and kCylinderCpfgTubes, the rings'
    // sides from bit
    // kCylinderSidesShift, the contours from bit kCylinderContoursShift; contour k's ring is at contourRings[
    // contourFirst + k * (sides + 1)], its points' w the contour's id.
    uint cylinders;
    uint contourFirst;
};
// What `$` does: roll the turtle level (the quick grammars'), return from a sub-L-system call (cpfg's .l files of
// several L-systems), or nothing (cpfg's other .l files).
SIMECO_CONST kDollarIgnored = 0u;
SIMECO_CONST kDollarRolls = 1u;
SIMECO_CONST kDollarReturns = 2u;
SIMECO_CONST kCylinderMeshes = 1u;
SIMECO_CONST kCylinderTwist = 2u;
SIMECO_CONST kCylinderCpfgTubes = 4u;  // tubes as cpfg's pixel and polygon line styles draw them
SIMECO_CONST kCylinderSidesShift = 3u; // 10 bits: at most kMostCylinderSides
SIMECO_CONST kCylinderContoursShift = 13u;
SIMECO_CONST kMostCylinderSides = 1023u;
SIMECO_CONST kSurfaceWords = 4u;
// How `~` draws a surface: not at all (an id a cpfg view does not define), along the heading (a built-in blade or
// blossom, a model), or around its base (a cpfg surface from its contact point).
SIMECO_CONST kSurfaceNone = 0u;
SIMECO_CONST kSurfaceAlongHeading = 1u;
SIMECO_CONST kSurfaceAroundBase = 2u;

// How segments bend toward the tropism (ir::TropismRule).
SIMECO_CONST kTropismTorque = 0u;
SIMECO_CONST kTropismCpfgDirection = 1u;
SIMECO_CONST kTropismCpfgTropism = 2u;

// Per-module marks that the searches up the tree stop at (TurtlePush hitMask and stopMask).
SIMECO_CONST kMarkNonlinear = 1u;      // resolved by levels, not composed
SIMECO_CONST kMarkStem = 2u;           // draws a stem segment (F, G)
SIMECO_CONST kMarkStemBreak = 4u;      // the next segment does not continue the last one: `[`, f, @M
SIMECO_CONST kMarkCylinderStart = 8u;  // @Gs, `{(n)`
SIMECO_CONST kMarkCylinderPoint = 16u; // @Gc, @Ge, `}(n)`
SIMECO_CONST kMarkTube = 32u;          // a cylinder point that drew a tube segment
SIMECO_CONST kMarkTubeBreak = 64u;     // `[`, @Gs: the next tube segment does not continue the last one
SIMECO_CONST kMarkPolygon = 128u;      // `{`: a polygon's first module
SIMECO_CONST kMarkBranchClose = 256u;  // `]`: with kMarkStemBreak, where a tapering segment's end stops narrowing
SIMECO_CONST kMarkContour = 512u;             // @#: a cylinder's contour
SIMECO_CONST kMarkCylinderTangents = 1024u;   // @Gt with parameters
SIMECO_CONST kMarkRadiusScale = 2048u;        // @Gr(s)
SIMECO_CONST kMarkRadiusTangents = 4096u;     // @Gr(a1, l1[, a2, l2])
// The marks whose passes a recording leaves out where its room says they do not occur.
SIMECO_CONST kSearchedMarks = kMarkNonlinear | kMarkStem | kMarkCylinderStart | kMarkCylinderPoint;

// A cylinder point `@Gc(n)` draws the tube from the last one as n segments (at most this many) along the
// Hermite curve whose tangents are the turtle's headings at the two points, each 1.2 times as long as the chord
// (cpfg's tangent parameters before any `@Gt`).
SIMECO_CONST kTubeMaxSegments = 64u;

// A cylinder point draws a tube segment from the last one when they lie further apart than this times one
// plus the last point's distance from the plant's root: shorter segments' directions are rounding noise.
#ifdef __cplusplus
inline constexpr float kTubeEpsilon = 1e-5f;
#else
const float kTubeEpsilon = 1e-5;
#endif

// Push constants of every turtle kernel.
// The modules a pass interprets are counted on the device, in the turtle's status words: from the host's count,
// or from the plant table of a derivation recorded before the turtle in the same submission. `count` is their
// bound, the length of the per-module arrays (and of each organ kind's slice of the flags).
SIMECO_CONST kTurtleStatusModules = 0u; // modules to interpret
SIMECO_CONST kTurtleStatusLevels = 1u;  // levels of non-linear modules (level_layout.comp)
SIMECO_CONST kTurtleStatusOrgans = 2u;  // organs the string draws (field.comp), written or not
// In a recording's copy of the words for the host only: the marks that occur in the string (setup.comp's).
SIMECO_CONST kTurtleStatusMarks = 3u;
SIMECO_CONST kTurtleStatusWords = 4u;

// The workgroups of a recording's passes (pass_sizes.comp), from the module count and the marks that occur, which
// interpret() reads back instead: per gate, (x, y, z) of the passes over chunks, then of those over modules. A
// gate's passes get none where none of its marks occur.
SIMECO_CONST kGateModules = 0u;   // every module's passes: always open
SIMECO_CONST kGateStems = 1u;     // kMarkStem
SIMECO_CONST kGateCylinders = 2u; // kMarkCylinderStart or kMarkCylinderPoint
SIMECO_CONST kGateTubes = 3u;     // kMarkCylinderStart
SIMECO_CONST kGateNonlinear = 4u; // kMarkNonlinear
SIMECO_CONST kGates = 5u;
SIMECO_CONST kGateWords = 6u;

// The lists a round of pointer jumping walks (jump_list.glsl): a header of the workgroups that walk the list
// (x, y, z, written by list_groups.comp) and the items' count, then the items (module indices).
SIMECO_CONST kJumpListCount = 3u;
SIMECO_CONST kJumpListHeader = 4u;

struct TurtlePush {
    uint count;       // modules at most (the status words count them)
    uint plants;
    uint stride;      // parameter slots per module
    uint species;
    uint symbols;     // alphabet size: the command tables' row length
    uint atSymbol;    // `@`, `~`, `?` (kNoModule when the alphabet lacks them)
    uint tildeSymbol;
    uint querySymbol;
    uint first;       // levels: the level resolved; jumps: the round
    uint items;       // levels laid out and resolved (a deeper string's table counts no organs)
    uint hitMask;     // searches: marks that end the search with a result
    uint stopMask;    // searches: marks that end it without one
    float spacing;    // field: distance between plants (0: from the widest plant)
    uint organCapacity; // instances the buffer holds: no organ is written past them
    uint maxGroupsX;    // workgroups a dispatch holds along x (level_layout.comp splits larger ones over y)
    uint placed;        // place: where the plants stand (kFieldOnGrid, kFieldPlaced, kFieldScattered)
};

// turtle/organ_merge.comp: one batch's organs into the field's instances.
struct OrganMergePush {
    uint count[kOrganKinds];       // the batch's organs of each kind, one kind after the other from `source`
    uint destination[kOrganKinds]; // where each kind's go in the field's instances
    uint source;                   // the batch's first instance in the buffer the batches were kept in
    uint organs;                   // the batch's organs
    uint firstPlant;               // added to each organ's plant
    uint firstModule;              // added to each organ's module
};

#ifdef __cplusplus
static_assert(sizeof(OrganMergePush) == 56);
static_assert(sizeof(TurtleState) == 64);
static_assert(sizeof(TurtleStep) == 112);
static_assert(sizeof(TurtleSpecies) == 96);
static_assert(sizeof(TurtlePush) == 64);
#endif
SIMECO_SHARED_END

#endif
