// The host side of a derivation, the same for every engine: which species each plant is, how many steps it
// derives, its globals and arrays, its control blocks (Start, StartEach, EndEach, End) and its axiom, all
// evaluated as cpfg evaluates them. The engines rewrite the strings; this decides when and with which globals.
#pragma once

#include <chrono>
#include <cstdint>
#include <vector>

#include "compute/shared/particle_layout.h"
#include "ir/grammar.h"
#include "stream/derive_options.h"
#include "stream/evaluator.h"
#include "stream/module_string.h"
#include "stream/random_passes.h"
#include "stream/stepped_state.h"

namespace simeco::stream {

class PlantControl {
public:
    // Plant p is of species p mod species.size() (ir::speciesOfPlant); the species share one alphabet. The
    // seed is options.seed, else the first species'; the stride is the largest of the species'.
    PlantControl(const std::vector<ir::Grammar>& species, const DeriveOptions& options);

    uint32_t plants() const { return plants_; }
    uint32_t seed() const { return seed_; }
    // The number of plant p's random stream (DeriveOptions::firstPlant).
    uint32_t randomStream(uint32_t plant) const { return firstPlant_ + plant; }
    float lightScale() const { return lightScale_; } // DeriveOptions::lightScale
    int stride() const { return stride_; }
    // The module budget of the whole stream: options.maxModules, else sized to this machine's memory.
    uint64_t budget() const { return budget_; }
    const std::vector<ir::Grammar>& allSpecies() const { return species_; }
    const ir::Grammar& speciesOf(uint32_t plant) const;
    // The steps the plant derives: options.steps, else its species' derivation length.
    int stepsOf(uint32_t plant) const;
    // The most steps any plant derives.
    int steps() const { return steps_; }
    PlantState& state(uint32_t plant) { return states_[plant]; }
    const PlantState& state(uint32_t plant) const { return states_[plant]; }

    // Resets the plant's globals, runs its Start block and appends its axiom to `axiom` (parameters evaluated
    // with the globals Start set); with a null `axiom`, only the globals (what the homomorphism sees).
    void start(uint32_t plant, ModuleString* axiom);
    // Every plant started, their axioms in one string with its plant table.
    ModuleString startAll();
    // Before step `step` (from 1): whether the plant derives it (it has steps left and called no stop());
    // when it does, its StartEach block runs, with the global Q set to the step where the grammar has one.
    // Throws ir::LimitError once the derivation has run past options.maxSeconds.
    bool beginStep(uint32_t plant, int step);
    // After the plant derived step `step`: its EndEach block runs, and the step counts as derived.
    void endStep(uint32_t plant, int step);
    // beginStep for every plant, into `growing`; whether any plant derives the step. And endStep for those that did.
    bool beginFieldStep(int step, std::vector<uint8_t>& growing);
    void endFieldStep(int step, const std::vector<uint8_t>& growing);
    // After the derivation: the plant's End block.
    void finish(uint32_t plant);
    // Steps derived by the plant that went furthest.
    int mostStepsDerived() const;
    // Steps the plant has derived.
    int stepsDerived(uint32_t plant) const { return derived_[plant]; }
    // The plant's variables and steps derived, as a saved field keeps them, and back (after startAll(); a file
    // a plant opened is not kept).
    PlantVariables variables(uint32_t plant) const;
    void restore(uint32_t plant, const PlantVariables& v);

private:
    void run(uint32_t plant, const std::vector<ir::Stmt>& block, uint32_t step, ControlBlock which);

    const std::vector<ir::Grammar>& species_;
    uint32_t plants_ = 1;
    uint32_t seed_ = 0;
    uint32_t firstPlant_ = 0;
    int stride_ = 1;
    uint64_t budget_ = 0;
    double maxSeconds_ = 0;
    float lightScale_ = 0.0f;
    std::chrono::steady_clock::time_point started_;
    int fixedSteps_ = -1;
    int steps_ = 0;
    std::vector<PlantState> states_;
    std::vector<int> derived_;
    std::vector<uint8_t> absent_; // DeriveOptions::absent, one per plant
};

} // namespace simeco::stream
