// The growing field (field::Simulation) on the device against the CPU references: a garden in batches of plants,
// derived, grown, interpreted, merged and counted batch by batch, gives the organs and statistics the CPU gives;
// every plant draws from the random stream of its place in the field, however the field is batched.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <gtest/gtest.h>

#include "compute/shared/derive_layout.h"
#include "compute/shared/organ_layout.h"
#include "draw/renderer.h"
#include "field/simulation.h"
#include "ir/source_loc.h"
#include "same_organs.h"
#include "gpu_fixture.h"
#include "turtle/interpretation.h"
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

// One garden in four batches and in two, and on the CPU, each drawn after a tick: what the four batches and the CPU
// drew, and the submissions the drawings on the device took.
struct Drawings {
    turtle::Interpretation four, cpu;
    uint64_t fourSubmissions = 0, twoSubmissions = 0;
};
Drawings drawEach(const vk::Context& context, field::Simulation& four, field::Simulation& two,
                  field::Simulation& cpu) {
    Drawings d;
    uint64_t before = context.submissions();
    d.four = turtle::readBack(context, four.interpret(), four.plants());
    d.fourSubmissions = context.submissions() - before - 3; // less readBack's three
    before = context.submissions();
    two.interpretParts();
    d.twoSubmissions = context.submissions() - before;
    d.cpu = turtle::readBack(context, cpu.interpret(), cpu.plants());
    return d;
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
    ASSERT_EQ(organDifference(want, got), "");
    const float size = glm::length(want.bounds.max - want.bounds.min);
    // Every plant's organs are there, in plant order within each kind, across the batches.
    const std::vector<shared::PlantStatistics> a = gpu.statistics(), b = cpu.statistics();
    ASSERT_EQ(a.size(), 12u);
    for (uint32_t p = 0; p < 12; ++p) {
        EXPECT_EQ(a[p].organs, b[p].organs) << p;
        EXPECT_EQ(a[p].living, b[p].living) << p;
        EXPECT_GT(a[p].organs, 0u) << p;
        EXPECT_NEAR(a[p].leafArea, b[p].leafArea, 1e-4f * std::max(1.0f, b[p].leafArea)) << p;
        EXPECT_NEAR(a[p].height, b[p].height, 1e-4f * size) << p;
    }
    // Plants 0 and 3 are of one species, in two batches, each with the random stream of its place in the field.
    EXPECT_NE(gpu.plantModules()[0], gpu.plantModules()[3]);
    EXPECT_EQ(gpu.plantModules(), cpu.plantModules());
}

// A tick derives the due plants of every batch and grows every particle in one submission, which the host waits for
// once: as many submissions in four batches as in two, where no batch's step outgrew its streams. A step that did
// is derived again, waiting. The drawing after a step
// records every batch in one submission too, within rooms grown as the strings grew: as many submissions in four
// batches as in two where none outgrew its room. What is derived, grown and drawn is the CPU's all the same.
TEST_F(SimulationTest, EveryBatchDerivesInOneSubmissionAndIsDrawnInAnotherAsOnTheCpu) {
    // A step every tick (the garden's DeriveTime), so that the strings outgrow the streams' first room within ten.
    field::SimulationOptions inFour = garden(field::Backend::Gpu), inTwo = inFour, onCpu = garden(field::Backend::Cpu);
    inFour.dt = inTwo.dt = onCpu.dt = 3.0f;
    inTwo.plantsPerBatch = 6;
    field::Simulation four(inFour, &context()), two(inTwo, &context()), cpu(onCpu, &context());
    int fit = 0, rederived = 0, drawnInOne = 0;
    for (int tick = 0; tick < 10; ++tick) {
        uint64_t before = context().submissions();
        const field::TickReport a = four.tick();
        const uint64_t fourTick = context().submissions() - before;
        before = context().submissions();
        const field::TickReport b = two.tick();
        const uint64_t twoTick = context().submissions() - before;
        const field::TickReport c = cpu.tick();
        ASSERT_EQ(a.derived, c.derived) << tick;
        ASSERT_EQ(a.modules, c.modules) << tick;
        ASSERT_EQ(four.plantModules(), cpu.plantModules()) << tick;
        if (a.derived > 0 && (a.rederived > 0 || b.rederived > 0)) {
            ++rederived;
        } else {
            fit += a.derived > 0 ? 1 : 0;
            EXPECT_EQ(fourTick, 1u) << tick;
            EXPECT_EQ(twoTick, 1u) << tick;
        }

        const Drawings drawn = drawEach(context(), four, two, cpu);
        ASSERT_EQ(organDifference(drawn.cpu, drawn.four), "") << tick;
        const std::vector<shared::PlantStatistics> s = four.statistics(), t = cpu.statistics();
        for (uint32_t p = 0; p < 12; ++p)
            EXPECT_NEAR(s[p].leafArea, t[p].leafArea, 1e-4f * std::max(1.0f, t[p].leafArea)) << tick << " " << p;
        if (four.reinterpretedBatches() > 0 || two.reinterpretedBatches() > 0) continue;
        drawnInOne += a.derived > 0 ? 1 : 0;
        EXPECT_EQ(drawn.fourSubmissions, drawn.twoSubmissions) << tick;
    }
    EXPECT_GE(fit, 2);
    EXPECT_GE(rederived, 1);
    EXPECT_GE(drawnInOne, 2); // drawings after a step, every batch recorded
}

