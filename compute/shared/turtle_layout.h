// Turtle commands: what each symbol of an alphabet does when interpreted, shared by the CPU turtle and the
// turtle kernels. The host builds one command per symbol from its name (turtle/turtle_commands.h); kernels
// read that table instead of comparing names.
#ifndef SIMECO_SHARED_TURTLE_LAYOUT_H
#define SIMECO_SHARED_TURTLE_LAYOUT_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kTurtleNone = 0u;          // draws nothing, changes nothing (plain letters, `%`, queries)
SIMECO_CONST kTurtleBranchOpen = 1u;    // [
SIMECO_CONST kTurtleBranchClose = 2u;   // ]
SIMECO_CONST kTurtleDraw = 3u;          // F(l): move and draw a stem segment (inside a polygon, also a vertex)
SIMECO_CONST kTurtleMove = 4u;          // f(l): move without drawing (inside a polygon, a vertex)
SIMECO_CONST kTurtleTurnLeft = 5u;      // +(a): about U, heading toward left
SIMECO_CONST kTurtleTurnRight = 6u;     // -(a)
SIMECO_CONST kTurtlePitchDown = 7u;     // &(a): about L, heading toward -U
SIMECO_CONST kTurtlePitchUp = 8u;       // ^(a)
SIMECO_CONST kTurtleRollLeft = 9u;      // \(a): about H
SIMECO_CONST kTurtleRollRight = 10u;    // /(a)
SIMECO_CONST kTurtleTurnAround = 11u;   // |: 180 degrees about U
SIMECO_CONST kTurtleRollLevel = 12u;    // $: roll so that L is horizontal, U closest to up (not in cpfg .l files,
                                        // where it ends a sub-L-system call: TurtleSpecies::dollar)
SIMECO_CONST kTurtleWidthUp = 13u;      // #(w): add the width increment, or set w
SIMECO_CONST kTurtleWidthDown = 14u;    // !(w): subtract the width increment, or set w
SIMECO_CONST kTurtleColorUp = 15u;      // ;(c): add the colour increment, or set c
SIMECO_CONST kTurtleColorDown = 16u;    // ,(c)
SIMECO_CONST kTurtleSphere = 17u;       // @O(d): sphere of diameter d (default: the width)
SIMECO_CONST kTurtleDisc = 18u;         // @c(d): disc in the H-L plane
SIMECO_CONST kTurtleDiscFacing = 19u;   // @o(d): disc facing the viewer
SIMECO_CONST kTurtleSurface = 20u;      // ~name(s): a leaf surface scaled by s
SIMECO_CONST kTurtleSetPosition = 21u;  // @M(x,y,z)
SIMECO_CONST kTurtleSetHeading = 22u;   // @R(hx,hy,hz[,ux,uy,uz])
SIMECO_CONST kTurtleScaleSet = 23u;     // @D(s)
SIMECO_CONST kTurtleScaleUp = 24u;      // @Di(s): multiply by s
SIMECO_CONST kTurtleScaleDown = 25u;    // @Dd(s): divide by s
SIMECO_CONST kTurtleElasticitySet = 26u;  // @Ts(id, e)
SIMECO_CONST kTurtleElasticityUp = 27u;   // @T(id, e)
SIMECO_CONST kTurtleElasticityDown = 28u; // @Td(id, e)
SIMECO_CONST kTurtlePolygonBegin = 29u; // {
SIMECO_CONST kTurtlePolygonEnd = 30u;   // }
SIMECO_CONST kTurtlePolygonVertex = 31u; // .
SIMECO_CONST kTurtleCylinderStart = 32u; // @Gs: a generalized cylinder's first control point
SIMECO_CONST kTurtleCylinderPoint = 33u; // @Gc, @Ge: a control point; a tube segment from the previous one
SIMECO_CONST kTurtleRotateWorldX = 34u;  // rotx(a): SimEco, radians about the world's x axis
SIMECO_CONST kTurtleRotateWorldY = 35u;  // roty(a)
SIMECO_CONST kTurtleRotateWorldZ = 36u;  // rotz(a)
SIMECO_CONST kTurtlePitchRadians = 37u;  // rotr(a): SimEco, pitch about the reference axis (L), radians
SIMECO_CONST kTurtleRollRadians = 38u;   // rotu(a): SimEco, turn about the growth direction (H), radians
SIMECO_CONST kTurtleQueryPosition = 39u; // ?P(x,y[,z]): filled with the position
SIMECO_CONST kTurtleQueryHeading = 40u;  // ?H
SIMECO_CONST kTurtleQueryLeft = 41u;     // ?L
SIMECO_CONST kTurtleQueryUp = 42u;       // ?U
SIMECO_CONST kTurtleIgnored = 43u;       // a predefined command simeco does not draw (@PS, @Tx, @!, ...)
SIMECO_CONST kTurtleTropism = 44u;       // tropism(e): SimEco's growth, set the elasticity to e
SIMECO_CONST kTurtleAlive = 45u;         // alive(a): SimEco's growth, scale what follows by a (0: shed)
SIMECO_CONST kTurtlePhototropism = 46u;  // phototropism(e,x,y,z): SimEco's growth, turn the heading toward the
                                         // direction (x,y,z) by e |H x d| about H x d (d the direction made unit)
