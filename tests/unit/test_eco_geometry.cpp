// SimEco organs as the turtle draws them: stage sizes and colours from the script, and rotu spinning a branch
// about its parent's axis.
#include <gtest/gtest.h>

#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include "compute/shared/organ_layout.h"
#include "cpu/derive.h"
#include "lang/eco_geometry.h"
#include "lang/eco_parser.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"

namespace {

using namespace simeco;

turtle::Interpretation interpretEco(const std::string& text) {
    ir::EcoScene scene = lang::parseEcoText(text, "test.eco");
    ir::Grammar g = lang::compileEcoPlant(scene, 0);
    stream::DeriveOptions options;
    options.homomorphism = true;
    stream::DeriveResult r = cpu::deriveCpu(g, options);
    return turtle::interpretCpu(r.string, turtle::turtleCommands(g.alphabet), {turtle::turtleSettings(g, g.alphabet)});
}

glm::vec3 xyz(const shared::vec4& v) { return {v.x, v.y, v.z}; }

TEST(EcoGeometry, StagesSetLengthWidthColourAndLeafSize) {
    turtle::Interpretation r = interpretEco(R"(EcoSystem 1.0 "t" { Plant "p" {
        DerivationLength = 0;
        Stem { Stage 2 { GrowRate = 0.5; GrowTime = 4.0; BroadenRate = 0.05; Color = RGBA(1.0, 0.0, 0.0, 1.0); }
               Default { GrowRate = 0.25; GrowTime = 2.0; } }
        Leaf { Stage 0 { GrowRate = 0.1; GrowTime = 2.0; } Stage 1 { GrowRate = 0.2; GrowTime = 1.0; } }
        Grow { w = S(2) S(7) L(1); }
    } })");
    ASSERT_EQ(r.count[shared::kOrganStem], 2u);
    ASSERT_EQ(r.count[shared::kOrganLeaf], 1u);
    const shared::OrganInstance& described = r.organs[r.first[shared::kOrganStem]];
    const shared::OrganInstance& fallback = r.organs[r.first[shared::kOrganStem] + 1];
    EXPECT_FLOAT_EQ(described.position.w, 2.0f);       // 0.5 x 4
    EXPECT_FLOAT_EQ(described.heading.w, 0.5f * 0.2f); // width 0.05 x 4, radius half of it
    EXPECT_FLOAT_EQ(described.color.x, 1.0f);          // red, linear
    EXPECT_FLOAT_EQ(described.color.y, 0.0f);
    EXPECT_FLOAT_EQ(fallback.position.w, 0.5f);        // the Default stage: 0.25 x 2
    EXPECT_FLOAT_EQ(fallback.position.y, 2.0f);        // on top of the first
    const shared::OrganInstance& leaf = r.organs[r.first[shared::kOrganLeaf]];
    EXPECT_FLOAT_EQ(leaf.position.w, lang::kEcoLeafModelSize * (1.0f + 0.2f + 0.2f)); // stages 0 and 1 grown
    EXPECT_FLOAT_EQ(leaf.position.y, 2.5f);
}

// rotr tilts a branch away from its parent's axis and rotu spins it about that axis, in whichever order the
// script writes them: two branches tilted alike and spun by 0 and by b keep the same height and lie b apart
// around the parent.
TEST(EcoGeometry, RotuSpinsTheTiltedBranchAboutTheParentAxis) {
    turtle::Interpretation r = interpretEco(R"(EcoSystem 1.0 "t" { Plant "p" {
        DerivationLength = 0;
        Stem { Default { GrowRate = 1.0; GrowTime = 1.0; } }
        Grow { w = S(0) [ rotr(0.6) S(1) ] [ rotr(0.6) rotu(1.2) S(1) ] [ rotu(1.2) rotr(0.6) S(1) ]; }
    } })");
    ASSERT_EQ(r.count[shared::kOrganStem], 4u);
    glm::vec3 a = xyz(r.organs[1].heading), b = xyz(r.organs[2].heading), c = xyz(r.organs[3].heading);
    EXPECT_NEAR(a.y, std::cos(0.6f), 1e-5f);
    EXPECT_NEAR(b.y, a.y, 1e-5f);
    float around = std::acos(glm::dot(glm::normalize(glm::vec2(a.x, a.z)), glm::normalize(glm::vec2(b.x, b.z))));
    EXPECT_NEAR(around, 1.2f, 1e-4f);
    EXPECT_NEAR(glm::length(b - c), 0.0f, 1e-5f); // the order the script writes them in does not matter
}

// MTRL's diffuse factor tints the Color: (0.5, 1.0, 0.0) keeps green, drops red and blue.
TEST(EcoGeometry, MaterialTintsTheColour) {
    turtle::Interpretation r = interpretEco(R"(EcoSystem 1.0 "t" { Plant "p" {
        DerivationLength = 0;
        Stem { Default { GrowRate = 1.0; GrowTime = 1.0; Color = RGBA(1.0, 1.0, 1.0, 1.0);
                         Material = MTRL(0.5, 1.0, 0.0, 0.1, 0.1, 0.1); } }
        Grow { w = S(0); }
    } })");
    ASSERT_EQ(r.count[shared::kOrganStem], 1u);
    const shared::OrganInstance& stem = r.organs[0];
    EXPECT_NEAR(stem.color.x, 0.2140f, 1e-3f); // sRGB 0.5 as linear
    EXPECT_FLOAT_EQ(stem.color.y, 1.0f);
    EXPECT_FLOAT_EQ(stem.color.z, 0.0f);
}

TEST(EcoGeometry, SeedScenesDrawStemsAndLeaves) {
    for (const char* scene : {"lantana-camara.eco", "garden.eco"}) {
        SCOPED_TRACE(scene);
        ir::EcoScene s = lang::parseEcoFile(std::string(SIMECO_SOURCE_DIR) + "/scenes/" + scene);
        ir::Grammar g = lang::compileEcoPlant(s, 0);
        EXPECT_TRUE(g.homomorphism.present);
        stream::DeriveOptions options;
        options.homomorphism = true;
        stream::DeriveResult d = cpu::deriveCpu(g, options);
        turtle::Interpretation r =
            turtle::interpretCpu(d.string, turtle::turtleCommands(g.alphabet), {turtle::turtleSettings(g, g.alphabet)});
        EXPECT_GT(r.count[shared::kOrganStem], 10u);
        EXPECT_GT(r.count[shared::kOrganLeaf], 0u);
    }
}

} // namespace