// A batch's streams start with room for its plants' first steps as the grown plants took them: 300 seedlings, whose
// first step would outgrow the seeds' room, derive and grow their first steps in one submission each, none again.
TEST_F(SimulationTest, AFieldsFirstStepsFitTheRoomItsGrownPlantsTookAndAreDrawnAsRecorded) {
    field::SimulationOptions o = garden(field::Backend::Gpu);
    o.plants = 300;
    o.plantsPerBatch = 0;
    o.dt = 3.0f; // a step every tick
    field::Simulation seedlings(o, &context());
    ASSERT_EQ(seedlings.batches(), 1u);
    for (int tick = 0; tick < 3; ++tick) {
        uint64_t before = context().submissions();
        const field::TickReport report = seedlings.tick();
        EXPECT_EQ(report.derived, 300u) << tick;
        EXPECT_EQ(report.rederived, 0u) << tick;
        EXPECT_EQ(context().submissions() - before, 1u) << tick;
        // The seedlings' first drawing too is recorded within a room, as every later one, which is one submission
        // (the first also uploads the turtle's tables, made as the field is first drawn).
        before = context().submissions();
        seedlings.interpretParts();
        EXPECT_EQ(seedlings.reinterpretedBatches(), 0u) << tick;
        if (tick > 0) {
            EXPECT_EQ(context().submissions() - before, 1u) << tick;
        }
    }
    EXPECT_GT(seedlings.modules(), 10u * 300u); // ten times the seeds
    // Steps no drawing took up: the room after the first is a guess, and guesses are not grown on guesses (their
    // levels would double at every step); the drawing after them interprets, reading between its passes.
    for (int tick = 0; tick < 3; ++tick) EXPECT_EQ(seedlings.tick().derived, 300u);
    seedlings.interpretParts();
    EXPECT_EQ(seedlings.reinterpretedBatches(), 1u);
}

