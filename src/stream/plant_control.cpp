#include "stream/plant_control.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "ir/species.h"

namespace simeco::stream {

PlantControl::PlantControl(const std::vector<ir::Grammar>& species, const DeriveOptions& options) : species_(species) {
    if (species.empty()) throw std::invalid_argument("PlantControl: no species");
    plants_ = std::max<uint32_t>(options.plants, 1);
    seed_ = options.seed >= 0 ? uint32_t(options.seed) : species.front().seed;
    firstPlant_ = options.firstPlant;
    for (const ir::Grammar& g : species)
        stride_ = std::max(stride_, g.maxParams());
    budget_ = options.maxModules ? options.maxModules : defaultModuleBudget(stride_);
    maxSeconds_ = options.maxSeconds;
    lightScale_ = options.lightScale;
    started_ = std::chrono::steady_clock::now();
    fixedSteps_ = options.steps;
    for (uint32_t plant = 0; plant < std::min<uint32_t>(plants_, uint32_t(species.size())); ++plant)
        steps_ = std::max(steps_, stepsOf(plant));
    states_.resize(plants_);
    derived_.assign(plants_, 0);
    absent_.assign(plants_, 0);
    for (uint32_t plant = 0; plant < plants_; ++plant) absent_[plant] = options.isAbsent(plant);
}

const ir::Grammar& PlantControl::speciesOf(uint32_t plant) const {
    return species_[ir::speciesOfPlant(plant, species_.size())];
}

int PlantControl::stepsOf(uint32_t plant) const {
    return fixedSteps_ >= 0 ? fixedSteps_ : speciesOf(plant).derivationLength;
}

void PlantControl::run(uint32_t plant, const std::vector<ir::Stmt>& block, uint32_t step, ControlBlock which) {
    Evaluator evaluator(speciesOf(plant), states_[plant]);
    evaluator.key = controlBlockKey(seed_, randomStream(plant), step, which);
    evaluator.exec(block, nullptr);
}

void PlantControl::start(uint32_t plant, ModuleString* axiom) {
    const ir::Grammar& g = speciesOf(plant);
    states_[plant].reset(g);
    Evaluator evaluator(g, states_[plant]);
    evaluator.key = controlBlockKey(seed_, randomStream(plant), 0, ControlBlock::Start);
    evaluator.exec(g.startBlock, nullptr);
    if (!axiom || absent_[plant]) return;
    // The axiom's parameters may use globals of the Start block, and draw on from its stream.
    std::vector<float> values;
    for (const ir::SuccessorModule& m : g.axiom) {
        values.clear();
        for (const ir::Expr& e : m.args)
            values.push_back(static_cast<float>(evaluator.eval(e, nullptr)));
        axiom->push(m.sym, values.data(), values.size());
    }
}

PlantVariables PlantControl::variables(uint32_t plant) const {
    const PlantState& st = states_[plant];
    return {st.globals, st.arrays, st.stopRequested, derived_[plant]};
}

void PlantControl::restore(uint32_t plant, const PlantVariables& v) {
    PlantState& st = states_[plant];
    if (v.globals.size() != st.globals.size() || v.arrays.size() != st.arrays.size())
        throw std::invalid_argument("PlantControl::restore: the variables are not the plant's grammar's");
    for (size_t a = 0; a < v.arrays.size(); ++a)
        if (v.arrays[a].size() != st.arrays[a].size())
            throw std::invalid_argument("PlantControl::restore: an array is not the plant's grammar's");
    st.globals = v.globals;
    st.arrays = v.arrays;
    st.stopRequested = v.stopRequested;
    derived_[plant] = v.stepsDerived;
}

ModuleString PlantControl::startAll() {
    ModuleString axioms;
    axioms.stride = stride_;
    axioms.plantStart.push_back(0);
    for (uint32_t plant = 0; plant < plants_; ++plant) {
        start(plant, &axioms);
        axioms.plantStart.push_back(axioms.size());
    }
    return axioms;
}

bool PlantControl::beginStep(uint32_t plant, int step) {
    if (step > stepsOf(plant) || states_[plant].stopRequested || absent_[plant]) return false;
    if (maxSeconds_ > 0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count() > maxSeconds_)
        throw ir::LimitError(fmt::format("the derivation ran past its time limit of {} s in step {} of {} "
                                         "(raise it with --max-seconds, or derive fewer steps)",
                                         maxSeconds_, step, stepsOf(plant)));
    const ir::Grammar& g = speciesOf(plant);
    if (!g.globalNames.empty() && g.globalNames.front() == "Q") states_[plant].globals[0] = step;
    run(plant, g.startEachBlock, uint32_t(step), ControlBlock::StartEach);
    return true;
}

void PlantControl::endStep(uint32_t plant, int step) {
    run(plant, speciesOf(plant).endEachBlock, uint32_t(step), ControlBlock::EndEach);
    ++derived_[plant];
}

bool PlantControl::beginFieldStep(int step, std::vector<uint8_t>& growing) {
    growing.resize(plants_);
    bool any = false;
    for (uint32_t plant = 0; plant < plants_; ++plant) {
        growing[plant] = beginStep(plant, step);
        any = any || growing[plant];
    }
    return any;
}

void PlantControl::endFieldStep(int step, const std::vector<uint8_t>& growing) {
    for (uint32_t plant = 0; plant < plants_; ++plant)
        if (growing[plant]) endStep(plant, step);
}

void PlantControl::finish(uint32_t plant) {
    run(plant, speciesOf(plant).endBlock, 0, ControlBlock::End);
}

int PlantControl::mostStepsDerived() const {
    return *std::max_element(derived_.begin(), derived_.end());
}

} // namespace simeco::stream
