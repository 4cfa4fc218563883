// What the growth simulation reports of each plant, as compute/grow/plant_statistics.comp writes it and
// src/field/plant_statistics.cpp (its CPU reference) computes it: from the turtle's organs of the plant, which
// each kind's instances hold together (they follow the modules, and the modules the plants).
#ifndef SIMECO_SHARED_PLANT_STATISTICS_LAYOUT_H
#define SIMECO_SHARED_PLANT_STATISTICS_LAYOUT_H

#include "compute/shared/organ_layout.h"
#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kPlantStatisticsWorkgroupSize = 64u;
SIMECO_CONST kSurfaceShapes = kSurfaceLastShape + 1u; // the built-in surfaces: leaf blades and blossoms

struct PlantStatistics {
    uint organs;    // organ instances drawn
    uint living;    // of them, those not shed: an organ shed at the end of its life is drawn at size 0
    float leafArea; // of its leaf blades (their shape's area at their length and width) and polygon triangles
    float light;    // the light its leaves caught: each leaf's area times its particle's light
    float height;   // the top of its highest organ above its base
};

struct PlantStatisticsPush {
    uint plants;
    uint particles; // 1: the drawn string carries particle state (light), else 0
    uint pad0;
    uint pad1;
};

// A plant lives until every organ it drew has been shed (a seed that has drawn nothing yet lives).
SIMECO_FN bool plantAlive(PlantStatistics s) {
    return s.organs == 0u || s.living > 0u;
}

SIMECO_SHARED_END

#endif
