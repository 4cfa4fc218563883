// How the plants of a field without placements stand when scattered (turtle::FieldOptions::scattered): each is
// moved from the centre of its grid cell by up to 0.3 of the spacing along x and along z, and turned about its own
// axis, by draws of its index, so that a field of one grammar looks planted rather than stamped. The CPU turtle
// (turtle/interpretation.cpp) and the GPU's (turtle/organ_bounds.glsl) draw the same numbers.
#ifndef SIMECO_SHARED_FIELD_SCATTER_H
#define SIMECO_SHARED_FIELD_SCATTER_H

#include "compute/shared/preamble.h"
#include "compute/shared/random.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kFieldScatterPass = 0xFFFFFF10u;
SIMECO_CONST_FLOAT kFieldScatterJitter = 0.3f; // of the spacing, either way

// Draws 0 and 1 move the plant along x and z, draw 2 turns it.
SIMECO_FN float fieldScatterDraw(uint plant, uint draw) {
    return randomUnit(0u, plant, kFieldScatterPass, 0u, draw);
}

// The plant's move along x (axis 0) or z (axis 1), in spacings.
SIMECO_FN float fieldScatterOffset(uint plant, uint axis) {
    return kFieldScatterJitter * (2.0f * fieldScatterDraw(plant, axis) - 1.0f);
}

// Its turn about its own axis, in radians.
SIMECO_FN float fieldScatterYaw(uint plant) {
    return 6.28318530717958647692f * fieldScatterDraw(plant, 2u);
}

SIMECO_SHARED_END

#endif