// Between derivation steps every batch is drawn again in one submission, into organ buffers of its own, and the
// host reads back only the statistics after it: the tick's growth, the drawing and the light's propagation are that
// one submission, in four batches as in two, where every batch's string fit its room, and the batches' organs are
// merged in another. What it draws, and counts, is
// what the CPU draws, tick after tick; and the field is the same in four batches as in two, each plant drawing from
// the random stream of its place in the field.
TEST_F(SimulationTest, BetweenStepsEveryBatchIsDrawnInOneSubmissionAsOnTheCpu) {
    field::SimulationOptions inTwo = garden(field::Backend::Gpu);
    inTwo.plantsPerBatch = 6;
    field::Simulation four(garden(field::Backend::Gpu), &context()), two(inTwo, &context());
    field::Simulation cpu(garden(field::Backend::Cpu), &context());
    ASSERT_EQ(four.batches(), 4u);
    ASSERT_EQ(two.batches(), 2u);
    int between = 0, inOne = 0;
    for (int tick = 0; tick < 12; ++tick) {
        const uint64_t before = context().submissions();
        const field::TickReport report = four.tick();
        const uint64_t tickSubmissions = context().submissions() - before;
        two.tick();
        cpu.tick();
        const Drawings drawn = drawEach(context(), four, two, cpu);
        const turtle::Interpretation &got = drawn.four, &want = drawn.cpu;
        if (want.organs.empty()) { // the seeds, before their first organs
            EXPECT_TRUE(got.organs.empty()) << tick;
            continue;
        }
        ASSERT_EQ(organDifference(want, got), "") << tick;
        const std::vector<shared::PlantStatistics> a = four.statistics(), b = cpu.statistics(), c = two.statistics();
        for (uint32_t p = 0; p < 12; ++p) {
            EXPECT_EQ(a[p].organs, b[p].organs) << tick << " " << p;
            EXPECT_NEAR(a[p].leafArea, b[p].leafArea, 1e-4f * std::max(1.0f, b[p].leafArea)) << tick << " " << p;
            EXPECT_EQ(a[p].organs, c[p].organs) << tick << " " << p;
            EXPECT_EQ(a[p].leafArea, c[p].leafArea) << tick << " " << p;
            // The plants' tips placed in the field by the device, to its rounding.
            EXPECT_NEAR(a[p].height, c[p].height, 1e-6f * std::max(1.0f, c[p].height)) << tick << " " << p;
        }
        EXPECT_EQ(four.plantModules(), two.plantModules()) << tick;
        if (report.derived > 0) continue;
        ++between;
        EXPECT_EQ(tickSubmissions, 0u) << tick; // its growth waits for the drawing's submission
        EXPECT_EQ(drawn.fourSubmissions, drawn.twoSubmissions) << tick;
        if (four.reinterpretedBatches() > 0) continue;
        ++inOne;
        EXPECT_EQ(drawn.fourSubmissions, 2u) << tick; // and the merge of the batches' organs
    }
    EXPECT_GE(between, 3);
    EXPECT_GE(inOne, 3);
}

// A tick longer than the plants' DeriveTime (a time-lapse of few frames) derives every step due within it: two
// ticks of four DeriveTimes reach the string eight short ticks do, and one very long tick derives the whole
// grammar and stops there.
TEST_F(SimulationTest, ALongTickDerivesEveryStepDueWithinIt) {
    auto sedge = [](float dt) {
        field::SimulationOptions o;
        o.file = std::string(SIMECO_SOURCE_DIR) + "/grammars/cpfg/sedge.l";
        o.plants = 2;
        o.dt = dt;
        return o;
    };
    field::Simulation shortTicks(sedge(3.0f), &context()), longTicks(sedge(12.0f), &context());
    for (int tick = 0; tick < 8; ++tick) shortTicks.tick();
    for (int tick = 0; tick < 2; ++tick) EXPECT_EQ(longTicks.tick().derived, 2u);
    EXPECT_EQ(longTicks.plantModules(), shortTicks.plantModules());

    field::Simulation whole(sedge(1000.0f), &context()), stepByStep(sedge(3.0f), &context());
    whole.tick();
    for (int tick = 0; tick < 20; ++tick) stepByStep.tick(); // past the grammar's 16 steps
    EXPECT_EQ(whole.plantModules(), stepByStep.plantModules());
    EXPECT_GT(whole.plantModules()[0], 400u);
}

