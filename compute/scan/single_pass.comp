// Exclusive prefix sum over uint32 in one pass: decoupled look-back with a bounded wait.
//
// This work is based on:
//   D. Merrill, M. Garland, "Single-pass Parallel Prefix Scan with Decoupled Look-back", NVIDIA NVR-2016-002.
//   T. Smith, R. Levien, J. D. Owens, "Decoupled Fallback: A Portable Single-Pass GPU Scan", 2025
//   (when a predecessor stalls, reduce its tile from the input instead of waiting for it).
//
// Each workgroup takes the next tile index from an atomic counter (so every tile it waits on was taken by a
// workgroup that already started), scans its tile locally, publishes the tile sum, then walks back over
// predecessors adding their published sums until it meets an inclusive prefix. Vulkan does not promise that
// a started workgroup keeps running while another spins (lavapipe runs workgroups as tasks on a small thread
// pool), so the walk polls a predecessor at most pc.lookBackSpins times; then the whole workgroup reduces
// that predecessor's tile from the input itself. The scan therefore finishes under any scheduling; the wait
// bound only trades redundant reads for waiting.
//
// status[0] is the tile counter; tile t's state lives in status[1 + 2t] (low half of its value) and
// status[2 + 2t] (high half), each word tagged with the state (see shared/config.h). The host zeroes the
// buffer before every dispatch. Input and output must be different buffers: a fallback re-reads input
// elements of earlier tiles, which an in-place scan may already have overwritten.
#version 450
#extension GL_GOOGLE_include_directive : require
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require

#include "compute/shared/config.h"

layout(local_size_x = kScanWorkgroupSize) in;

layout(set = 0, binding = 0, std430) readonly buffer Input { uint values[]; };
layout(set = 0, binding = 1, std430) writeonly buffer Output { uint prefix[]; };
layout(set = 0, binding = 2, std430) coherent buffer Status { uint status[]; };
layout(set = 0, binding = 3, std430) writeonly buffer Total { uint total; };
// When pc.count is kCountOnDevice, the elements to scan are deviceCounts[pc.tileCount], written by an earlier
// kernel; unread otherwise.
layout(set = 0, binding = 4, std430) readonly buffer DeviceCounts { uint deviceCounts[]; };
layout(push_constant) uniform Push { ScanSinglePassPush pc; };

#include "compute/scan/workgroup_scan.glsl"

shared uint sharedTile;
shared int sharedPredecessor;   // tile the look-back stalled on, or -1 when the prefix is complete
shared uint sharedExclusive;    // sum of all tiles before this one, accumulated by the look-back

const uint kLowMask = (1u << kScanStateShift) - 1u;

void publish(uint tile, uint state, uint value) {
    atomicExchange(status[1u + 2u * tile], (state << kScanStateShift) | (value & kLowMask));
    atomicExchange(status[2u + 2u * tile], (state << kScanStateShift) | (value >> kScanStateShift));
}

// The two words are written independently, so a reader can see them from different publications; the state
// tags disagree then and the tile counts as not ready yet.
uint readState(uint tile, out uint value) {
    uint low = atomicAdd(status[1u + 2u * tile], 0u);
    uint high = atomicAdd(status[2u + 2u * tile], 0u);
    uint state = low >> kScanStateShift;
    if (state != (high >> kScanStateShift)) {
        return kScanStateNotReady;
    }
    value = (low & kLowMask) | ((high & kLowMask) << kScanStateShift);
    return state;
}

// Run by one invocation: adds predecessors' sums to sharedExclusive from `predecessor` down, stopping at an
// inclusive prefix (sets -1) or at a predecessor that stayed not-ready for too long (records it).
void lookBack(int predecessor) {
    uint exclusive = sharedExclusive;
    uint spins = 0u;
    while (predecessor >= 0) {
        uint value = 0u;
        uint state = readState(uint(predecessor), value);
        if (state == kScanStateInclusive) {
            exclusive += value;
            predecessor = -1;
        } else if (state == kScanStateAggregate) {
            exclusive += value;
            --predecessor;
            spins = 0u;
        } else if (++spins >= pc.lookBackSpins) {
            break;
        }
    }
    sharedExclusive = exclusive;
    sharedPredecessor = predecessor;
}

void main() {
    if (gl_LocalInvocationIndex == 0u) {
        sharedTile = atomicAdd(status[0], 1u);
        sharedExclusive = 0u;
    }
    barrier();
    uint count = pc.count != kCountOnDevice ? pc.count : deviceCounts[pc.tileCount];
    uint tileCount = pc.count != kCountOnDevice ? pc.tileCount : (count + kScanTileSize - 1u) / kScanTileSize;
    uint tile = sharedTile;
    if (tile >= tileCount) {
        return;  // padding of a 2D dispatch; uniform over the workgroup
    }

    // Local scan of the whole tile, kept in registers until the tile's offset is known.
    uint v[kScanRounds * kScanValuesPerInvocation];
    uint localPrefix[kScanRounds];
    uint carry = 0u;
    for (uint round = 0u; round < kScanRounds; ++round) {
        uint base = tileElementBase(tile, round);
        uint sum = 0u;
        for (uint k = 0u; k < kScanValuesPerInvocation; ++k) {
            uint x = base + k < count ? values[base + k] : 0u;
            v[round * kScanValuesPerInvocation + k] = x;
            sum += x;
        }
        uint roundTotal;
        localPrefix[round] = carry + workgroupExclusiveAdd(sum, round & 1u, roundTotal);
        carry += roundTotal;
    }
    uint aggregate = carry;

    if (gl_LocalInvocationIndex == 0u) {
        publish(tile, tile == 0u ? kScanStateInclusive : kScanStateAggregate, aggregate);
        lookBack(int(tile) - 1);
    }
    barrier();
    // Uniform loop: each stalled predecessor is reduced by the whole workgroup, then the look-back resumes.
    for (;;) {
        int stalled = sharedPredecessor;
        if (stalled < 0) {
            break;
        }
        uint sum = 0u;
        for (uint round = 0u; round < kScanRounds; ++round) {
            uint base = tileElementBase(uint(stalled), round);
            for (uint k = 0u; k < kScanValuesPerInvocation; ++k) {
                sum += values[base + k];  // an earlier tile is always full
            }
        }
        uint stalledTotal;
        workgroupExclusiveAdd(sum, 0u, stalledTotal);
        if (gl_LocalInvocationIndex == 0u) {
            sharedExclusive += stalledTotal;
            lookBack(stalled - 1);
        }
        barrier();
    }
    uint exclusive = sharedExclusive;
    if (gl_LocalInvocationIndex == 0u) {
        if (tile != 0u) {
            publish(tile, kScanStateInclusive, exclusive + aggregate);
        }
        if (pc.writeTotal != 0u && tile == tileCount - 1u) {
            total = exclusive + aggregate;
        }
    }

    for (uint round = 0u; round < kScanRounds; ++round) {
        uint base = tileElementBase(tile, round);
        uint running = exclusive + localPrefix[round];
        for (uint k = 0u; k < kScanValuesPerInvocation; ++k) {
            if (base + k < count) {
                prefix[base + k] = running;
            }
            running += v[round * kScanValuesPerInvocation + k];
        }
    }
}
