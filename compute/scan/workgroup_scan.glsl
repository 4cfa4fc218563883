// Workgroup-wide exclusive sum built from subgroup operations, for any subgroup size (8 on lavapipe,
// 32 on NVIDIA, 64 on AMD). Needs GL_KHR_shader_subgroup_arithmetic and kScanWorkgroupSize.
#ifndef SIMECO_SCAN_WORKGROUP_SCAN_GLSL
#define SIMECO_SCAN_WORKGROUP_SCAN_GLSL

// Per-subgroup totals, double-buffered: call k uses slot k & 1, so a call may start writing while slower
// invocations still read the previous call's results (one barrier per call saved).
shared uint scanSubgroupTotals[2][kScanWorkgroupSize];
shared uint scanWorkgroupTotal[2];

// Exclusive prefix of `value` over the invocations of the workgroup in gl_LocalInvocationIndex order;
// `groupTotal` receives the sum over the whole workgroup. Call in uniform control flow.
uint workgroupExclusiveAdd(uint value, uint slot, out uint groupTotal) {
    // The subgroup's last invocation holds its total in its inclusive prefix: one subgroup operation, which
    // lavapipe runs as a loop over the invocations, where an exclusive prefix and a sum are two.
    uint through = subgroupInclusiveAdd(value);
    if (gl_SubgroupInvocationID == gl_SubgroupSize - 1u) {
        scanSubgroupTotals[slot][gl_SubgroupID] = through;
    }
    barrier();
    // The subgroup totals can outnumber the lanes of one subgroup (32 totals, 8 lanes on lavapipe), so the
    // first subgroup walks them in chunks, carrying the running sum.
    if (gl_SubgroupID == 0u) {
        uint carry = 0u;
        for (uint first = 0u; first < gl_NumSubgroups; first += gl_SubgroupSize) {
            uint i = first + gl_SubgroupInvocationID;
            uint t = i < gl_NumSubgroups ? scanSubgroupTotals[slot][i] : 0u;
            uint p = subgroupExclusiveAdd(t);
            if (i < gl_NumSubgroups) {
                scanSubgroupTotals[slot][i] = carry + p;
            }
            carry += subgroupAdd(t);
        }
        if (subgroupElect()) {
            scanWorkgroupTotal[slot] = carry;
        }
    }
    barrier();
    groupTotal = scanWorkgroupTotal[slot];
    return scanSubgroupTotals[slot][gl_SubgroupID] + through - value;
}

// First element of round `round` owned by this invocation in tile `tile`.
uint tileElementBase(uint tile, uint round) {
    return tile * kScanTileSize + round * (kScanWorkgroupSize * kScanValuesPerInvocation) +
           gl_LocalInvocationIndex * kScanValuesPerInvocation;
}

#endif