TEST_F(SimulationTest, AFieldInPartsDrawsAsInOnePart) {
    field::Simulation whole(garden(field::Backend::Gpu), &context());
    for (int tick = 0; tick < 30; ++tick) whole.tick();
    uint64_t organs = 0;
    const std::vector<const turtle::DeviceOrgans*> one = whole.interpretParts();
    for (const shared::PlantStatistics& s : whole.statistics()) organs += s.organs;
    ASSERT_EQ(one.size(), 1u);
    // Parts of about half the field's organs: its four batches in two or three parts.
    field::SimulationOptions options = garden(field::Backend::Gpu);
    options.maxPartBytes = organs * sizeof(shared::OrganInstance) / 2 + 1;
    field::Simulation split(options, &context());
    for (int tick = 0; tick < 30; ++tick) split.tick();
    const std::vector<const turtle::DeviceOrgans*> parts = split.interpretParts();
    ASSERT_GE(parts.size(), 2u);
    EXPECT_THROW(split.interpret(), ir::LimitError);
    uint64_t inParts = 0;
    for (const turtle::DeviceOrgans* part : parts) inParts += turtle::readBack(context(), *part, 12).organs.size();
    EXPECT_EQ(inParts, organs);

    draw::Renderer renderer(context());
    draw::RenderSettings settings;
    settings.width = 240;
    settings.height = 180;
    const turtle::Bounds drawn = turtle::readBack(context(), *one.front(), 12).bounds;
    const draw::Bounds framed{drawn.min, drawn.max};
    const draw::Frame a = renderer.render(field::organParts(one), framed, settings);
    const draw::Frame b = renderer.render(field::organParts(parts), framed, settings);
    size_t plantPixels = 0, differ = 0;
    for (size_t i = 0; i < a.plant.size(); ++i) {
        plantPixels += a.plant[i] != draw::Frame::kNoId;
        differ += a.plant[i] != b.plant[i] || std::fabs(a.rgba[4 * i] - b.rgba[4 * i]) > 1e-3f;
    }
    EXPECT_GT(plantPixels, 500u);
    EXPECT_LE(differ, plantPixels / 200); // the same field, drawn in another order of its draws
}

// Herbs of one SimEco plant and bushes of a cpfg grammar (scenes/shrub.l) in two populations, and a box.
field::SimulationOptions populated(field::Backend backend) {
    field::SimulationOptions o;
    o.file = std::string(SIMECO_SOURCE_DIR) + "/scenes/populated-test.eco"; // beside shrub.l
    o.sceneText = R"(EcoSystem 1.0 "Populated" {
        Plant "Herb" {
            Stem { Default { GrowRate = 0.5; GrowTime = 2.0; BroadenRate = 0.05; } }
            Leaf { Default { GrowRate = 0.2; GrowTime = 2.0; } }
            Grow { w = A(0); A(0) -> S(0)[rotr(0.8)L(0)]A(0); }
        }
        Plant "Bush" { Grammar = "shrub.l"; }
        Population "Herbs" { Plant = "Herb"; Count = 7; Center = vector(10.0, 0.0, 0.0); Size = vector(8.0, 0.0, 6.0);
                             Placement = jittered; Variation = 0.4; }
        Population "Bushes" { Plant = "Bush"; Count = 2; Center = vector(-10.0, 0.0, 0.0);
                              Size = vector(4.0, 0.0, 4.0); }
        Box "Shed" { Min = vector(0.0, 0.0, 5.0); Max = vector(2.0, 3.0, 7.0); }
    })";
    o.plantsPerBatch = 4; // four batches of the seven rounds of two species
    o.seed = 5;
    o.backend = backend;
    return o;
}

