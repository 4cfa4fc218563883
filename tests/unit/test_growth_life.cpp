// The growth simulation's life cycle and bending, on the CPU reference, as the turtle draws them: organs that die
// at their LifeTime or after their ShadeTime in deep shade and are shed with their branch, leaves that turn from
// young to mature to old, shoots that turn against gravity (Geotropism) and bend under their weight (WeightFactor
// against Strength).
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "compute/shared/particle_layout.h"
#include "cpu/derive.h"
#include "field/plant_statistics.h"
#include "grow/growing_species.h"
#include "grow/growth_tables.h"
#include "grow/tick_cpu.h"
#include "lang/eco_parser.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_settings.h"

namespace simeco::test {
namespace {

// One plant of `stem` and `leaf` organ blocks, its axiom `axiom`, no rules; `gravity` the scene's Gravity line.
std::string scene(const std::string& stem, const std::string& leaf, const std::string& axiom,
                  const std::string& gravity = "") {
    return "EcoSystem 1.0 \"Test\" {\n" + gravity + " Plant \"P\" {\n DeriveTime = 3.0;\n Stem {\n" + stem +
           "}\n Leaf {\n" + leaf + "}\n Grow {\n w = " + axiom + ";\n }\n }\n}\n";
}

// The plant grown for `seconds` in ticks of one second, its drawn string interpreted by the CPU turtle.
class GrownPlant {
public:
    explicit GrownPlant(const std::string& text)
        : g_(grow::growingSpecies(lang::parseEcoText(text, "test.eco"))),
          tables_(grow::growthTables(g_.species, g_.ecoPlants)),
          deriveTimes_(grow::plantDeriveTimes(g_.ecoPlants, 1, 1)), derivation_(g_.species, options()) {}

