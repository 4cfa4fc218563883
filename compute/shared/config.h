// Workgroup sizes, tile shapes and push-constant layouts shared by the C++ host code and the GLSL kernels.
//
// Both sides include this file, so a tile size or a push-constant field changed here changes both at once;
// the dispatch helper additionally checks sizes against the SPIR-V reflection at run time.
#ifndef SIMECO_SHARED_CONFIG_H
#define SIMECO_SHARED_CONFIG_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

// A count the host does not know when it records a command buffer: in place of a count in push constants
// (ScanSinglePassPush::count, DerivePush::count, DeriveHelperPush::count and total) it tells the kernel to read
// the count on the device, where a derivation recorded step after step left it (GpuDeriver's recorded steps).
SIMECO_CONST kCountOnDevice = 0xFFFFFFFFu;

// Prefix sum (compute/scan). A workgroup handles one tile of kScanTileSize consecutive elements in
// kScanRounds rounds; in each round every invocation owns kScanValuesPerInvocation consecutive elements, so
// neighbouring invocations touch neighbouring 16-byte chunks (coalesced on GPUs, SIMD-friendly on lavapipe).
// 256 invocations keeps the per-subgroup totals within 32 subgroups even at lavapipe's subgroup size of 8.
SIMECO_CONST kScanWorkgroupSize = 256u;
SIMECO_CONST kScanValuesPerInvocation = 4u;
SIMECO_CONST kScanRounds = 4u;
SIMECO_CONST kScanTileSize = kScanWorkgroupSize * kScanValuesPerInvocation * kScanRounds;

// Look-back tile states of the single-pass scan. Each status word carries a state in its top bits and half
// of a 32-bit value in its low 16 bits; a reader accepts a tile's value only when both halves show the same
// state, so no 64-bit atomics or memory-model extension are needed.
SIMECO_CONST kScanStateNotReady = 0u;
SIMECO_CONST kScanStateAggregate = 1u;
SIMECO_CONST kScanStateInclusive = 2u;
SIMECO_CONST kScanStateShift = 16u;
// How many times a look-back polls a predecessor before reducing the predecessor's tile itself (the default of
// ScanSinglePassPush::lookBackSpins). Bounds the wait, so the scan finishes even where workgroups are not
// guaranteed to run concurrently.
SIMECO_CONST kScanLookBackSpins = 256u;

// Push constants: only 32-bit scalars, so C++ and std430 layouts agree without padding rules.
struct ScanReducePush {
    uint count;      // elements in the input
    uint tileCount;  // tiles (one per workgroup)
};

struct ScanDownsweepPush {
    uint count;           // elements in the input
    uint tileCount;       // tiles (one per workgroup)
    uint hasTileOffsets;  // nonzero: add tileOffsets[tile] (the exclusive scan of the tile sums) to each tile
    uint writeTotal;      // nonzero (single tile only): store the sum of all elements in total
};

struct ScanSinglePassPush {
    uint count;       // elements in the input, or kCountOnDevice
    uint tileCount;   // tiles (one per workgroup); with kCountOnDevice, the index of the count's word
    uint writeTotal;     // nonzero: the last tile stores the sum of all elements in total
    uint lookBackSpins;  // polls of a not-ready predecessor before the fallback (>= 1; tests lower it)
};

#ifdef __cplusplus
static_assert(sizeof(ScanReducePush) == 8);
static_assert(sizeof(ScanDownsweepPush) == 16);
static_assert(sizeof(ScanSinglePassPush) == 16);
#endif
SIMECO_SHARED_END

#endif
