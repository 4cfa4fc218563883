// Counter-based random numbers shared by the CPU reference engine (C++) and the GPU kernels (GLSL).
//
// A draw is a pure function of (seed, plant, pass, module index, draw number), so any thread can produce the
// numbers of any module without a shared generator, and CPU and GPU draw identical values. The mixer is the
// "lowbias32" integer hash (Chris Wellons, hash-prospector), chained over the key words.
#ifndef SIMECO_SHARED_RANDOM_H
#define SIMECO_SHARED_RANDOM_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_FN uint lowbias32(uint x) {
    x ^= x >> 16;
    x *= 0x7feb352du;
    x ^= x >> 15;
    x *= 0x846ca68bu;
    x ^= x >> 16;
    return x;
}

SIMECO_FN uint randomBits(uint seed, uint plant, uint pass, uint moduleIndex, uint draw) {
    uint h = lowbias32(seed ^ 0x9e3779b9u);
    h = lowbias32(h ^ plant);
    h = lowbias32(h ^ pass);
    h = lowbias32(h ^ moduleIndex);
    h = lowbias32(h ^ draw);
    return h;
}

// Uniform in [0, 1) with 24 bits, exactly representable as a 32-bit float on both sides.
SIMECO_FN float randomUnit(uint seed, uint plant, uint pass, uint moduleIndex, uint draw) {
    return float(randomBits(seed, plant, pass, moduleIndex, draw) >> 8u) * (1.0f / 16777216.0f);
}

SIMECO_SHARED_END

#endif