    std::vector<shared::OrganInstance> after(uint32_t seconds) { return drawnAfter(seconds).organs; }
    turtle::Interpretation drawnAfter(uint32_t seconds) {
        grow::TickSettings ts{&tables_, 1, 1.0f, 0, 1, g_.relativeGravity()};
        if (light_ >= 0.0f) ts.openLight = 1.0f;
        for (; ticks_ < seconds; ++ticks_) {
            ts.tick = ticks_;
            if (light_ >= 0.0f)
                for (shared::ParticleState& p : derivation_.current().particles) p.value[shared::kParticleLight] = light_;
            grow::tickCpu(ts, derivation_.current());
        }
        stream::ModuleString drawn = derivation_.drawn();
        grow::growSizesCpu(ts, deriveTimes_, drawn);
        const ir::Alphabet& alphabet = g_.species[0].alphabet;
        return turtle::interpretCpu(drawn, turtle::turtleCommands(alphabet),
                                    {turtle::turtleSettings(g_.species[0], alphabet)}, {});
    }
    const stream::ModuleString& derived() { return derivation_.current(); }
    // From now on every particle stands in `light` (as a share of the open's, which a light grid gives them).
    void standIn(float light) { light_ = light; }

private:
    static stream::DeriveOptions options() {
        stream::DeriveOptions o;
        o.plants = 1;
        o.seed = 1;
        o.particles = true;
        return o;
    }
    grow::GrowingSpecies g_;
    grow::GrowthTables tables_;
    std::vector<float> deriveTimes_;
    cpu::SteppedDerivation derivation_;
    uint32_t ticks_ = 0;
    float light_ = -1.0f; // none: no light grid runs
};

std::vector<shared::OrganInstance> ofKind(const std::vector<shared::OrganInstance>& organs, uint32_t kind) {
    std::vector<shared::OrganInstance> out;
    std::copy_if(organs.begin(), organs.end(), std::back_inserter(out),
                 [&](const shared::OrganInstance& o) { return o.kind == kind; });
    return out;
}

float tipHeight(const std::vector<shared::OrganInstance>& organs) {
    float top = -1e9f;
    for (const shared::OrganInstance& o : ofKind(organs, shared::kOrganStem))
        top = std::max(top, o.position.y + o.heading.y * o.position.w);
    return top;
}

TEST(GrowthLife, AStemThatDiesIsShedWithItsBranchAndLeavesAgeThenFall) {
    // S(1) [ rotr / S(0) S(1) L(0) ] S(1) L(0): the stage-0 stem lives 5 s, the leaves 8 s.
    GrownPlant plant(scene("Stage 0 { GrowRate = 1.0; GrowTime = 10.0; LifeTime = 5.0; }\n"
                           "Default { GrowRate = 1.0; GrowTime = 10.0; }\n",
                           "Default { GrowRate = 0.1; GrowTime = 10.0; LifeTime = 8.0; }\n",
                           "S(1) [ rotr(0.5) S(0) S(1) L(0) ] S(1) L(0)"));
    // Young leaves while they unfold (their first DeriveTime, 3 s), then mature.
    auto leaves = ofKind(plant.after(2), shared::kOrganLeaf);
    ASSERT_EQ(leaves.size(), 2u);
    const shared::vec4 young = leaves[0].color;
    leaves = ofKind(plant.after(4), shared::kOrganLeaf);
    const shared::vec4 mature = leaves[0].color;
    EXPECT_NE(young, mature);
    EXPECT_LT(mature.x, mature.y); // green
    for (const shared::OrganInstance& leaf : leaves) EXPECT_GT(leaf.position.w, 0.0f);

    // At 6 s the stage-0 stem is dead: it, the stem after it and the leaf in its branch are drawn at no size; the
    // main axis and its leaf are not, and the leaves are old (yellow: past 70% of their LifeTime).
    std::vector<shared::OrganInstance> organs = plant.after(6);
    auto stems = ofKind(organs, shared::kOrganStem);
    ASSERT_EQ(stems.size(), 4u); // in module order: S(1), S(0), S(1) in the branch, S(1)
    EXPECT_FLOAT_EQ(stems[0].position.w, 6.0f);
    EXPECT_FLOAT_EQ(stems[1].position.w, 0.0f);
    EXPECT_FLOAT_EQ(stems[2].position.w, 0.0f);
    EXPECT_FLOAT_EQ(stems[3].position.w, 6.0f);
    leaves = ofKind(organs, shared::kOrganLeaf);
    EXPECT_FLOAT_EQ(leaves[0].position.w, 0.0f);
    EXPECT_GT(leaves[1].position.w, 0.0f);
    EXPECT_GT(leaves[1].color.x, leaves[1].color.y); // yellow
    // The dead stem grew no more after 5 s; the living ones did.
    EXPECT_FLOAT_EQ(plant.derived().particles[4].value[shared::kParticleElongation], 5.0f); // after [ rotr /

    // At 9 s every leaf has fallen.
    for (const shared::OrganInstance& leaf : ofKind(plant.after(9), shared::kOrganLeaf))
        EXPECT_FLOAT_EQ(leaf.position.w, 0.0f);
}

TEST(GrowthLife, AnOrganInDeepShadeForItsShadeTimeIsShedWithItsBranchAndStaysShed) {
    // S(1) [ S(0) L(0) ] S(1): the stage-0 stem and the leaf are shed after 3 s without a break in deep shade.
    GrownPlant plant(scene("Stage 0 { GrowRate = 1.0; GrowTime = 20.0; ShadeTime = 3.0; }\n"
                           "Default { GrowRate = 1.0; GrowTime = 20.0; }\n",
                           "Default { GrowRate = 0.1; GrowTime = 20.0; ShadeTime = 3.0; }\n",
                           "S(1) [ rotr(0.5) S(0) L(0) ] S(1)"));
    auto drawn = [&](uint32_t seconds) {
        const std::vector<shared::OrganInstance> organs = plant.after(seconds);
        return std::pair(ofKind(organs, shared::kOrganStem), ofKind(organs, shared::kOrganLeaf));
    };
    plant.standIn(1.0f);
    auto [stems, leaves] = drawn(2);
    ASSERT_EQ(stems.size(), 3u); // S(1), S(0), S(1)
    ASSERT_EQ(leaves.size(), 1u);
    EXPECT_FLOAT_EQ(stems[1].position.w, 2.0f);
    // Two seconds in deep shade (below 0.15 of the open's light), two in the light, two in the shade again: never
    // three without a break, so all live, growing at the pace of their light.
    plant.standIn(0.1f);
    drawn(4);
    plant.standIn(1.0f);
    drawn(6);
    plant.standIn(0.1f);
    std::tie(stems, leaves) = drawn(8);
    EXPECT_GT(stems[1].position.w, 4.0f);
    EXPECT_GT(leaves[0].position.w, 0.0f);
    const float stemAt8 = stems[1].position.w;
    // A third second in the shade sheds the stem and its leaf; the main axis, never shaded long enough, is not
    // (all stand in the same light, but only the stage-0 stem and the leaf have a ShadeTime).
    std::tie(stems, leaves) = drawn(9);
    EXPECT_FLOAT_EQ(stems[1].position.w, 0.0f);
    EXPECT_FLOAT_EQ(leaves[0].position.w, 0.0f);
    EXPECT_GT(stems[0].position.w, stemAt8);
    // Back in the light it stays shed.
    plant.standIn(1.0f);
    std::tie(stems, leaves) = drawn(12);
    EXPECT_FLOAT_EQ(stems[1].position.w, 0.0f);
    EXPECT_FLOAT_EQ(leaves[0].position.w, 0.0f);
    EXPECT_GT(stems[2].position.w, 0.0f);
}

TEST(GrowthLife, APlantLivesUntilEveryOrganItDrewIsShed) {
    // The stems live 5 s, the leaf at their base 7 s: the plant is alive until all are shed.
    GrownPlant plant(scene("Default { GrowRate = 1.0; GrowTime = 10.0; LifeTime = 5.0; }\n",
                           "Default { GrowRate = 0.1; GrowTime = 10.0; LifeTime = 7.0; }\n", "[ L(0) ] S(0) S(0)"));
    auto statistics = [&](uint32_t seconds) {
        return field::plantStatisticsCpu(plant.drawnAfter(seconds), {0.0f}, {}, field::leafShapeAreas()).at(0);
    };
    const shared::PlantStatistics young = statistics(3);
    EXPECT_EQ(young.organs, 3u);
    EXPECT_EQ(young.living, 3u);
    EXPECT_TRUE(shared::plantAlive(young));
    // At 6 s both stems are shed, the leaf not yet; at 8 s nothing is left.
    const shared::PlantStatistics shedding = statistics(6);
    EXPECT_EQ(shedding.organs, 3u);
    EXPECT_EQ(shedding.living, 1u);
    EXPECT_TRUE(shared::plantAlive(shedding));
    const shared::PlantStatistics dead = statistics(8);
    EXPECT_EQ(dead.living, 0u);
    EXPECT_FALSE(shared::plantAlive(dead));
    // A seed that has drawn nothing yet lives.
    EXPECT_TRUE(shared::plantAlive(shared::PlantStatistics{0, 0, 0.0f, 0.0f, 0.0f}));
}

TEST(GrowthLife, ShootsTurnAgainstGravityAndBendUnderTheirWeight) {
    // A shoot leaning 1.2 rad from the vertical, four segments long.
    const std::string axiom = "rotr(1.2) S(0) S(0) S(0) S(0)";
    const std::string growth = "GrowRate = 1.0; GrowTime = 2.0; ";
    auto height = [&](const std::string& stem, const std::string& gravity = "") {
        GrownPlant plant(scene("Default { " + growth + stem + " }\n", "", axiom, gravity));
        return tipHeight(plant.after(4));
    };
    const float free = height("");
    EXPECT_GT(height("Geotropism = -0.3;"), free + 0.5f);
    EXPECT_LT(height("WeightFactor = 0.3; Strength = 1.0;"), free - 0.5f);
    // A stronger stem bends less; without gravity nothing bends.
    EXPECT_GT(height("WeightFactor = 0.3; Strength = 3.0;"), height("WeightFactor = 0.3; Strength = 1.0;"));
    EXPECT_FLOAT_EQ(height("Geotropism = -0.3;", " Gravity = vector(0.0, 0.0, 0.0);\n"), free);
    // Under gravity pointing up (+y), negative geotropism turns the shoot down.
    EXPECT_LT(height("Geotropism = -0.3;", " Gravity = vector(0.0, 9.81, 0.0);\n"), free - 0.5f);
}

TEST(GrowthLife, AGrammarsSegmentsAndSpheresGrowOverTheirFirstDeriveTime) {
    // A cpfg grammar: each step adds a segment of length 2, a segment of the turtle's step (1), the letter of
    // an `@` command, which is not a segment, and a sphere of radius 3.
    const std::filesystem::path file = std::filesystem::temp_directory_path() / "simeco-segments-test.l";
    {
        std::ofstream out(file);
        out << "Lsystem: 1\nderivation length: 3\nAxiom: A\nA --> F(2)F@Gs@O(3)A\nendlsystem\n";
    }
    const grow::GrowingSpecies g = grow::loadGrowingSpecies(file.string());
    std::filesystem::remove(file);
    const grow::GrowthTables tables = grow::growthTables(g.species, g.ecoPlants);
    ASSERT_TRUE(tables.growsSegments());
    stream::DeriveOptions o;
    o.particles = true;
    cpu::SteppedDerivation derivation(g.species, o);
    const std::vector<float> deriveTimes = {3.0f};
    grow::TickSettings ts{&tables, 1, 1.0f, 0, 1};
    ASSERT_EQ(derivation.advance({1}), 1u);
    // F(2) F @ G s @ O(3) A: each tick a third more of both segments and of the sphere's radius; the G after `@`
    // untouched.
    const std::vector<float> want = {2.0f / 3, 4.0f / 3, 2.0f, 2.0f};
    for (uint32_t tick = 0; tick < want.size(); ++tick) {
        ts.tick = tick;
        grow::tickCpu(ts, derivation.current());
        stream::ModuleString drawn = derivation.drawn();
        grow::growSizesCpu(ts, deriveTimes, drawn);
        ASSERT_EQ(drawn.size(), 8u);
        EXPECT_FLOAT_EQ(drawn.paramsOf(0)[0], want[tick]) << tick;
        EXPECT_EQ(drawn.paramCount[1], want[tick] < 2.0f ? 1 : 0) << tick;
        if (want[tick] < 2.0f) {
            EXPECT_FLOAT_EQ(drawn.paramsOf(1)[0], want[tick] / 2) << tick;
        }
        EXPECT_EQ(drawn.paramCount[3], 0) << tick;
        EXPECT_FLOAT_EQ(drawn.paramsOf(6)[0], 1.5f * want[tick]) << tick;
        // The derived string keeps its full lengths.
        EXPECT_FLOAT_EQ(derivation.current().paramsOf(0)[0], 2.0f);
    }
}

} // namespace
} // namespace simeco::test
