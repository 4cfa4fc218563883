// What the growth kernels share: each module's plant (a binary search of the plant table), a stage's row and
// the properties a particle draws from it, and whether the particle lives. Needs the buffers `plantStart`,
// `speciesWords` and `rows` and the push constants `pc` (GrowPush).
#ifndef SIMECO_GROWTH_GLSL
#define SIMECO_GROWTH_GLSL

// The modules a kernel runs over: those the plant table's last entry counts, at most pc.count. A string a derivation
// recorded in the same submission is counted only on the device, and one whose step outgrew its room leaves a table
// not to be trusted, which the bound keeps within the buffers.
uint moduleCount() { return min(plantStart[pc.plants], pc.count); }

// The plant whose modules hold module i: the last p with plantStart[p] <= i.
uint plantOf(uint i, uint plants) {
    uint lo = 0u, hi = plants; // plantStart[lo] <= i < plantStart[hi]
    while (hi - lo > 1u) {
        uint mid = (lo + hi) / 2u;
        if (plantStart[mid] <= i) lo = mid;
        else hi = mid;
    }
    return lo;
}

// Whether the species has stage rows for the organ kind.
bool hasRows(uint species, uint organ) {
    return speciesWords[species * kSpeciesGrowthWords + kSpeciesFirstRow + organ] != kGrowNoRow;
}

// The first float of the organ's stage row in species `species`: the stage's own, else the organ's Default row.
uint stageRow(uint species, uint organ, float stage) {
    uint words = species * kSpeciesGrowthWords;
    uint first = speciesWords[words + kSpeciesFirstRow + organ];
    uint count = speciesWords[words + kSpeciesRowCount + organ];
    for (uint r = first; r < first + count; ++r)
        if (rows[r * kStageRowFloats + kStageNumber] == stage) return r * kStageRowFloats;
    return speciesWords[words + kSpeciesDefaultRow + organ] * kStageRowFloats;
}

// Property k of the row, as particle `id` of plant `plant` draws it in its range.
float property(uint row, uint k, uint plant, uint id) {
    float lo = rows[row + propertyMin(k)], hi = rows[row + propertyMax(k)];
    return lo + (hi - lo) * randomUnit(pc.seed, pc.firstPlant + plant, kGrowPropertyPass, id, k);
}

// Whether a particle lives: its age within its row's LifeTime (none: 0), and not shed in the shade.
bool alive(uint row, uint plant, uint id, float age, float shade) {
    float lifeTime = property(row, kLifeTime, plant, id);
    return (lifeTime <= 0.0 || age < lifeTime) && !shedInShade(property(row, kShadeTime, plant, id), shade);
}

#endif
