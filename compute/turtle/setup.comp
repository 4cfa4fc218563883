// Turtle, pass 1: each module's command, parent (the module whose state it continues: the one before it, or
// for `]` the one before its matching `[`), step relative to the parent, marks, and the first pointer of the
// step composition (its parent; a non-linear module points at itself, its state comes from the levels).
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "compute/turtle/turtle_buffers.glsl"
layout(set = 0, binding = 5, std430) readonly buffer DepthTree { int depthTree[]; };
layout(set = 0, binding = 6, std430) readonly buffer LevelInfo { uint levelInfo[]; };
layout(set = 0, binding = 7, std430) writeonly buffer Commands { uint commands[]; };
layout(set = 0, binding = 8, std430) writeonly buffer Parents { uint parents[]; };
layout(set = 0, binding = 9, std430) writeonly buffer Steps { TurtleStep steps[]; };
layout(set = 0, binding = 10, std430) writeonly buffer Pointers { uint pointers[]; };
layout(set = 0, binding = 11, std430) writeonly buffer Marks { uint marks[]; };
layout(set = 0, binding = 12, std430) writeonly buffer Plants { uint plantOfModule[]; };
// Every mark some module carries, so the host runs only the searches and levels the string needs.
layout(set = 0, binding = 13, std430) buffer Present { uint presentMarks; };
#define TURTLE_STATUS_BINDING 14
#include "compute/turtle/module_count.glsl"

#include "compute/turtle/turtle_math.glsl"
#include "compute/turtle/turtle_modules.glsl"
uint symOf(uint i) { return symbolAt(i); }
#include "compute/derive/depth_tree.glsl"

// Writes module i's command, parent, plant, marks, step and first pointer; returns its marks.
uint setUpModule(uint i) {
    uint plant = plantOf(i);
    uint begin = plantStarts[plant], end = plantStarts[plant + 1u];
    TurtleSpecies sp = speciesTable[speciesOf(plant)];
    uint command = commandAt(i, begin, end);
    // `{(n)` and `}(n)` are generalized cylinders, like @Gs and @Gc.
    if (command == kTurtlePolygonBegin && hasParam(i)) command = kTurtleCylinderStart;
    if (command == kTurtlePolygonEnd && hasParam(i)) command = kTurtleCylinderPoint;

    uint parent = i == begin ? kNoModule : i - 1u;
    if (command == kTurtleBranchClose) {
        uint open = matchClose(i, begin);
        if (open != kNoModule) parent = open == begin ? kNoModule : open - 1u;
    }

    uint mark = 0u;
    bool nonlinear = isNonlinear(command, sp);
    if (nonlinear) mark |= kMarkNonlinear;
    if (turtleDraws(command)) mark |= kMarkStem;
    // A surface that moves the turtle ends the stem like a move (turtle_cpu.cpp).
    bool surfaceMoves = command == kTurtleSurface && surfaceDrawn(sp, symbolAt(i)) &&
                        surfaceEnd(sp, symbolAt(i)) != vec3(0.0);
    if (command == kTurtleBranchOpen || turtleMovesOnly(command) || command == kTurtleSetPosition || surfaceMoves)
        mark |= kMarkStemBreak;
    if (command == kTurtleCylinderStart) mark |= kMarkCylinderStart | kMarkTubeBreak;
    if (command == kTurtleCylinderPoint) mark |= kMarkCylinderPoint;
    if (command == kTurtleBranchOpen) mark |= kMarkTubeBreak;
    if (command == kTurtlePolygonBegin) mark |= kMarkPolygon;
    if (command == kTurtleBranchClose) mark |= kMarkBranchClose;
    // The settings of a generalized cylinder's next control point, which its mesh looks back for.
    if (command == kTurtleContour) mark |= kMarkContour;
    if (command == kTurtleCylinderTangents && hasParam(i)) mark |= kMarkCylinderTangents;
    if (command == kTurtleRadiusTangents && paramCountAt(i) == 1u) mark |= kMarkRadiusScale;
    if (command == kTurtleRadiusTangents && paramCountAt(i) >= 2u) mark |= kMarkRadiusTangents;

    commands[i] = command;
    parents[i] = parent;
    plantOfModule[i] = plant;
    marks[i] = mark;
    steps[i] = nonlinear ? identityStep() : commandStep(command, i, sp);
    pointers[i] = nonlinear ? i : parent;
    return mark;
}

void main() {
    uint i = invocationIndex();
    uint mark = i < moduleCount() ? setUpModule(i) : 0u;
    uint marked = subgroupOr(mark);
    if (subgroupElect() && marked != 0u) atomicOr(presentMarks, marked);
}
