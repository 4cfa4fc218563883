// Plants that compete for light and space (field::Simulation with its light grid), on the device against the CPU
// reference: shoots turn toward the light, away from an obstacle's shade; a dense stand sheds its shaded lower
// branches while an open-grown plant keeps them; a plant among taller neighbours catches less light than one alone;
// a shoot does not grow into a wall; rules on the light choose what grows.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "field/simulation.h"
#include "gpu_fixture.h"
#include "same_organs.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_gpu.h"

namespace simeco::test {
namespace {

using CompetitionTest = GpuTest;

// A herb of one shoot: a node each DeriveTime, each with a leaf on alternate sides; its stems turn toward the light.
std::string shoot(float phototropism) {
    return fmt::format(R"(
            DeriveTime = 2.0;
            Stem {{ Default {{ GrowRate = 0.5; GrowTime = 2.0; BroadenRate = 0.02; Phototropism = {}; }} }}
            Leaf {{ Default {{ GrowRate = 0.5; GrowTime = 2.0; }} }}
            Grow {{ w = A(0); A(0) -> S(0)[rotr(1.0)L(0)]rotu(3.1416)A(0); }}
        }})",
                       phototropism);
}

field::SimulationOptions scene(const std::string& body, field::Backend backend) {
    field::SimulationOptions options;
    options.file = "competition.eco";
    options.sceneText = "EcoSystem 1.0 \"Competition\" {\n" + body + "}\n";
    options.seed = 5;
    options.dt = 1.0f;
    options.backend = backend;
    return options;
}

// What a plant's drawn stems show: how far their tips lean along x from its base, on average, and its top.
struct Lean {
    float x = 0.0f;
    float top = 0.0f;
    int stems = 0;
};

std::vector<Lean> leans(const turtle::Interpretation& drawn, const std::vector<shared::PlantPlacement>& placements) {
    std::vector<Lean> lean(placements.size());
    for (uint32_t k = 0; k < drawn.count[shared::kOrganStem]; ++k) {
        const shared::OrganInstance& o = drawn.organs[drawn.first[shared::kOrganStem] + k];
        if (o.position.w <= 0.0f || o.plant >= lean.size()) continue;
        const float tipX = o.position.x + o.position.w * o.heading.x, tipY = o.position.y + o.position.w * o.heading.y;
        Lean& l = lean[o.plant];
        l.x += tipX - placements[o.plant].x.w;
        l.top = std::max(l.top, tipY);
        ++l.stems;
    }
    for (Lean& l : lean)
        if (l.stems > 0) l.x /= float(l.stems);
    return lean;
}

// A change of both fields before a tick (a viewer's panel acting on the running field).
using DuringGrowth = std::function<void(field::Simulation& field, int tick)>;

// Grows the scene on both backends for `ticks`, checks that they draw alike, and returns the device's drawing.
turtle::Interpretation grownAlike(const vk::Context& context, const std::string& body, int ticks,
                                  std::vector<shared::PlantStatistics>* statistics = nullptr,
                                  const DuringGrowth& during = {}) {
    field::Simulation gpu(scene(body, field::Backend::Gpu), &context);
    field::Simulation cpu(scene(body, field::Backend::Cpu), &context);
    for (int tick = 0; tick < ticks; ++tick) {
        if (during) during(gpu, tick), during(cpu, tick);
        gpu.tick(), cpu.tick();
        gpu.interpretParts(), cpu.interpretParts();
    }
    const turtle::Interpretation want = turtle::readBack(context, cpu.interpret(), cpu.plants());
    const turtle::Interpretation got = turtle::readBack(context, gpu.interpret(), gpu.plants());
    EXPECT_EQ(organDifference(want, got), "");
    if (statistics) *statistics = gpu.statistics();
    return got;
}

TEST_F(CompetitionTest, ShootsTurnTowardTheSunWhereverItIs) {
    const std::string plants = " Plant \"Turning\" { Position = vector(0.0, 0.0, 0.0);" + shoot(0.3) +
                               "\n Plant \"Straight\" { Position = vector(0.0, 0.0, 8.0);" + shoot(0.0) + "\n";
    float lean[2][2] = {};
    for (int side = 0; side < 2; ++side) {
        const float x = side == 0 ? 1.0f : -1.0f;
        const std::string sun = fmt::format(" SunDirection = vector({}, 0.8, 0.0);\n", x);
        field::Simulation probe(scene(sun + plants, field::Backend::Cpu), &context());
        const turtle::Interpretation drawn = grownAlike(context(), sun + plants, 12);
        const std::vector<Lean> l = leans(drawn, probe.placements());
        ASSERT_GE(l[0].stems, 5);
        ASSERT_EQ(l[0].stems, l[1].stems);
        lean[side][0] = l[0].x, lean[side][1] = l[1].x;
    }
    // The turning shoot leans toward the sun, east then west; the one without phototropism stands as it grew.
    EXPECT_GT(lean[0][0], 0.3f);
    EXPECT_LT(lean[1][0], -0.3f);
    EXPECT_NEAR(lean[0][0], -lean[1][0], 0.05f * lean[0][0]);
    EXPECT_LT(std::abs(lean[0][1]), 0.02f);
    EXPECT_LT(std::abs(lean[1][1]), 0.02f);
}

