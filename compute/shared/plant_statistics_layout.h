// What the growth simulation reports of each plant, as compute/grow/plant_statistics.comp writes it and
// src/field/plant_statistics.cpp (its CPU reference) computes it: from the turtle's organs of the plant, which
// each kind's instances hold together (they follow the modules, and the modules the plants).
#ifndef SIMECO_SHARED_PLANT_STATISTICS_LAYOUT_H
#define SIMECO_SHARED_PLANT_STATISTICS_LAYOUT_H

#include "compute/shared/organ_layout.h"
#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kPlantStatisticsWorkgroupSize = 64u;
SIMECO_CONST kLeafShapes = kLeafLastShape + 1u; // kLeafLanceolate .. kLeafLastShape

struct PlantStatistics {
    uint organs;    // organ instances drawn
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

SIMECO_SHARED_END

#endif