TEST_F(SimulationTest, PopulationsStandInTheirRegionsWithEmptySlotsAndObstacles) {
    field::Simulation gpu(populated(field::Backend::Gpu), &context());
    field::Simulation cpu(populated(field::Backend::Cpu), &context());
    // Seven rounds of the two species: the herbs in every round, the bushes in the first two.
    ASSERT_EQ(gpu.plants(), 14u);
    EXPECT_EQ(gpu.standingPlants(), 9u);
    EXPECT_GT(gpu.batches(), 1u);
    for (uint32_t p = 0; p < 14; ++p) {
        const bool herb = p % 2 == 0;
        EXPECT_EQ(gpu.present(p), herb || p < 4) << p;
        if (!gpu.present(p)) continue;
        const glm::vec3 at = turtle::plantOrigin(gpu.placements()[p]);
        const glm::vec2 center = herb ? glm::vec2(10, 0) : glm::vec2(-10, 0);
        const glm::vec2 half = herb ? glm::vec2(4, 3) : glm::vec2(2, 2);
        EXPECT_LE(std::fabs(at.x - center.x), half.x) << p;
        EXPECT_LE(std::fabs(at.z - center.y), half.y) << p;
    }
    for (int tick = 0; tick < 9; ++tick) {
        const field::TickReport a = gpu.tick(), b = cpu.tick();
        ASSERT_EQ(a.modules, b.modules) << tick;
    }
    const std::vector<uint64_t> modules = gpu.plantModules();
    EXPECT_EQ(modules, cpu.plantModules());
    for (uint32_t p = 0; p < 14; ++p) EXPECT_EQ(modules[p] > 0, gpu.present(p)) << p;

    // The shed is drawn after the plants, as twelve triangles of the plant past the field's.
    for (field::Simulation* s : {&gpu, &cpu}) {
        const turtle::Interpretation drawn = turtle::readBack(context(), s->interpret(), s->plants());
        uint32_t shed = 0;
        for (const shared::OrganInstance& o : drawn.organs) shed += o.plant == s->plants();
        EXPECT_EQ(shed, 12u);
        EXPECT_GE(drawn.bounds.max.y, 3.0f);
    }
    // The herbs grow each at its own vigour: their heights differ, within the variation's range.
    const std::vector<shared::PlantStatistics> stats = gpu.statistics();
    float lowest = 1e9f, highest = 0;
    for (uint32_t p = 0; p < 14; p += 2) {
        lowest = std::min(lowest, stats[p].height);
        highest = std::max(highest, stats[p].height);
        EXPECT_NEAR(stats[p].height, cpu.statistics()[p].height, 1e-4f * highest + 1e-5f) << p;
    }
    EXPECT_GT(highest, 1.05f * lowest);
    EXPECT_LT(highest, 1.4f / 0.6f * lowest + 1e-3f);
}

TEST_F(SimulationTest, ADensityFactorScalesEveryPopulationsPlantsAndNeedsPopulations) {
    field::SimulationOptions o = populated(field::Backend::Cpu);
    o.density = 2.0f; // 14 herbs, 4 bushes: fourteen rounds of the two species
    field::Simulation twice(o, &context());
    EXPECT_EQ(twice.plants(), 28u);
    EXPECT_EQ(twice.standingPlants(), 18u);
    for (uint32_t p = 0; p < twice.plants(); p += 2) {
        ASSERT_TRUE(twice.present(p)) << p;
        const glm::vec3 at = turtle::plantOrigin(twice.placements()[p]);
        EXPECT_LE(std::fabs(at.x - 10.0f), 4.0f) << p;
        EXPECT_LE(std::fabs(at.z), 3.0f) << p;
    }
    o.density = 0.5f; // 3.5 herbs round to 4, one bush
    field::Simulation half(o, &context());
    EXPECT_EQ(half.plants(), 8u);
    EXPECT_EQ(half.standingPlants(), 5u);

    field::SimulationOptions plain;
    plain.file = "plain.eco";
    plain.sceneText = R"(EcoSystem 1.0 "Plain" { Plant "Herb" { Grow { w = A(0); A(0) -> A(0); } } })";
    plain.backend = field::Backend::Cpu;
    plain.density = 2.0f;
    EXPECT_THROW(field::Simulation(plain, &context()), ir::InputError);
}