TEST_F(CompetitionTest, MovingTheSunWhileAFieldGrowsTurnsItsShootsTowardTheNewSun) {
    const std::string body = " SunDirection = vector(1.0, 0.8, 0.0);\n Plant \"Turning\" { Position = "
                             "vector(0.0, 0.0, 0.0);" + shoot(0.3) + "\n";
    field::Simulation probe(scene(body, field::Backend::Cpu), &context());
    const float east = leans(grownAlike(context(), body, 12), probe.placements())[0].x;
    // The same field with the sun moved to the west after four ticks, as a viewer's slider moves it.
    const DuringGrowth sunToTheWest = [](field::Simulation& f, int tick) {
        if (tick != 4) return;
        field::LiveEnvironment e = f.environment();
        ASSERT_TRUE(e.light.sunDirection);
        EXPECT_FLOAT_EQ((*e.light.sunDirection)[0], 1.0f); // the scene's sun, until it moves
        e.light.sunDirection = std::array<float, 3>{-1.0f, 0.8f, 0.0f};
        f.setEnvironment(e);
    };
    const float moved = leans(grownAlike(context(), body, 12, nullptr, sunToTheWest), probe.placements())[0].x;
    EXPECT_GT(east, 0.3f);
    EXPECT_LT(moved, 0.0f); // the stems grown since lean west, more of them than before
}

TEST_F(CompetitionTest, ASpeciesFactorsAndTheClimateSetWhileItGrowsActOnBothBackends) {
    const std::string body = " SunDirection = vector(0.3, 1.0, 0.2);\n Plant \"A\" { Position = "
                             "vector(0.0, 0.0, 0.0);" + shoot(0.0) + "\n Plant \"B\" { Position = "
                             "vector(6.0, 0.0, 0.0);" + shoot(0.0) + "\n";
    std::vector<shared::PlantStatistics> before, after;
    grownAlike(context(), body, 10, &before);
    // From the second tick on, species B grows at half its rate, and the days are short for both.
    const DuringGrowth slower = [](field::Simulation& f, int tick) {
        if (tick != 1) return;
        field::LiveEnvironment e = f.environment();
        ASSERT_EQ(e.species.size(), 2u);
        e.species[1].growRate = 0.5f;
        e.dayLight = 6.0f;
        f.setEnvironment(e);
    };
    grownAlike(context(), body, 10, &after, slower);
    ASSERT_EQ(before.size(), 2u);
    ASSERT_EQ(after.size(), 2u);
    EXPECT_FLOAT_EQ(before[0].height, before[1].height);
    // Short days slow both; B's own factor slows it further.
    EXPECT_LT(after[0].height, 0.95f * before[0].height);
    EXPECT_LT(after[1].height, 0.8f * after[0].height);
    EXPECT_LT(after[1].leafArea, after[0].leafArea);
}

TEST_F(CompetitionTest, AShootBesideAWallTurnsAwayFromItsShadeAndGrowsLess) {
    // The sun low in the east behind a tall wall; the sky's light still comes over the west.
    const std::string body = " SunDirection = vector(1.0, 0.5, 0.0);\n"
                             " Plant \"Walled\" { Position = vector(0.0, 0.0, 0.0);" + shoot(0.3) +
                             "\n Plant \"Open\" { Position = vector(0.0, 0.0, 30.0);" + shoot(0.3) +
                             "\n Wall \"Wall\" { From = vector(7.0, 0.0, -10.0); To = vector(7.0, 0.0, 10.0);"
                             " Height = 14.0; Thickness = 1.0; }\n";
    std::vector<shared::PlantStatistics> statistics;
    field::Simulation probe(scene(body, field::Backend::Cpu), &context());
    const turtle::Interpretation drawn = grownAlike(context(), body, 12, &statistics);
    const std::vector<Lean> l = leans(drawn, probe.placements());
    ASSERT_GE(l[1].stems, 5);
    EXPECT_GT(l[1].x, 0.3f);  // toward the sun in the open
    EXPECT_LT(l[0].x, -0.1f); // away from the wall's shade
    ASSERT_EQ(statistics.size(), 2u);
    EXPECT_LT(statistics[0].light, 0.7f * statistics[1].light);
    EXPECT_LT(statistics[0].leafArea, 0.8f * statistics[1].leafArea);
    EXPECT_LT(statistics[0].height, statistics[1].height);
}

