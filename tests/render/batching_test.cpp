// A field goes on alike however it is cut into batches of plants, so that each device may take batches as large as
// its storage bindings hold: a plant draws from the random stream of its place in the field, stepping at every
// advance of the field (also where none of its batch derives), and a state saved in some batches goes on in others.
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "field/simulation.h"
#include "gpu_fixture.h"
#include "same_organs.h"
#include "turtle/interpretation.h"

namespace simeco::test {
namespace {

using BatchingTest = GpuTest;

// Herbs whose steps come at times of their own (a DeriveTime drawn per plant), each a coin toss between a leafy
// node and a bare one: a plant's string tells which draws it made.
field::SimulationOptions herbs(uint32_t plantsPerBatch, field::Backend backend) {
    field::SimulationOptions o;
    o.file = "herbs.eco";
    o.sceneText = R"(EcoSystem 1.0 "Herbs" {
        Plant "Herb" {
            DeriveTime = rand(1.0, 4.0);
            Stem { Default { GrowRate = 0.5; GrowTime = 2.0; BroadenRate = 0.05; } }
            Leaf { Default { GrowRate = 0.2; GrowTime = 2.0; } }
            Grow { w = A(0); A(0) -> prob(0.5) S(0)[rotr(0.8)L(0)]A(0) | S(0)A(0); }
        }
    })";
    o.plants = 8;
    o.plantsPerBatch = plantsPerBatch;
    o.seed = 5;
    o.backend = backend;
    return o;
}

// The first particle slot in which two strings' particles differ, or "": by their bytes, since a slot that holds a
// uint's bits (a particle's identity) may read as a NaN.
std::string particleDifference(const std::vector<shared::ParticleState>& a,
                               const std::vector<shared::ParticleState>& b) {
    if (a.size() != b.size()) return fmt::format("{} particles against {}", a.size(), b.size());
    for (size_t k = 0; k < a.size(); ++k)
        for (uint32_t slot = 0; slot < shared::kParticleStateFloats; ++slot)
            if (std::memcmp(&a[k].value[slot], &b[k].value[slot], sizeof(float)) != 0)
                return fmt::format("particle {} slot {}: {} against {}", k, slot, a[k].value[slot], b[k].value[slot]);
    return "";
}

void expectSamePlants(const field::SimulationState& a, const field::SimulationState& b) {
    EXPECT_EQ(a.ticks, b.ticks);
    EXPECT_EQ(a.nextStep, b.nextStep);
    EXPECT_EQ(a.plants.fieldStep, b.plants.fieldStep);
    EXPECT_EQ(a.plants.string.plantStart, b.plants.string.plantStart);
    EXPECT_EQ(a.plants.string.sym, b.plants.string.sym);
    EXPECT_EQ(a.plants.string.params, b.plants.string.params);
    EXPECT_EQ(particleDifference(a.plants.string.particles, b.plants.string.particles), "");
    EXPECT_EQ(a.plants.plants, b.plants.plants);
}

TEST_F(BatchingTest, APlantDrawsAlikeInAnyBatchesAlsoWhereNoneOfItsBatchDerives) {
    field::Simulation whole(herbs(0, field::Backend::Cpu), nullptr);
    field::Simulation single(herbs(1, field::Backend::Cpu), nullptr); // a batch for each plant
    field::Simulation device(herbs(1, field::Backend::Gpu), &context());
    ASSERT_EQ(whole.batches(), 1u);
    ASSERT_EQ(single.batches(), 8u);
    // Ticks where some plants derive and others do not: there, a batch of one plant derived nothing while the field
    // stepped on.
    int someDerived = 0;
    for (int tick = 0; tick < 16; ++tick) {
        const field::TickReport report = whole.tick();
        single.tick();
        device.tick();
        someDerived += report.derived > 0 && report.derived < 8 ? 1 : 0;
    }
    EXPECT_GE(someDerived, 4);
    EXPECT_EQ(single.plantModules(), whole.plantModules());
    expectSamePlants(whole.save(), single.save());
    EXPECT_EQ(device.plantModules(), whole.plantModules());
    EXPECT_EQ(device.save().plants.string.sym, whole.save().plants.string.sym);
    // The draws differ from plant to plant: the strings tell them apart.
    const field::SimulationState state = whole.save();
    const stream::ModuleString& string = state.plants.string;
    std::vector<std::vector<uint32_t>> plants;
    for (size_t p = 0; p < 8; ++p)
        plants.emplace_back(string.sym.begin() + string.plantStart[p], string.sym.begin() + string.plantStart[p + 1]);
    EXPECT_NE(plants[0], plants[1]);
    EXPECT_NE(plants[0], plants[7]);
}

// The garden of three species, drawn every tick as `simeco run` draws it.
field::SimulationOptions garden(uint32_t plantsPerBatch, field::Backend backend) {
    field::SimulationOptions o;
    o.file = std::string(SIMECO_SOURCE_DIR) + "/scenes/garden.eco";
    o.plants = 12;
    o.plantsPerBatch = plantsPerBatch;
    o.seed = 3;
    o.dt = 1.5f;
    o.backend = backend;
    return o;
}

void tickAndDraw(field::Simulation& sim, int ticks) {
    for (int tick = 0; tick < ticks; ++tick) {
        sim.tick();
        sim.interpretParts();
    }
}

TEST_F(BatchingTest, AFieldSavedInSomeBatchesGoesOnInOthersAsIfUninterrupted) {
    for (field::Backend backend : {field::Backend::Cpu, field::Backend::Gpu}) {
        SCOPED_TRACE(backend == field::Backend::Cpu ? "cpu" : "gpu");
        field::Simulation uninterrupted(garden(3, backend), &context()); // four batches
        field::Simulation saved(garden(3, backend), &context());
        tickAndDraw(uninterrupted, 12);
        tickAndDraw(saved, 6);
        field::Simulation resumed(garden(0, backend), &context()); // one batch
        ASSERT_EQ(resumed.batches(), 1u);
        resumed.resume(saved.save());
        tickAndDraw(resumed, 6);
        const field::SimulationState want = uninterrupted.save(), got = resumed.save();
        EXPECT_GT(got.plants.string.size(), saved.save().plants.string.size());
        // To the bit: every particle's light too, which the resumed field's first drawing leaves as it was saved.
        expectSamePlants(want, got);
        EXPECT_EQ(resumed.plantModules(), uninterrupted.plantModules());
        const turtle::Interpretation a = turtle::readBack(context(), uninterrupted.interpret(), 12);
        const turtle::Interpretation b = turtle::readBack(context(), resumed.interpret(), 12);
        EXPECT_EQ(organDifference(a, b), "");
    }
    // A state of other plants is refused.
    field::Simulation other(herbs(0, field::Backend::Cpu), nullptr);
    field::Simulation garden12(garden(0, field::Backend::Cpu), nullptr);
    EXPECT_THROW(garden12.resume(other.save()), std::invalid_argument);
}

} // namespace
} // namespace simeco::test