SIMECO_CONST kTurtleQueryEnvironment = 47u; // ?E(...): answered by the light grid where one runs (light_layout.h)
SIMECO_CONST kTurtleTilt = 48u;          // tilt(p,r): SimEco's growth, rotu(r) rotr(p) rotu(-r) in one module: pitch
                                         // by p radians about L turned by r about H
SIMECO_CONST kTurtleDrawNoVertex = 49u;  // G(l): as F, but no vertex of a polygon
SIMECO_CONST kTurtleMoveNoVertex = 50u;  // g(l): as f, but no vertex of a polygon
SIMECO_CONST kTurtleRollUpright = 51u;   // @v: cpfg's roll so that H and its U share a vertical plane, its U
                                        // closest to up (ours, its reverse, closest to down)
SIMECO_CONST kTurtleElasticityStep = 52u; // _(e): cpfg's, the elasticity increased by the view's increment, or set
SIMECO_CONST kTurtleContour = 53u;        // @#(id): cpfg's, the contour of a generalized cylinder's next rings
SIMECO_CONST kTurtleCylinderTangents = 54u; // @Gt(a[,b]): cpfg's, the cylinder's tangents at the next control point,
                                          // a times the chord into it, b out of it (both 1.2 at first)
SIMECO_CONST kTurtleRadiusTangents = 55u; // @Gr(s) or @Gr(a1,l1[,a2,l2]): cpfg's, how the cylinder's radius runs
                                          // into and out of the next control point (contour_ring.h, CylinderShape)
SIMECO_CONST kTurtleSubLsystemCall = 56u; // ?(label, s): cpfg's sub-L-system call, lengths and widths scaled by s
                                            // until its `$` (kTurtleRollLevel where `$` does not roll) returns
SIMECO_CONST kTurtleCommands = 57u;

// F and G draw a segment; f and g move without one. Inside a polygon F, f and `.` add vertices, G and g none, and
// F and G still draw their segments, as cpfg draws them.
SIMECO_FN bool turtleDraws(uint command) { return command == kTurtleDraw || command == kTurtleDrawNoVertex; }
SIMECO_FN bool turtleMovesOnly(uint command) { return command == kTurtleMove || command == kTurtleMoveNoVertex; }
SIMECO_FN bool turtleAddsVertex(uint command) {
    return command == kTurtleDraw || command == kTurtleMove || command == kTurtlePolygonVertex;
}

// cpfg writes its predefined modules of several characters as separate modules: `@O(d)` is `@` then `O(d)`,
// `@Gc(n)` is `@`, `G`, `c(n)`, `?P(x,y)` is `?` then `P(x,y)`, `~l(s)` is `~` then `l(s)` (productions can
// rewrite the parts: `o(r) --> o(r+1)` changes `@o(r)`). The command belongs to the last part, which carries
// the parameters; the parts before it do nothing. Two-letter @-commands start with one of these letters.
SIMECO_CONST kPairNone = 0xFFFFFFFFu;
SIMECO_CONST kPairG = 0u; // @Gs @Gc @Ge @Gt @Gr
SIMECO_CONST kPairT = 1u; // @Ts @Td @Tp @Tf @Tx
SIMECO_CONST kPairD = 2u; // @Di @Dd
SIMECO_CONST kPairB = 3u; // @bo @bc
SIMECO_CONST kPairP = 4u; // @PS @PC @PD
SIMECO_CONST kPairPrefixes = 5u;

SIMECO_SHARED_END

#endif