TEST_F(SimulationTest, LeavesOfAModelAreDrawnAndMeasuredWithIt) {
    // A diamond leaf model two units long and one wide (a quarter of its square of length), beside the scene.
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "simeco-model-leaf-test";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "diamond.obj") << "v 0 0 0\nv 1 -0.5 0\nv 2 0 0\nv 1 0.5 0\nf 1 2 3\nf 1 3 4\n";
    field::SimulationOptions options;
    options.file = (folder / "model.eco").string();
    options.sceneText = R"(EcoSystem 1.0 "Model" {
        Plant "Herb" {
            Stem { Default { GrowRate = 1.0; GrowTime = 1.0; BroadenRate = 0.1; } }
            Leaf { Default { Model = "diamond.obj"; } }
            Grow { w = S(0)[rotr(1.2)L(0)]; }
        }
    })";
    options.seed = 1;
    field::Simulation gpu(options, &context());
    options.backend = field::Backend::Cpu;
    field::Simulation cpu(options, &context());
    ASSERT_EQ(gpu.species().assets.models.size(), 1u);
    for (int tick = 0; tick < 4; ++tick) gpu.tick(), cpu.tick(); // past the leaf's first DeriveTime: unfolded
    const std::vector<const turtle::DeviceOrgans*> parts = gpu.interpretParts();
    cpu.interpret();
    // The leaf model's size is 3 units long: a quarter of 3 x 3.
    EXPECT_NEAR(gpu.statistics()[0].leafArea, 0.25f * 9.0f, 1e-4f);
    EXPECT_NEAR(cpu.statistics()[0].leafArea, 0.25f * 9.0f, 1e-4f);
    // Drawn with the model's triangles: the leaf shows.
    draw::Renderer renderer(context(), gpu.species().assets);
    draw::RenderSettings settings;
    settings.width = 160;
    settings.height = 120;
    settings.shadows = draw::Shadows::None;
    const turtle::Interpretation drawn = turtle::readBack(context(), *parts.front(), 1);
    ASSERT_EQ(drawn.count[shared::kOrganLeaf], 1u);
    const uint32_t leaf = drawn.organs[drawn.first[shared::kOrganLeaf]].module;
    EXPECT_EQ(drawn.organs[drawn.first[shared::kOrganLeaf]].shape, shared::kSurfaceLastShape + 1);
    const draw::Frame frame =
        renderer.render(field::organParts(parts), draw::Bounds{drawn.bounds.min, drawn.bounds.max}, settings);
    EXPECT_GT(std::count(frame.organ.begin(), frame.organ.end(), leaf), 100);
    std::filesystem::remove_all(folder);
}

