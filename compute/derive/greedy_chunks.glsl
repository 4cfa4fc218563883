// Predecessors of several modules consume their neighbours, and which modules start a production depends on
// the ones before (the CPU walks left to right). The walk is a composition of small functions: on entering a
// module with s modules still to skip, the state becomes s - 1, or, when s is 0 (the module starts a rewrite),
// the length of the production chosen there minus 1; a plant's first module and a module dropped by a cut
// reset it to 0. Chunks of kGreedyChunk modules compose their functions (packed 4 bits per entry state),
// greedy_scan.comp composes the chunks in order, then each chunk marks its starts. A count only the device knows
// (kCountOnDevice: a recorded step) is the plant table's last entry.

uint greedyModules() { return pc.count != kCountOnDevice ? pc.count : plantStart[pc.plants]; }

uint strictLength(uint choice) { return choice == kChoiceDropped ? 1u : (choice >> 24u) + 1u; }

bool isPlantStart(uint i) {
    uint low = 0u, high = pc.plants;
    while (low < high) {
        uint mid = (low + high) / 2u;
        if (plantStart[mid] < i) low = mid + 1u; else high = mid;
    }
    return low <= pc.plants && plantStart[low] == i;
}

// One module of the walk: the state after it, and whether it starts a rewrite.
uint walkStep(uint i, uint state, out bool starts) {
    uint choice = choices[i];
    if (isPlantStart(i)) state = 0u;
    if (choice == kChoiceDropped) {
        starts = false;
        return 0u;
    }
    starts = state == 0u;
    return starts ? strictLength(choice) - 1u : state - 1u;
}
