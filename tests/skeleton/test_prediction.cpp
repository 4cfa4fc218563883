// The prediction grammar and the description's keywords: grown on past its skeleton, an inferred plant keeps the
// lengths and angles of its young growth; a description puts leaves where its phyllotaxy says.
#include <cmath>
#include <fstream>
#include <numbers>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "../unit/temporary_folder.h"
#include "plant_skeletons.h"
#include "skeleton/dressing.h"
#include "skeleton/eco_writer.h"
#include "skeleton/skeleton_check.h"
#include "skeleton/skeleton_statistics.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;
const fs::path kGrammars = fs::path(SIMECO_SOURCE_DIR) / "grammars";

class Prediction : public simeco::testing::TemporaryFolderTest {};

// The young half of a plant's levels, and a grown plant's levels beyond its skeleton's, as one distribution each.
skeleton::Distribution over(const std::vector<skeleton::LevelStatistics>& levels, int from, int to,
                            skeleton::Distribution skeleton::LevelStatistics::*what) {
    std::vector<double> means;
    double sum = 0.0, weights = 0.0;
    skeleton::Distribution d;
    for (const skeleton::LevelStatistics& l : levels)
        if (l.level >= from && l.level < to && (l.*what).count > 0) {
            sum += (l.*what).mean * double((l.*what).count);
            weights += double((l.*what).count);
        }
    d.count = size_t(weights);
    d.mean = weights > 0 ? sum / weights : 0.0;
    return d;
}

TEST_F(Prediction, GrownOnTheInferredPlantKeepsItsYoungGrowthsLengthsAndAngles) {
    skeleton::Plant plant = skeletonOfFile(kGrammars / "abop" / "fig2.8-ternary.l");
    skeleton::checkPlant(plant, "skeleton", 0);
    const skeleton::Regrowth growth = skeleton::regrowth(plant, skeleton::Dialect::SimEco);
    const skeleton::Prediction prediction = skeleton::predictionOf(plant, growth);
    ASSERT_GE(prediction.templates.size(), 2u);
    skeleton::EcoScriptOptions options;
    options.prediction = &prediction;
    std::ofstream(dir_ / "plant.eco") << skeleton::ecoScript(plant, growth, options);

    const int levels = growth.tree.levels;
    // Derived as many steps as it has levels, it is its skeleton; four steps more and its tips have grown on.
    EXPECT_TRUE(skeleton::matchSegments(plant, skeletonOfFile(dir_ / "plant.eco", levels)).same());
    skeleton::Plant grown = skeletonOfFile(dir_ / "plant.eco", levels + 4);
    skeleton::checkPlant(grown, "grown", 0);
    const auto before = skeleton::levelStatistics(growth.tree);
    const auto after = skeleton::levelStatistics(skeleton::internodeTree(grown));
    ASSERT_GT(after.size(), before.size()) << "the prediction added no level";

    const int young = levels / 2;
    const auto oldLength = over(before, young, levels, &skeleton::LevelStatistics::length);
    const auto newLength = over(after, levels, int(after.size()), &skeleton::LevelStatistics::length);
    const auto oldAngle = over(before, young, levels, &skeleton::LevelStatistics::angle);
    const auto newAngle = over(after, levels, int(after.size()), &skeleton::LevelStatistics::angle);
    ASSERT_GT(newLength.count, 10u);
    EXPECT_NEAR(newLength.mean, oldLength.mean, 0.5 * oldLength.mean);
    EXPECT_NEAR(newAngle.mean, oldAngle.mean, 15.0) << "degrees";
    std::printf("young growth: %zu internodes, length %.4g, angle %.1f; grown on: %zu internodes, length %.4g, "
                "angle %.1f\n",
                oldLength.count, oldLength.mean, oldAngle.mean, newLength.count, newLength.mean, newAngle.mean);
}

TEST(Description, EnglishAndChineseKeywordsChooseTheSameLook) {
    skeleton::PlantDescription english = skeleton::describePlant("opposite, ovate, shrub");
    skeleton::PlantDescription chinese = skeleton::describePlant("對生、卵形、灌木");
    EXPECT_EQ(english.phyllotaxy, skeleton::Phyllotaxy::Opposite);
    EXPECT_EQ(english.leafShape, "ovate");
    EXPECT_EQ(english.habit, skeleton::Habit::Shrub);
    EXPECT_EQ(chinese.phyllotaxy, english.phyllotaxy);
    EXPECT_EQ(chinese.leafShape, english.leafShape);
    EXPECT_EQ(chinese.habit, english.habit);
    EXPECT_EQ(skeleton::describePlant("互生").phyllotaxy, skeleton::Phyllotaxy::Alternate);
    EXPECT_EQ(skeleton::describePlant("輪生").phyllotaxy, skeleton::Phyllotaxy::Whorled);
    EXPECT_EQ(skeleton::describePlant("基生").phyllotaxy, skeleton::Phyllotaxy::Basal);
    EXPECT_EQ(skeleton::describePlant("叢生").phyllotaxy, skeleton::Phyllotaxy::Clustered);
    EXPECT_THROW(skeleton::describePlant("opposite, purple"), std::invalid_argument);
}

// A straight stem of four segments with a branch at its second point.
skeleton::Plant bareStem() {
    skeleton::Plant p;
    p.stems.push_back({0, -1, -1, {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}, {0, 3, 0}, {0, 4, 0}}, 0.0, {}});
    p.stems.push_back({1, 0, 2, {{0, 2, 0}, {1, 3, 0}}, 0.0, {}});
    return p;
}

TEST(Description, OppositeLeavesComeInPairsTurnedARightAngleFromPairToPair) {
    skeleton::Plant p = bareStem();
    skeleton::checkPlant(p, "stem", 0);
    std::string done = skeleton::dressPlant(p, skeleton::describePlant("opposite"));
    EXPECT_NE(done.find("opposite leaves"), std::string::npos) << done;
    // Five internode ends, two leaves each.
    ASSERT_EQ(p.organs.size(), 10u);
    auto across = [](const skeleton::Organ& o) {
        glm::dvec3 h = o.heading - glm::dvec3(0, 1, 0) * glm::dot(o.heading, glm::dvec3(0, 1, 0));
        return glm::normalize(h);
    };
    // The two leaves of the trunk's first node point opposite ways; the next node's pair is turned a right angle.
    EXPECT_NEAR(glm::dot(across(p.organs[0]), across(p.organs[1])), -1.0, 1e-9);
    EXPECT_NEAR(glm::dot(across(p.organs[0]), across(p.organs[2])), 0.0, 1e-9);
    // A bare skeleton gets widths that narrow from the base to the tips.
    EXPECT_GT(p.stems[0].widths.front(), p.stems[0].widths.back());
    EXPECT_GT(p.stems[0].widths.back(), 0.0);
}

TEST(Description, AlternateLeavesTurnByTheGoldenAngle) {
    skeleton::Plant p = bareStem();
    skeleton::checkPlant(p, "stem", 0);
    skeleton::dressPlant(p, skeleton::describePlant("alternate"));
    ASSERT_EQ(p.organs.size(), 5u);
    glm::dvec3 a = p.organs[0].heading, b = p.organs[1].heading;
    a.y = b.y = 0.0;
    const double turn = std::acos(glm::dot(glm::normalize(a), glm::normalize(b))) * 180.0 / std::numbers::pi;
    EXPECT_NEAR(turn, 137.50776405, 1e-6);
}

} // namespace
} // namespace simeco::test