// A small tree: a trunk of internodes (stage 0), each node a side branch of two internodes (stage 1) with leaves;
// the side branches and the leaves are shed after `shadeTime` seconds in deep shade, the trunk lives on.
std::string tree(float shadeTime) {
    return fmt::format(R"(
            DeriveTime = 2.0;
            Stem {{
                Stage 0 {{ GrowRate = 0.8; GrowTime = 2.0; BroadenRate = 0.03; }}
                Stage 1 {{ GrowRate = 0.5; GrowTime = 2.0; BroadenRate = 0.02; ShadeTime = {0}; }}
            }}
            Leaf {{ Default {{ GrowRate = 0.1; GrowTime = 2.0; ShadeTime = {0}; }} }}
            Grow {{
                w = A(0);
                A(0) -> S(0)[rotr(1.2)A(1)]rotu(2.4)A(0);
                A(1) -> S(1)[rotr(0.8)L(0)][rotr(0.8)rotu(3.1416)L(0)]A(2);
                A(2) -> S(1)[rotr(0.8)L(0)][rotr(0.8)rotu(3.1416)L(0)];
            }}
        }})",
                       shadeTime);
}

// Per plant: its drawn leaves, and the height of its lowest one.
struct Leaves {
    int count = 0;
    float lowest = 1e30f;
};

std::vector<Leaves> leavesOf(const turtle::Interpretation& drawn, size_t plants) {
    std::vector<Leaves> leaves(plants);
    for (uint32_t k = 0; k < drawn.count[shared::kOrganLeaf]; ++k) {
        const shared::OrganInstance& o = drawn.organs[drawn.first[shared::kOrganLeaf] + k];
        if (o.position.w <= 0.0f || o.plant >= plants) continue;
        ++leaves[o.plant].count;
        leaves[o.plant].lowest = std::min(leaves[o.plant].lowest, o.position.y);
    }
    return leaves;
}

TEST_F(CompetitionTest, ADenseStandShedsItsShadedLowerBranchesWhereAnOpenTreeKeepsThem) {
    std::string body = " SunDirection = vector(0.2, 1.0, 0.1);\n";
    // Plant 0 grows in the open; plants 1 to 9 stand a little apart in a square, plant 5 in its middle.
    body += " Plant \"Open\" { Position = vector(-12.0, 0.0, 0.0);" + tree(4.0f) + "\n";
    for (int k = 0; k < 9; ++k)
        body += fmt::format(" Plant \"Stand {}\" {{ Position = vector({}, 0.0, {});", k, 2.5f * float(k % 3),
                            2.5f * float(k / 3)) +
                tree(4.0f) + "\n";
    std::vector<shared::PlantStatistics> statistics;
    const turtle::Interpretation drawn = grownAlike(context(), body, 20, &statistics);
    const std::vector<Leaves> leaves = leavesOf(drawn, 10);
    ASSERT_EQ(statistics.size(), 10u);
    // The open tree keeps its lowest branch's leaves; the stand's middle tree has shed its lower ones.
    ASSERT_GT(leaves[0].count, 8);
    ASSERT_GT(leaves[5].count, 0);
    EXPECT_LT(leaves[5].count, leaves[0].count);
    EXPECT_GT(leaves[5].lowest, leaves[0].lowest + 1.0f);
    EXPECT_LT(statistics[5].living, statistics[0].living);
}