// Two plants of one kind, one under a roof and one in the open: the roofed one's organs have less light and grow
// less, on the device as in the reference.
TEST_F(SimulationTest, APlantUnderARoofCatchesLessLightAndGrowsLessThanOneInTheOpen) {
    const std::string herb = R"(
            DeriveTime = 3.0;
            Stem { Default { GrowRate = 1.0; GrowTime = 3.0; BroadenRate = 0.05; } }
            Leaf { Default { GrowRate = 0.2; GrowTime = 3.0; } }
            Grow { w = S(0)[rotr(1.0)L(0)][rotr(1.0)rotu(3.1)L(0)]S(0)[rotr(1.0)rotu(1.6)L(0)]; }
        })";
    field::SimulationOptions options;
    options.file = "roof.eco";
    options.sceneText = "EcoSystem 1.0 \"Roof\" {\n SunDirection = vector(0.2, 1.0, 0.1);\n"
                        " Plant \"Roofed\" { Position = vector(-10.0, 0.0, 0.0);" + herb +
                        "\n Plant \"Open\" { Position = vector(10.0, 0.0, 0.0);" + herb +
                        "\n Box \"Roof\" { Min = vector(-16.0, 8.0, -6.0); Max = vector(-4.0, 9.0, 6.0); }\n}\n";
    options.seed = 3;
    field::Simulation gpu(options, &context());
    options.backend = field::Backend::Cpu;
    field::Simulation cpu(options, &context());
    std::vector<shared::PlantStatistics> a, b;
    for (int tick = 0; tick < 8; ++tick) {
        gpu.tick(), cpu.tick();
        gpu.interpretParts(), cpu.interpretParts();
        a = gpu.statistics(), b = cpu.statistics();
        ASSERT_EQ(a.size(), 2u);
        for (size_t p = 0; p < 2; ++p) {
            EXPECT_NEAR(a[p].light, b[p].light, 1e-4f * std::max(1.0f, b[p].light)) << tick << " " << p;
            EXPECT_NEAR(a[p].leafArea, b[p].leafArea, 1e-4f * std::max(1.0f, b[p].leafArea)) << tick << " " << p;
        }
    }
    // The derived string's particles have the light their drawn organs had, alike on both backends.
    const field::SimulationState sa = gpu.save(), sb = cpu.save();
    const std::vector<shared::ParticleState>& pa = sa.plants.string.particles;
    const std::vector<shared::ParticleState>& pb = sb.plants.string.particles;
    ASSERT_EQ(pa.size(), pb.size());
    // The open plant's two stems and three leaves have the open's light, the roofed plant's little or none.
    const stream::ModuleString& derived = sb.plants.string;
    const ir::Alphabet& alphabet = gpu.species().species[0].alphabet;
    const uint32_t stem = *alphabet.find("S"), leaf = *alphabet.find("L");
    int organs[2] = {0, 0};
    for (size_t k = 0; k < pa.size(); ++k) {
        const float light = pb[k].value[shared::kParticleLight];
        EXPECT_NEAR(pa[k].value[shared::kParticleLight], light, 1e-4f) << k;
        const uint32_t symbol = derived.sym[k] & shared::kSymbolMask;
        if (symbol != stem && symbol != leaf) continue;
        const bool open = k >= derived.plantStart[1];
        EXPECT_TRUE(open ? light > 0.8f : light < 0.2f) << k << ": " << light;
        ++organs[open ? 1 : 0];
    }
    EXPECT_EQ(organs[0], 5);
    EXPECT_EQ(organs[1], 5);
    // The roofed plant grew less, in leaf area and in height, for the light it lacked; its leaves caught less of
    // what there was (1.3 in the open, where nothing shades them).
    ASSERT_GT(a[1].leafArea, 1.0f);
    EXPECT_LT(a[0].leafArea, 0.85f * a[1].leafArea);
    EXPECT_LT(a[0].height, a[1].height);
    const float roofed = a[0].light / a[0].leafArea, open = a[1].light / a[1].leafArea;
    EXPECT_GT(open, 1.0f);
    EXPECT_LE(open, 1.3f + 1e-4f);
    EXPECT_LT(roofed, 0.6f * open);
}

// The same plant under longer days grows a larger leaf area (grow/environment.h), on either backend.
TEST_F(SimulationTest, LeafAreaRisesWithDayLight) {
    auto leafArea = [&](float hours, field::Backend backend) {
        field::SimulationOptions options;
        options.file = "days.eco";
        options.sceneText = fmt::format(R"(EcoSystem 1.0 "Days" {{
            DayLight = {};
            Plant "Herb" {{
                DeriveTime = 3.0;
                Stem {{ Default {{ GrowRate = 1.0; GrowTime = 3.0; BroadenRate = 0.05; }} }}
                Leaf {{ Default {{ GrowRate = 0.2; GrowTime = 3.0; }} }}
                Grow {{ w = S(0)[rotr(1.0)L(0)][rotr(1.0)rotu(3.1)L(0)]S(0); }}
            }}
        }})", hours);
        options.backend = backend;
        field::Simulation simulation(options, &context());
        for (int tick = 0; tick < 6; ++tick) simulation.tick();
        simulation.interpretParts();
        return simulation.statistics().at(0).leafArea;
    };
    for (field::Backend backend : {field::Backend::Gpu, field::Backend::Cpu}) {
        const float shortDays = leafArea(6.0f, backend), thesisDays = leafArea(12.0f, backend);
        EXPECT_LT(shortDays, thesisDays);
        EXPECT_LT(thesisDays, leafArea(18.0f, backend));
    }
}

