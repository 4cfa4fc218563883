// The CPU reference engine moves each module's particle state with the module (compute/shared/particle_layout.h):
// copies keep theirs, successors take their predecessor's, deleted and cut modules take theirs away.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "grammar_text.h"

namespace {

using simeco::stream::DeriveOptions;
using simeco::shared::ParticleState;
using simeco::testing::grammarFromText;
using simeco::testing::lsystem;

// A state told apart by its age slot; the other slots follow it so that all of them are checked to travel.
ParticleState state(float age) {
    ParticleState s;
    for (uint32_t k = 0; k < simeco::shared::kParticleStateFloats; ++k) s.value[k] = age + 0.125f * float(k);
    return s;
}

struct Carried {
    std::string modules;      // the string in cpfg notation
    std::vector<float> ages;  // each module's age slot
    bool wholeStates = true;  // every module's state is one of state(age)
};

Carried derive(const std::string& text, std::vector<float> axiomAges, uint32_t plants = 1,
               bool homomorphism = false) {
    simeco::ir::Grammar g = grammarFromText(text);
    DeriveOptions options;
    options.plants = plants;
    options.particles = true;
    options.homomorphism = homomorphism;
    for (float age : axiomAges) options.initialParticles.push_back(state(age));
    simeco::stream::DeriveResult r = simeco::cpu::deriveCpu(g, options);
    Carried c;
    c.modules = simeco::stream::formatModules(r.string, g.alphabet, 0, r.string.size());
    EXPECT_EQ(r.string.particles.size(), r.string.size());
    for (const ParticleState& s : r.string.particles) {
        c.ages.push_back(s.value[simeco::shared::kParticleAge]);
        c.wholeStates = c.wholeStates && s == state(s.value[simeco::shared::kParticleAge]);
    }
    return c;
}

TEST(ParticleCarry, CopiesKeepTheirStateAndSuccessorsTakeTheirPredecessors) {
    Carried c = derive(lsystem("ABC", "B --> XYZ", 1), {1, 2, 3});
    EXPECT_EQ(c.modules, "AXYZC");
    EXPECT_EQ(c.ages, (std::vector<float>{1, 2, 2, 2, 3}));
    EXPECT_TRUE(c.wholeStates);
}

TEST(ParticleCarry, StatesFollowTheirModulesOverSteps) {
    Carried c = derive(lsystem("AB", "A --> BA", 3), {1, 2});
    EXPECT_EQ(c.modules, "BBBAB");
    EXPECT_EQ(c.ages, (std::vector<float>{1, 1, 1, 1, 2}));
}

TEST(ParticleCarry, ErasedAndCutModulesTakeTheirStatesAway) {
    EXPECT_EQ(derive(lsystem("ABC", "B --> *", 1), {1, 2, 3}).ages, (std::vector<float>{1, 3}));
    Carried cut = derive(lsystem("A[BCD]E", "B --> %", 2), {1, 2, 3, 4, 5, 6, 7});
    EXPECT_EQ(cut.modules, "A[]E");
    EXPECT_EQ(cut.ages, (std::vector<float>{1, 2, 6, 7}));
}

TEST(ParticleCarry, APredecessorOfSeveralModulesGivesItsFirstModulesState) {
    Carried c = derive(lsystem("CABD", "AB --> XY", 1), {1, 2, 3, 4});
    EXPECT_EQ(c.modules, "CXYD");
    EXPECT_EQ(c.ages, (std::vector<float>{1, 2, 2, 4}));
}

TEST(ParticleCarry, DecompositionPassesTheStateDown) {
    Carried c = derive(lsystem("AC", "A --> AB\ndecomposition\nmaximum depth: 2\nB --> CD\nC --> E", 1), {1, 2});
    EXPECT_EQ(c.modules, "AEDE");
    EXPECT_EQ(c.ages, (std::vector<float>{1, 1, 1, 2}));
}

TEST(ParticleCarry, TheHomomorphismPassesTheStateDown) {
    Carried c = derive(lsystem("AB", "A --> AA\nhomomorphism\nA --> FG", 1), {1, 2}, 1, true);
    EXPECT_EQ(c.modules, "FGFGB");
    EXPECT_EQ(c.ages, (std::vector<float>{1, 1, 1, 1, 2}));
}

TEST(ParticleCarry, EveryPlantStartsWithItsOwnAxiomStates) {
    Carried c = derive(lsystem("AB", "A --> AA", 1), {1, 2, 3, 4}, 2);
    EXPECT_EQ(c.modules, "AAB" "AAB");
    EXPECT_EQ(c.ages, (std::vector<float>{1, 1, 2, 3, 3, 4}));
}

TEST(ParticleCarry, AxiomsStartAtZeroUnlessGiven) {
    simeco::ir::Grammar g = grammarFromText(lsystem("AB", "A --> AA", 2));
    DeriveOptions options;
    options.particles = true;
    simeco::stream::DeriveResult r = simeco::cpu::deriveCpu(g, options);
    ASSERT_EQ(r.string.particles.size(), 5u);
    for (const ParticleState& s : r.string.particles) EXPECT_EQ(s, ParticleState{});
}

TEST(ParticleCarry, NoStatesUnlessAsked) {
    simeco::ir::Grammar g = grammarFromText(lsystem("AB", "A --> AA", 2));
    EXPECT_TRUE(simeco::cpu::deriveCpu(g, DeriveOptions{}).string.particles.empty());
}

TEST(ParticleCarry, InitialStatesMustCoverTheAxioms) {
    simeco::ir::Grammar g = grammarFromText(lsystem("AB", "A --> AA", 2));
    DeriveOptions options;
    options.particles = true;
    options.plants = 2;
    options.initialParticles = {state(1), state(2), state(3)};
    EXPECT_THROW(simeco::cpu::deriveCpu(g, options), std::invalid_argument);
}

} // namespace
