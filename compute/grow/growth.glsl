// What the growth kernels share: each module's plant (a binary search of the plant table) and a particle's
// floats as one array.
#ifndef SIMECO_GROWTH_GLSL
#define SIMECO_GROWTH_GLSL

// The plant whose modules hold module i: the last p with plantStart[p] <= i. Needs a `plantStart` buffer.
uint plantOf(uint i, uint plants) {
    uint lo = 0u, hi = plants; // plantStart[lo] <= i < plantStart[hi]
    while (hi - lo > 1u) {
        uint mid = (lo + hi) / 2u;
        if (plantStart[mid] <= i) lo = mid;
        else hi = mid;
    }
    return lo;
}

#endif
