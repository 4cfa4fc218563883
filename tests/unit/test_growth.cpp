// The growth simulation's CPU reference (grow/tick_cpu.h) on small scenes: which module continues a particle,
// organs that grow continuously between derivation steps, properties drawn per plant and per particle, and the
// stage tables' fallbacks.
#include <bit>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compute/shared/growth_layout.h"
#include "compute/shared/particle_layout.h"
#include "cpu/derive.h"
#include "grow/growing_species.h"
#include "grow/growth_tables.h"
#include "grow/tick_cpu.h"
#include "lang/eco_parser.h"

namespace simeco::test {
namespace {

// One plant: an apex that becomes a stem with a leaf, and stems that branch.
std::string scene(const std::string& stem, const std::string& leaf, const std::string& rules) {
    return "EcoSystem 1.0 \"Test\" {\n Plant \"P\" {\n DeriveTime = 3.0;\n Apex {}\n Stem {\n" + stem + "}\n Leaf {\n" +
           leaf + "}\n Grow {\n" + rules + "}\n }\n}\n";
}

struct Grown {
    grow::GrowingSpecies species;
    grow::GrowthTables tables;
    std::vector<float> deriveTimes;
};

Grown grown(const std::string& text, uint32_t plants) {
    Grown g{grow::growingSpecies(lang::parseEcoText(text, "test.eco")), {}, {}};
    g.tables = grow::growthTables(g.species.species, g.species.ecoPlants);
    g.deriveTimes = grow::plantDeriveTimes(g.species.ecoPlants, plants, 1);
    return g;
}

stream::DeriveOptions options(uint32_t plants) {
    stream::DeriveOptions o;
    o.plants = plants;
    o.seed = 1;
    o.particles = true;
    return o;
}

uint32_t idOf(const shared::ParticleState& p) {
    return std::bit_cast<uint32_t>(p.value[shared::kParticleId]);
}

TEST(Growth, TheFirstModuleOfAnOrganContinuesItsParticleAndTheOthersAreBorn) {
    Grown g = grown(scene("Default { GrowRate = 1.0; GrowTime = 10.0; BroadenRate = 0.1; }", "",
                          "w = S(0);\nS(0) -> S(1)[rotr(0.5)S(0)]S(0);\n"),
                    1);
    cpu::SteppedDerivation derivation(g.species.species, options(1));
    grow::TickSettings ts{&g.tables, 1, 1.0f, 0, 1};
    grow::tickCpu(ts, derivation.current());
    ts.tick = 1;
    grow::tickCpu(ts, derivation.current());
    const shared::ParticleState axiom = derivation.current().particles[0];
    EXPECT_FLOAT_EQ(axiom.value[shared::kParticleElongation], 2.0f);
    ASSERT_EQ(derivation.advance({1}), 1u);
    ts.tick = 2;
    grow::tickCpu(ts, derivation.current());
    // S(1) [ rotr / S(0) ] S(0): the first stem goes on growing in its new stage; the other two start at zero.
    const stream::ModuleString& s = derivation.current();
    ASSERT_EQ(s.size(), 7u);
    EXPECT_EQ(idOf(s.particles[0]), idOf(axiom));
    EXPECT_FLOAT_EQ(s.particles[0].value[shared::kParticleElongation], 3.0f);
    EXPECT_FLOAT_EQ(s.particles[0].value[shared::kParticleAge], 3.0f);
    EXPECT_FLOAT_EQ(s.particles[0].value[shared::kParticleStageAge], 1.0f);
    for (size_t i : {4u, 6u}) {
        EXPECT_FLOAT_EQ(s.particles[i].value[shared::kParticleElongation], 1.0f) << i;
        EXPECT_FLOAT_EQ(s.particles[i].value[shared::kParticleAge], 1.0f) << i;
        EXPECT_NE(idOf(s.particles[i]), idOf(axiom)) << i;
    }
    EXPECT_NE(idOf(s.particles[4]), idOf(s.particles[6]));
    // The brackets, the rotation and the branch's roll are born too, as modules of classes of their own.
    for (size_t i : {1u, 2u, 3u, 5u})
        EXPECT_NE(idOf(s.particles[i]), idOf(axiom)) << i;
    EXPECT_NE(idOf(s.particles[2]), idOf(s.particles[1]));
}

// The size the drawn string gives plant 0's only leaf.
float leafSize(const Grown& g, const cpu::SteppedDerivation& derivation, const grow::TickSettings& ts) {
    stream::ModuleString drawn = derivation.drawn();
    grow::growSizesCpu(ts, g.deriveTimes, drawn);
    const ir::SymbolId leaf = *g.species.species[0].alphabet.find("leaf");
    for (size_t i = 0; i < drawn.size(); ++i)
        if (drawn.sym[i] == leaf) return drawn.paramsOf(i)[0];
    return -1.0f;
}

TEST(Growth, AnApexThatBecomesAStemIsBornAgain) {
    Grown g = grown(scene("Default { GrowRate = 1.0; GrowTime = 10.0; }", "", "w = A(0);\nA(0) -> S(0);\n"), 1);
    cpu::SteppedDerivation derivation(g.species.species, options(1));
    grow::TickSettings ts{&g.tables, 1, 1.0f, 0, 1};
    grow::tickCpu(ts, derivation.current());
    const uint32_t apex = idOf(derivation.current().particles[0]);
    ASSERT_EQ(derivation.advance({1}), 1u);
    ts.tick = 1;
    grow::tickCpu(ts, derivation.current());
    EXPECT_NE(idOf(derivation.current().particles[0]), apex);
    EXPECT_FLOAT_EQ(derivation.current().particles[0].value[shared::kParticleAge], 1.0f);
}

TEST(Growth, ALeafGrowsOverTheTicksOfOneDeriveTime) {
    Grown g = grown(scene("Default { GrowRate = 0.5; GrowTime = 3.0; }", "Default { GrowRate = 0.1; GrowTime = 3.0; }",
                          "w = A(0);\nA(0) -> S(0)L(0);\n"),
                    1);
    cpu::SteppedDerivation derivation(g.species.species, options(1));
    grow::TickSettings ts{&g.tables, 1, 0.5f, 0, 1};
    EXPECT_EQ(leafSize(g, derivation, ts), -1.0f); // no leaf yet
    ASSERT_EQ(derivation.advance({1}), 1u);
    std::vector<float> sizes;
    for (uint32_t tick = 0; tick < 6; ++tick) { // one DeriveTime
        ts.tick = tick;
        grow::tickCpu(ts, derivation.current());
        sizes.push_back(leafSize(g, derivation, ts));
    }
    for (size_t k = 1; k < sizes.size(); ++k)
        EXPECT_GT(sizes[k], sizes[k - 1]) << "tick " << k;
    EXPECT_GT(sizes.front(), 0.0f);
    // Unfolded after one DeriveTime, and grown by GrowRate x GrowTime.
    EXPECT_NEAR(sizes.back(), shared::kLeafModelSize * (1.0f + 0.1f * 3.0f), 1e-5f);
}

TEST(Growth, RandomRangesAreDrawnPerPlantAndPerParticle) {
    Grown g = grown(
        scene("Default { GrowRate = rand(0.1, 1.0); GrowTime = 3.0; }", "", "w = S(0);\nS(0) -> S(0)[S(0)];\n"), 2);
    cpu::SteppedDerivation derivation(g.species.species, options(2));
    grow::TickSettings ts{&g.tables, 1, 1.0f, 0, 1};
    grow::tickCpu(ts, derivation.current());
    const stream::ModuleString& s = derivation.current();
    const float first = s.particles[s.plantStart[0]].value[shared::kParticleElongation];
    const float second = s.particles[s.plantStart[1]].value[shared::kParticleElongation];
    EXPECT_NE(first, second);
    for (float v : {first, second}) {
        EXPECT_GE(v, 0.1f);
        EXPECT_LE(v, 1.0f);
    }
    ASSERT_EQ(derivation.advance({1, 0}), 1u);
    ts.tick = 1;
    grow::tickCpu(ts, derivation.current());
    // Plant 0's stem and its branch's new stem grew at rates of their own.
    const stream::ModuleString& after = derivation.current();
    EXPECT_NE(after.particles[0].value[shared::kParticleElongation] - first,
              after.particles[2].value[shared::kParticleElongation]);
}

TEST(Growth, StagesFallBackToTheirOrgansDefaultThenToSimecosDefaults) {
    Grown g = grown(scene("Stage 2 { GrowRate = 2.0; }\nDefault { GrowTime = 4.0; }", "", "w = S(2);\n"), 1);
    const uint32_t* words = g.tables.species.data();
    const uint32_t stem = uint32_t(ir::EcoOrganKind::Stem);
    ASSERT_EQ(words[shared::kSpeciesRowCount + stem], 1u);
    const float* row = &g.tables.rows[words[shared::kSpeciesFirstRow + stem] * shared::kStageRowFloats];
    EXPECT_EQ(row[shared::kStageNumber], 2.0f);
    EXPECT_EQ(row[shared::propertyMin(shared::kGrowRate)], 2.0f);
    EXPECT_EQ(row[shared::propertyMin(shared::kGrowTime)], 4.0f);
    EXPECT_EQ(row[shared::propertyMin(shared::kBroadenRate)],
              grow::defaultProperty(ir::EcoOrganKind::Stem, shared::kBroadenRate));
    const float* fallback = &g.tables.rows[words[shared::kSpeciesDefaultRow + stem] * shared::kStageRowFloats];
    EXPECT_EQ(fallback[shared::propertyMin(shared::kGrowTime)], 4.0f);
    EXPECT_EQ(fallback[shared::propertyMin(shared::kGrowRate)],
              grow::defaultProperty(ir::EcoOrganKind::Stem, shared::kGrowRate));
}

} // namespace
} // namespace simeco::test
