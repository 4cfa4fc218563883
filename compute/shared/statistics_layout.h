// The statistics of a module stream computed on the device (compute/stream/statistics.comp), shared by C++ and
// GLSL: what `simeco derive --format stats` reports, without reading the string back.
//
// Each invocation summarises a chunk of kStatisticsChunk consecutive modules: it counts each symbol, and it
// describes its brackets as the walk the CPU reference takes over them (a `[` adds one to the depth, a `]`
// takes one away but not below zero: depth' = max(depth + d, 0)). Such steps compose as v -> max(v + a, b),
// and the deepest value reached on the way as max(v + c, e), so each chunk is four numbers that the host
// composes in order: no chunk needs to know the depth its neighbours leave.
#ifndef SIMECO_SHARED_STATISTICS_LAYOUT_H
#define SIMECO_SHARED_STATISTICS_LAYOUT_H

#include "compute/shared/preamble.h"

SIMECO_SHARED_BEGIN

SIMECO_CONST kStatisticsWorkgroupSize = 64u;
SIMECO_CONST kStatisticsChunk = 256u;
// Alphabets up to this size are counted in shared memory first; larger ones straight into the buffer.
SIMECO_CONST kStatisticsSharedSymbols = 1024u;
// Minus infinity of the depth walk's summaries: below any depth a string of 2^32 modules can reach.
SIMECO_CONST kStatisticsNoDepth = 0x80000000u;

struct StatisticsPush {
    uint count;   // modules
    uint symbols; // alphabet size: entries of the symbol counts
    uint chunks;  // (count + kStatisticsChunk - 1) / kStatisticsChunk
    uint pad;
};

#ifdef __cplusplus
// One chunk's bracket walk (int values, kStatisticsNoDepth as the least int).
struct DepthSummary {
    int32_t a, b, c, e;
};
static_assert(sizeof(StatisticsPush) == 16);
static_assert(sizeof(DepthSummary) == 16);
#endif

SIMECO_SHARED_END

#endif