// A 24-bit Windows bitmap of 2 x 2 pixels, its left column red and its right column blue, stored bottom-up.
void writeRedBlueBitmap(const std::filesystem::path& path) {
    std::vector<uint8_t> b(54 + 2 * 8, 0);
    auto put = [&](size_t at, uint32_t v, size_t bytes) {
        for (size_t k = 0; k < bytes; ++k) b[at + k] = uint8_t(v >> (8 * k));
    };
    b[0] = 'B', b[1] = 'M';
    put(2, uint32_t(b.size()), 4), put(10, 54, 4), put(14, 40, 4), put(18, 2, 4), put(22, 2, 4), put(26, 1, 2);
    put(28, 24, 2);
    for (size_t row = 0; row < 2; ++row) {
        const size_t at = 54 + 8 * row;
        b[at + 2] = 255; // red: blue, green, red
        b[at + 3] = 255; // blue
    }
    std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(b.data()), std::streamsize(b.size()));
}

TEST_F(SimulationTest, ATexturedStagesOrgansShowItsTexture) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "simeco-texture-test";
    std::filesystem::create_directories(folder);
    writeRedBlueBitmap(folder / "red-blue.bmp");
    field::SimulationOptions options;
    options.file = (folder / "texture.eco").string();
    // Stage 0's leaf is textured, stage 1's names a texture that is not there and keeps its colour.
    options.sceneText = R"(EcoSystem 1.0 "Texture" {
        Plant "Herb" {
            Stem { Default { GrowRate = 1.0; GrowTime = 1.0; BroadenRate = 0.1; } }
            Leaf {
                Stage 0 { Texture = "red-blue.bmp"; }
                Stage 1 { Texture = "missing.png"; Color = RGBA(0.2, 0.6, 0.2, 1.0); }
            }
            Grow { w = S(0)[rotr(1.2)L(0)][rotr(-1.2)L(1)]; }
        }
    })";
    field::Simulation gpu(options, &context());
    ASSERT_EQ(gpu.species().assets.textures.size(), 1u);
    for (int tick = 0; tick < 4; ++tick) gpu.tick();
    const std::vector<const turtle::DeviceOrgans*> parts = gpu.interpretParts();
    const turtle::Interpretation drawn = turtle::readBack(context(), *parts.front(), 1);
    ASSERT_EQ(drawn.count[shared::kOrganLeaf], 2u);
    const shared::OrganInstance& textured = drawn.organs[drawn.first[shared::kOrganLeaf]];
    const shared::OrganInstance& plain = drawn.organs[drawn.first[shared::kOrganLeaf] + 1];
    EXPECT_EQ(textured.color.w, shared::kColorFirstTexture);
    EXPECT_EQ(plain.color.w, shared::kColorUntextured);

    draw::Renderer renderer(context(), gpu.species().assets);
    draw::RenderSettings settings;
    settings.width = 200;
    settings.height = 150;
    settings.shadows = draw::Shadows::None;
    const draw::Frame frame =
        renderer.render(field::organParts(parts), draw::Bounds{drawn.bounds.min, drawn.bounds.max}, settings);
    // The textured leaf shows the red and the blue halves of its texture; the plain one neither.
    auto count = [&](uint32_t module, auto hue) {
        int n = 0;
        for (size_t i = 0; i < frame.organ.size(); ++i) {
            const float r = frame.rgba[4 * i], g = frame.rgba[4 * i + 1], bl = frame.rgba[4 * i + 2];
            n += frame.organ[i] == module && hue(r, g, bl) ? 1 : 0;
        }
        return n;
    };
    auto red = [](float r, float g, float b) { return r > 3 * g && r > 3 * b; };
    auto blue = [](float r, float g, float b) { return b > 3 * g && b > 3 * r; };
    EXPECT_GT(count(textured.module, red), 20);
    EXPECT_GT(count(textured.module, blue), 20);
    EXPECT_EQ(count(plain.module, red) + count(plain.module, blue), 0);
    EXPECT_GT(std::count(frame.organ.begin(), frame.organ.end(), plain.module), 20);
    std::filesystem::remove_all(folder);
}

} // namespace
} // namespace simeco::test