TEST_F(CompetitionTest, APlantAmongTallerNeighboursCatchesLessLightThanOneAlone) {
    const std::string small = R"(
            DeriveTime = 2.0;
            Stem { Default { GrowRate = 0.2; GrowTime = 2.0; BroadenRate = 0.02; } }
            Leaf { Default { GrowRate = 0.5; GrowTime = 2.0; } }
            Grow { w = A(0); A(0) -> S(0)[rotr(1.0)L(0)]rotu(3.1416)A(0); }
        })";
    std::string body = " SunDirection = vector(0.3, 1.0, 0.2);\n";
    body += " Plant \"Alone\" { Position = vector(-14.0, 0.0, 0.0);" + small + "\n";
    body += " Plant \"Crowded\" { Position = vector(0.0, 0.0, 0.0);" + small + "\n";
    for (int k = 0; k < 8; ++k) {
        const float a = 6.2832f * float(k) / 8.0f;
        body += fmt::format(" Plant \"Tall {}\" {{ Position = vector({}, 0.0, {});", k, 3.0f * std::cos(a),
                            3.0f * std::sin(a)) +
                shoot(0.0f) + "\n";
    }
    std::vector<shared::PlantStatistics> statistics;
    grownAlike(context(), body, 12, &statistics);
    ASSERT_EQ(statistics.size(), 10u);
    ASSERT_GT(statistics[0].leafArea, 0.0f);
    // Alike as they are, the crowded plant's leaves catch less light per area, and grow less, short of light and
    // of room.
    const float alone = statistics[0].light / statistics[0].leafArea;
    const float crowded = statistics[1].light / std::max(statistics[1].leafArea, 1e-6f);
    EXPECT_LT(crowded, 0.8f * alone);
    EXPECT_LT(statistics[1].leafArea, 0.8f * statistics[0].leafArea);
}

TEST_F(CompetitionTest, AShootStopsAtAWallWhereItsTwinInTheOpenGrowsOn) {
    // Two shoots leaning toward +x under a high sun, one with a wall across its way at x = 3.
    const std::string leaning = R"(
            Direction = vector(1.0, 0.35, 0.0);
            DeriveTime = 2.0;
            Stem { Default { GrowRate = 0.6; GrowTime = 2.0; BroadenRate = 0.02; } }
            Grow { w = A(0); A(0) -> S(0)A(0); }
        })";
    const std::string body = " SunDirection = vector(0.0, 1.0, 0.2);\n"
                             " Plant \"Walled\" { Position = vector(0.0, 0.0, 0.0);" + leaning +
                             "\n Plant \"Open\" { Position = vector(0.0, 0.0, 12.0);" + leaning +
                             "\n Wall \"Wall\" { From = vector(3.5, 0.0, -4.0); To = vector(3.5, 0.0, 4.0);"
                             " Height = 6.0; Thickness = 1.0; }\n";
    const turtle::Interpretation drawn = grownAlike(context(), body, 16);
    float reach[2] = {-1e30f, -1e30f};
    for (uint32_t k = 0; k < drawn.count[shared::kOrganStem]; ++k) {
        const shared::OrganInstance& o = drawn.organs[drawn.first[shared::kOrganStem] + k];
        if (o.plant < 2 && o.position.w > 0.0f)
            reach[o.plant] = std::max(reach[o.plant], o.position.x + o.position.w * o.heading.x);
    }
    // The open shoot reaches past where the wall stands; the walled one stops at its face (x = 3), within a voxel
    // of the light grid (about 0.7 here).
    EXPECT_GT(reach[1], 5.0f);
    EXPECT_LT(reach[0], 4.0f);
    EXPECT_GT(reach[0], 1.5f);
}

TEST_F(CompetitionTest, ARuleOnTheLightBranchesInTheSunAndNotInTheShade) {
    // Apices branch where their stem has more than half the open's light, and only grow on in the shade.
    const std::string herb = R"(
            DeriveTime = 2.0;
            Stem { Default { GrowRate = 0.5; GrowTime = 2.0; BroadenRate = 0.02; } }
            Leaf { Default { GrowRate = 0.2; GrowTime = 2.0; } }
            Grow {
                w = A(0);
                A(0) -> S(0)[rotr(1.0)L(0)]A(1);
                A(1) : light() > 0.5 -> S(0)[rotr(0.7)A(1)][rotr(0.7)rotu(3.1416)A(1)];
                A(1) : light() <= 0.5 -> S(0)[rotr(1.0)L(0)]rotu(2.4)A(1);
            }
        })";
    const std::string body = " SunDirection = vector(0.2, 1.0, 0.1);\n"
                             " Plant \"Roofed\" { Position = vector(-10.0, 0.0, 0.0);" + herb +
                             "\n Plant \"Open\" { Position = vector(10.0, 0.0, 0.0);" + herb +
                             "\n Box \"Roof\" { Min = vector(-16.0, 4.0, -6.0); Max = vector(-4.0, 5.0, 6.0); }\n";
    field::Simulation gpu(scene(body, field::Backend::Gpu), &context());
    field::Simulation cpu(scene(body, field::Backend::Cpu), &context());
    for (int tick = 0; tick < 9; ++tick) {
        gpu.tick(), cpu.tick();
        gpu.interpretParts(), cpu.interpretParts();
        ASSERT_EQ(gpu.plantModules(), cpu.plantModules()) << tick;
    }
    const turtle::Interpretation want = turtle::readBack(context(), cpu.interpret(), cpu.plants());
    const turtle::Interpretation got = turtle::readBack(context(), gpu.interpret(), gpu.plants());
    EXPECT_EQ(organDifference(want, got), "");
    // After four steps the open plant's apices have doubled three times; the roofed plant's one apex has grown on
    // with a leaf at each node.
    const field::SimulationState saved = cpu.save();
    const stream::ModuleString& derived = saved.plants.string;
    const ir::Alphabet& alphabet = gpu.species().species[0].alphabet;
    const uint32_t apex = *alphabet.find("A"), leaf = *alphabet.find("L");
    int apices[2] = {0, 0}, leaves[2] = {0, 0};
    for (size_t k = 0; k < derived.size(); ++k) {
        const int plant = k >= derived.plantStart[1] ? 1 : 0;
        apices[plant] += derived.sym[k] == apex;
        leaves[plant] += derived.sym[k] == leaf;
    }
    EXPECT_EQ(apices[0], 1);
    EXPECT_EQ(leaves[0], 4);
    EXPECT_EQ(apices[1], 8);
    EXPECT_EQ(leaves[1], 1);
}

