// What every derivation engine is asked and what it returns: the options of a derivation (steps, seed,
// plants, module budget, homomorphism, particle state) and its result, the module stream of all plants.
#pragma once

#include <cstdint>
#include <vector>

#include "compute/shared/particle_layout.h"
#include "ir/grammar.h"
#include "ir/source_loc.h"
#include "stream/module_string.h"

namespace simeco::stream {

// The bytes an engine allocates per module of the largest string a derivation holds, every allocation that
// grows with the string counted (docs/BENCHMARKS.md compares them with measured peaks).
// The CPU reference: the string being rewritten and the next (symbol, parameter count, `stride` parameters)
// with room to grow by half, and a few bytes of the rest (measured: 27 bytes at 1 slot, 57 at 4).
uint64_t cpuBytesPerModule(int stride);
// The device: three streams (symbol, origin, liveness, parameters, and the particle state where the derivation
// carries it), seven words of scratch per module for the passes, all with room to grow by half; and on the
// host, the string read back and its staging copy.
uint64_t deviceBytesPerModule(int stride, bool particles = false);
uint64_t hostBytesPerDeviceModule(int stride);

// This machine's physical memory.
uint64_t hostMemoryBytes();

// The CPU reference's default module budget: what a quarter of this machine's memory holds.
uint64_t defaultModuleBudget(int stride);

// What both engines say when a step's string outgrows the field's module budget.
ir::LimitError moduleBudgetExceeded(uint64_t budget, int step);

// How long a derivation may run unless told otherwise: far longer than any field derives, short of a hang.
inline constexpr double kDefaultMaxSeconds = 1800;

struct DeriveOptions {
    int steps = -1;            // -1: the grammar's derivation length
    int64_t seed = -1;         // -1: the grammar's `seed:` (or 0)
    uint32_t plants = 1;       // independent copies, each with its own random stream
    // The number of plant 0's random stream: plants [firstPlant, firstPlant + plants) of a larger field, derived as
    // a batch of it, draw the numbers they draw in the whole field.
    uint32_t firstPlant = 0;
    uint64_t maxModules = 0;   // 0: defaultModuleBudget
    // The derivation stops with an error once it has run this long (checked before each step of each plant,
    // by PlantControl); 0: no limit. A derivation length may be 10^9 steps.
    double maxSeconds = kDefaultMaxSeconds;
    bool homomorphism = false; // return the string the turtle interprets: the result under the homomorphism
    // Carry each module's particle state (compute/shared/particle_layout.h) through the derivation, into the
    // result's string.particles. The axioms' modules, all plants' in order, start with initialParticles, or
    // at zero when it is empty.
    bool particles = false;
    std::vector<shared::ParticleState> initialParticles;
    // Where a light grid runs, 1 / the light in the open: light() in a production is the rewritten module's
    // particle's light times this (compute/shared/particle_layout.h); 0 (no grid) or without particles, light()
    // is 1.
    float lightScale = 0.0f;
    // Per plant (or empty: none): the plants that stand out of the field. They have no axiom and derive no steps,
    // so cost next to nothing: a field whose species' plants are unequal in number leaves such slots in the
    // rounds of its species (plant p is of species p mod their count).
    std::vector<uint8_t> absent;
    bool isAbsent(uint32_t plant) const { return plant < absent.size() && absent[plant]; }
};

struct DeriveResult {
    ModuleString string; // all plants, one segment each
    int steps = 0;       // steps performed by the plant that went furthest (fewer when a model called stop())
};

// DeriveOptions::initialParticles cut into each plant's axiom (zeros when it is empty; none for an absent plant).
// Throws std::invalid_argument unless it has one state for each module of the plants' axioms.
std::vector<std::vector<shared::ParticleState>> splitAxiomParticles(const std::vector<ir::Grammar>& species,
                                                                    uint32_t plants, const DeriveOptions& options);

} // namespace simeco::stream
