// simeco's extensions of the `.eco` script for fields (ir/eco_field.h, docs/SCENES.md): populations, obstacles,
// grammar plants, the sun, sky and ground; malformed ones fail at their line and column; and the points a
// population's plants stand on.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "field/ground_samples.h"
#include "grow/growing_species.h"
#include "lang/eco_parser.h"
#include "lang/load_grammar.h"

namespace simeco {
namespace {

// A scene with one herb plant and `items` in its EcoSystem block.
std::string withItems(const std::string& items) {
    return "EcoSystem 1.0 \"t\" {\n  Plant \"Herb\" { Grow { w = S(0); } }\n" + items + "}\n";
}

TEST(EcoField, PopulationsObstaclesLightAndGrammarPlantsParse) {
    const ir::EcoScene scene = lang::parseEcoText(
        withItems("  SunDirection = vector(-1.0, 2.0, 0.5);\n  SunIntensity = 0.8;\n  SkyLight = 1.5;\n"
                  "  GroundSize = 60.0;\n"
                  "  Plant \"Bush\" { Grammar = \"bush.l\"; DeriveTime = 4.0; }\n"
                  "  Population \"Meadow\" { Plant = \"Herb\"; Density = 0.5; Center = vector(1.0, 0.0, 2.0);\n"
                  "    Size = vector(10.0, 0.0, 6.0); Placement = jittered; Seed = 7; Variation = 0.2; }\n"
                  "  Population \"Hedge\" { Plant = \"Bush\"; Count = 12; Spacing = 1.5; }\n"
                  "  Wall \"Wall\" { From = vector(0.0, 0.0, 0.0); To = vector(0.0, 0.0, 4.0); Height = 2.0;\n"
                  "    Thickness = 0.5; Color = RGBA(0.5, 0.4, 0.3, 1.0); }\n"
                  "  Box \"Shed\" { Min = vector(1.0, 0.0, 1.0); Max = vector(3.0, 2.0, 5.0); }\n"),
        "field.eco");
    ASSERT_TRUE(scene.light.sunDirection && scene.light.sunIntensity && scene.light.skyLight &&
                scene.light.groundSize);
    EXPECT_EQ((*scene.light.sunDirection)[1], 2.0f);
    EXPECT_EQ(*scene.light.groundSize, 60.0f);
    ASSERT_EQ(scene.plants.size(), 2u);
    EXPECT_EQ(scene.plants[1].grammar, "bush.l");
    EXPECT_EQ(scene.plants[1].deriveTime.min, 4.0f);

    ASSERT_EQ(scene.populations.size(), 2u);
    const ir::EcoPopulation& meadow = scene.populations[0];
    EXPECT_EQ(meadow.plant, "Herb");
    EXPECT_EQ(meadow.density, 0.5f);
    EXPECT_FALSE(meadow.count);
    EXPECT_EQ(meadow.centerX, 1.0f);
    EXPECT_EQ(meadow.centerZ, 2.0f);
    EXPECT_EQ(meadow.width, 10.0f);
    EXPECT_EQ(meadow.depth, 6.0f);
    EXPECT_EQ(meadow.placement, ir::EcoPlacement::Jittered);
    EXPECT_EQ(meadow.seed, 7u);
    EXPECT_EQ(meadow.variation, 0.2f);
    EXPECT_EQ(scene.populations[1].count, 12u);
    EXPECT_EQ(scene.populations[1].spacing, 1.5f);
    EXPECT_EQ(scene.populations[1].placement, ir::EcoPlacement::Poisson);

    ASSERT_EQ(scene.obstacles.size(), 2u);
    // The wall runs along z from the origin: 4 long, 2 high, 0.5 thick, standing on the ground.
    const ir::EcoObstacle& wall = scene.obstacles[0];
    EXPECT_FLOAT_EQ(wall.halfSize[0], 2.0f);
    EXPECT_FLOAT_EQ(wall.halfSize[1], 1.0f);
    EXPECT_FLOAT_EQ(wall.halfSize[2], 0.25f);
    EXPECT_FLOAT_EQ(wall.center[1], 1.0f);
    EXPECT_FLOAT_EQ(wall.center[2], 2.0f);
    EXPECT_NEAR(std::fabs(wall.yaw), float(M_PI / 2), 1e-6f);
    const ir::EcoObstacle& shed = scene.obstacles[1];
    EXPECT_FLOAT_EQ(shed.center[0], 2.0f);
    EXPECT_FLOAT_EQ(shed.halfSize[2], 2.0f);
    EXPECT_EQ(shed.yaw, 0.0f);
}

TEST(EcoField, MalformedFieldItemsReportLineAndColumn) {
    struct Malformed {
        const char* what;
        std::string items;
        int line, col;
        const char* message;
    };
    const std::vector<Malformed> cases = {
        {"population of an unknown plant", "  Population \"P\" { Plant = \"Tree\"; Count = 3; }\n", 3, 28,
         "names Plant \"Tree\", which the scene does not define"},
        {"population without a count", "  Population \"P\" { Plant = \"Herb\"; }\n", 3, 3,
         "needs either a Count or a Density"},
        {"population with both", "  Population \"P\" { Plant = \"Herb\"; Count = 3; Density = 1.0; }\n", 3, 3,
         "needs either a Count or a Density"},
        {"fractional count", "  Population \"P\" { Plant = \"Herb\"; Count = 2.5; }\n", 3, 44, "whole number"},
        {"unknown placement", "  Population \"P\" { Plant = \"Herb\"; Count = 2; Placement = grid; }\n", 3, 59,
         "poisson or jittered"},
        {"variation of 1", "  Population \"P\" { Plant = \"Herb\"; Count = 2; Variation = 1.0; }\n", 3, 59,
         "fraction from 0 to below 1"},
        {"random seed", "  Population \"P\" { Plant = \"Herb\"; Count = 2; Seed = rand(1.0, 2.0); }\n", 3, 54,
         "a number, not a range"},
        {"flat region", "  Population \"P\" { Plant = \"Herb\"; Count = 2; Size = vector(4.0, 0.0, 0.0); }\n", 3, 54,
         "width and depth above 0"},
        {"unknown population item", "  Population \"P\" { Plant = \"Herb\"; Count = 2; Rows = 3; }\n", 3, 47,
         "unknown keyword 'Rows'"},
        {"wall of no length", "  Wall \"W\" { From = vector(1.0, 0.0, 1.0); To = vector(1.0, 0.0, 1.0); }\n", 3, 3,
         "from a point to the same point"},
        {"box inside out", "  Box \"B\" { Min = vector(1.0, 0.0, 1.0); Max = vector(2.0, 0.0, 2.0); }\n", 3, 3,
         "Max must be above Min"},
        {"box without Max", "  Box \"B\" { Min = vector(1.0, 0.0, 1.0); }\n", 3, 3, "needs Min and Max"},
        {"sun from nowhere", "  SunDirection = vector(0.0, 0.0, 0.0);\n", 3, 3, "must not be vector(0, 0, 0)"},
        {"ground of no size", "  GroundSize = 0.0;\n", 3, 16, "must be above 0"},
        {"a dark sun", "  SunIntensity = -1.0;\n", 3, 18, "must not be below 0"},
        {"grammar and organs", "  Plant \"B\" { Grammar = \"b.l\"; Stem { } }\n", 3, 41, "no organ or Grow blocks"},
    };
    for (const Malformed& m : cases) {
        SCOPED_TRACE(m.what);
        try {
            lang::parseEcoText(withItems(m.items), "bad.eco");
            ADD_FAILURE() << "parsed without error";
        } catch (const ir::InputError& e) {
            EXPECT_EQ(e.loc().line, m.line) << e.formatted();
            EXPECT_EQ(e.loc().col, m.col) << e.formatted();
            EXPECT_NE(std::string(e.what()).find(m.message), std::string::npos) << e.formatted();
        }
    }
}

TEST(EcoField, AGrammarPlantIsItsFilesGrammarWhereverTheSceneIsRead) {
    const std::filesystem::path folder = std::filesystem::temp_directory_path() / "simeco-grammar-plant-test";
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "bush.l") << "Lsystem: 1\nderivation length: 2\nAxiom: F(1)A\nA --> F(1)[+A]A\nendlsystem\n";
    std::ofstream(folder / "scene.eco") << withItems("  Plant \"Bush\" { Grammar = \"bush.l\"; }\n");
    std::ofstream(folder / "broken.eco") << withItems("  Plant \"Bush\" { Grammar = \"gone.l\"; }\n");
    // As `simeco derive` and `render` read it, and as `simeco run` grows it.
    const std::vector<ir::Grammar> species = lang::loadSpecies((folder / "scene.eco").string());
    const grow::GrowingSpecies growing = grow::loadGrowingSpecies((folder / "scene.eco").string());
    for (const ir::Grammar* bush : {&species.at(1), &growing.species.at(1)}) {
        EXPECT_EQ(bush->axiom.size(), 2u);
        EXPECT_EQ(bush->derivationLength, 2);
        EXPECT_TRUE(bush->productions.present);
    }
    EXPECT_FALSE(growing.growsOrgans(1));
    try {
        lang::loadSpecies((folder / "broken.eco").string());
        ADD_FAILURE() << "a missing grammar file was read";
    } catch (const ir::InputError& e) {
        EXPECT_EQ(e.loc().line, 3) << e.formatted();
        EXPECT_NE(std::string(e.what()).find("cannot open the grammar file"), std::string::npos) << e.formatted();
    }
    std::filesystem::remove_all(folder);
}

bool inside(const field::GroundRect& r, glm::vec2 p) {
    const glm::vec2 d = glm::abs(p - r.center);
    return d.x <= 0.5f * r.size.x && d.y <= 0.5f * r.size.y;
}

TEST(EcoField, PoissonDiskPointsKeepTheirDistanceAndCoverTheRegion) {
    const field::GroundRect rect{{5.0f, -3.0f}, {40.0f, 20.0f}};
    const std::vector<glm::vec2> points = field::poissonDiskPoints(rect, 300, 0.0f, 9, 1);
    ASSERT_EQ(points.size(), 300u);
    float closest = 1e9f;
    for (size_t i = 0; i < points.size(); ++i) {
        EXPECT_TRUE(inside(rect, points[i])) << i;
        for (size_t j = 0; j < i; ++j) closest = std::min(closest, glm::length(points[i] - points[j]));
    }
    EXPECT_GE(closest, 0.75f * std::sqrt(800.0f / 300.0f) - 1e-4f);
    // Spread over the whole region, not grown from one spot: every quarter holds some.
    for (int q = 0; q < 4; ++q) {
        const auto inQuarter = [&](glm::vec2 p) {
            return ((p.x > 5.0f) == bool(q & 1)) && ((p.y > -3.0f) == bool(q & 2));
        };
        EXPECT_GT(std::count_if(points.begin(), points.end(), inQuarter), 50) << q;
    }
    // The same seed and key give the same points; another key others.
    EXPECT_EQ(field::poissonDiskPoints(rect, 300, 0.0f, 9, 1), points);
    EXPECT_NE(field::poissonDiskPoints(rect, 300, 0.0f, 9, 2), points);
    // No room for 300 plants 5 apart: as many as fit.
    const std::vector<glm::vec2> sparse = field::poissonDiskPoints(rect, 300, 5.0f, 9, 1);
    EXPECT_LT(sparse.size(), 300u);
    EXPECT_GT(sparse.size(), 10u);
}

TEST(EcoField, JitteredPointsFillTheirCells) {
    const field::GroundRect rect{{0.0f, 0.0f}, {30.0f, 10.0f}};
    const std::vector<glm::vec2> points = field::jitteredPoints(rect, 50, 3, 4);
    ASSERT_EQ(points.size(), 50u);
    for (const glm::vec2& p : points) EXPECT_TRUE(inside(rect, p));
    // A grid as square as the region: about 12 columns of 4 rows, so no two plants share a cell.
    float closest = 1e9f;
    for (size_t i = 0; i < points.size(); ++i)
        for (size_t j = 0; j < i; ++j) closest = std::min(closest, glm::length(points[i] - points[j]));
    EXPECT_GT(closest, 0.5f);
    EXPECT_EQ(field::jitteredPoints(rect, 50, 3, 4), points);
}

} // namespace
} // namespace simeco