TEST_F(CompetitionTest, TheLightGridAnswersCpfgEnvironmentQueries) {
    // A cpfg grammar whose plants ask for the light at two points (`?E(x)`, and `?E(x,dx,dy,dz)` with the direction
    // it comes from); one plant under a roof, one in the open.
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "simeco-queries-test";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "queries.l") << "Lsystem: 1\nderivation length: 3\n"
                                           "Axiom: F(1)?E(0)[+(60)F(1)?E(0,0,0,0)]\n"
                                           "F(x) --> F(x)\nendlsystem\n";
    const std::string body = " SunDirection = vector(0.2, 1.0, 0.1);\n"
                             " Plant \"Queries\" { Grammar = \"queries.l\"; DeriveTime = 2.0; }\n"
                             " Population \"Roofed\" { Plant = \"Queries\"; Count = 1;"
                             " Center = vector(-10.0, 0.0, 0.0); Size = vector(0.1, 0.0, 0.1); }\n"
                             " Population \"Open\" { Plant = \"Queries\"; Count = 1; Center = vector(10.0, 0.0, 0.0);"
                             " Size = vector(0.1, 0.0, 0.1); }\n"
                             " Box \"Roof\" { Min = vector(-14.0, 3.0, -4.0); Max = vector(-6.0, 4.0, 4.0); }\n";
    std::vector<field::SimulationState> states;
    uint32_t e = 0; // the symbol `E`
    for (field::Backend backend : {field::Backend::Gpu, field::Backend::Cpu}) {
        field::SimulationOptions options = scene(body, backend);
        options.file = (folder / "queries.eco").string();
        field::Simulation sim(options, &context());
        e = *sim.species().species[0].alphabet.find("E");
        for (int tick = 0; tick < 4; ++tick) {
            sim.tick();
            sim.interpretParts();
        }
        states.push_back(sim.save());
    }
    const stream::ModuleString& gpu = states[0].plants.string;
    const stream::ModuleString& cpu = states[1].plants.string;
    ASSERT_EQ(gpu.sym, cpu.sym);
    std::vector<std::vector<float>> answers[2];
    for (size_t k = 0; k < cpu.size(); ++k) {
        if (cpu.sym[k] != e) continue;
        const int plant = k >= cpu.plantStart[1] ? 1 : 0;
        std::vector<float> a(cpu.paramsOf(k), cpu.paramsOf(k) + cpu.paramCount[k]);
        for (size_t n = 0; n < a.size(); ++n) EXPECT_NEAR(gpu.paramsOf(k)[n], a[n], 1e-4f) << k << " " << n;
        answers[plant].push_back(a);
    }
    // Each plant's two queries, answered: the light as a share of the open's, and its direction (up, mostly).
    ASSERT_EQ(answers[0].size(), 2u);
    ASSERT_EQ(answers[1].size(), 2u);
    for (int plant = 0; plant < 2; ++plant)
        for (const std::vector<float>& a : answers[plant]) {
            if (plant == 0) {
                EXPECT_LT(a[0], 0.3f); // under the roof
            } else {
                EXPECT_GT(a[0], 0.9f); // in the open
            }
            if (a.size() == 4) {
                EXPECT_NEAR(a[1] * a[1] + a[2] * a[2] + a[3] * a[3], 1.0f, 1e-3f);
            }
        }
    EXPECT_GT(answers[1][1][2], 0.5f); // the open plant's light comes from above
}

} // namespace
} // namespace simeco::test
