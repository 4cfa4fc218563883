// The growing field (field::Simulation) on the device against the CPU references: a garden in batches of plants,
// derived, grown, interpreted, merged and counted batch by batch, gives the organs and statistics the CPU gives;
// batches have random streams of their own.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "field/simulation.h"
#include "gpu_fixture.h"
#include "turtle/turtle_gpu.h"

namespace simeco::test {
namespace {

using SimulationTest = GpuTest;

field::SimulationOptions garden(field::Backend backend) {
    field::SimulationOptions o;
    o.file = std::string(SIMECO_SOURCE_DIR) + "/scenes/garden.eco";
    o.plants = 12;
    o.plantsPerBatch = 3; // four batches
    o.seed = 3;
    o.dt = 1.0f;
    o.backend = backend;
    return o;
}

TEST_F(SimulationTest, AFieldInBatchesGrowsOnTheDeviceAsOnTheCpu) {
    field::Simulation gpu(garden(field::Backend::Gpu), &context());
    field::Simulation cpu(garden(field::Backend::Cpu), &context());
    ASSERT_EQ(gpu.batches(), 4u);
    for (int tick = 0; tick < 14; ++tick) {
        const field::TickReport a = gpu.tick(), b = cpu.tick();
        ASSERT_EQ(a.modules, b.modules) << tick;
        ASSERT_EQ(a.derived, b.derived) << tick;
    }
    const turtle::Interpretation want = turtle::readBack(context(), cpu.interpret(), cpu.plants());
    const turtle::Interpretation got = turtle::readBack(context(), gpu.interpret(), gpu.plants());
    ASSERT_EQ(got.count, want.count);
    ASSERT_EQ(got.first, want.first);
    float size = 0;
    for (int axis = 0; axis < 3; ++axis)
        size = std::max(size, want.bounds.max[axis] - want.bounds.min[axis]);
    ASSERT_GT(size, 0.0f);
    for (size_t i = 0; i < want.organs.size(); ++i) {
        const shared::OrganInstance &w = want.organs[i], &g = got.organs[i];
        ASSERT_EQ(g.plant, w.plant) << i;
        ASSERT_EQ(g.module, w.module) << i;
        ASSERT_EQ(g.kind, w.kind) << i;
        ASSERT_NEAR(g.position.x, w.position.x, 1e-4f * size) << i;
        ASSERT_NEAR(g.position.y, w.position.y, 1e-4f * size) << i;
        ASSERT_NEAR(g.position.z, w.position.z, 1e-4f * size) << i;
        ASSERT_NEAR(g.position.w, w.position.w, 1e-4f * size) << i;
    }
    // Every plant's organs are there, in plant order within each kind, across the batches.
    const std::vector<shared::PlantStatistics> a = gpu.statistics(), b = cpu.statistics();
    ASSERT_EQ(a.size(), 12u);
    for (uint32_t p = 0; p < 12; ++p) {
        EXPECT_EQ(a[p].organs, b[p].organs) << p;
        EXPECT_GT(a[p].organs, 0u) << p;
        EXPECT_NEAR(a[p].leafArea, b[p].leafArea, 1e-4f * std::max(1.0f, b[p].leafArea)) << p;
        EXPECT_NEAR(a[p].height, b[p].height, 1e-4f * size) << p;
    }
    // Plants 0 and 3 are of one species, in two batches with random streams of their own.
    EXPECT_NE(gpu.plantModules()[0], gpu.plantModules()[3]);
    EXPECT_EQ(gpu.plantModules(), cpu.plantModules());
}

} // namespace
} // namespace simeco::test
