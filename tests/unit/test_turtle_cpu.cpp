// The reference turtle, case by case, with geometry worked out by hand.
#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "compute/shared/organ_layout.h"
#include "grammar_text.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_settings.h"

namespace {

using namespace simeco;
using simeco::testing::grammarFromText;
using simeco::testing::lsystem;

// The reference turtle's organs for a grammar's string, derived under its homomorphism.
turtle::Interpretation interpretGrammar(const ir::Grammar& g, uint32_t plants = 1,
                                        const turtle::FieldOptions& field = {}) {
    stream::DeriveOptions options;
    options.plants = plants;
    options.homomorphism = true;
    stream::DeriveResult r = cpu::deriveCpu(g, options);
    return turtle::interpretCpu(r.string, turtle::turtleCommands(g.alphabet), {turtle::turtleSettings(g, g.alphabet)},
                                field);
}

// The same with segments drawn as cylinders, whose bounds hold their radii (cpfg's default, a model without a view,
// draws pixel lines: PixelLinesAreBoundedByTheirEnds).
turtle::Interpretation interpret(const std::string& text, uint32_t plants = 1, const turtle::FieldOptions& field = {}) {
    ir::Grammar g = grammarFromText(text);
    g.view.lineStyle = ir::LineStyle::Cylinder;
    return interpretGrammar(g, plants, field);
}

glm::vec3 xyz(const shared::vec4& v) { return {v.x, v.y, v.z}; }

void expectNear(glm::vec3 got, glm::vec3 want) {
    EXPECT_NEAR(got.x, want.x, 1e-5f);
    EXPECT_NEAR(got.y, want.y, 1e-5f);
    EXPECT_NEAR(got.z, want.z, 1e-5f);
}

TEST(TurtleCpu, LeafShapesComeFromTheSurfacesName) {
    // The seed species by the names their scenes give them.
    EXPECT_EQ(turtle::surfaceShapeOf("Oxalis corniculata"), shared::kLeafTrifoliate);
    EXPECT_EQ(turtle::surfaceShapeOf("Rose Rugosa"), shared::kLeafCompound);
    EXPECT_EQ(turtle::surfaceShapeOf("Lantan camara"), shared::kLeafSerrate);
    EXPECT_EQ(turtle::surfaceShapeOf("heart"), shared::kLeafCordate);
    EXPECT_EQ(turtle::surfaceShapeOf("grass blade"), shared::kLeafLanceolate);
    EXPECT_EQ(turtle::surfaceShapeOf("Lantana camara blossom"), shared::kBlossomHead);
    EXPECT_EQ(turtle::surfaceShapeOf("Rosa rugosa blossom"), shared::kBlossomRose);
    EXPECT_EQ(turtle::surfaceShapeOf("Oxalis corniculata blossom"), shared::kBlossomStar);
    EXPECT_EQ(turtle::surfaceShapeOf("flower"), shared::kBlossomStar);
    EXPECT_EQ(turtle::surfaceShapeOf("Sunflower leaf"), shared::kLeafOvate);
    EXPECT_EQ(turtle::surfaceShapeOf("leaf"), shared::kLeafOvate);
}

TEST(TurtleCpu, TurnsLeftTowardMinusXAndJoinsSegments) {
    turtle::Interpretation r = interpret(lsystem("F+(90)F(2)", "", 0));
    ASSERT_EQ(r.count[shared::kOrganStem], 2u);
    const shared::OrganInstance& a = r.organs[0];
    const shared::OrganInstance& b = r.organs[1];
    expectNear(xyz(a.position), {0, 0, 0});
    expectNear(xyz(a.heading), {0, 1, 0});
    EXPECT_FLOAT_EQ(a.position.w, 1.0f);
    expectNear(xyz(b.position), {0, 1, 0});
    expectNear(xyz(b.heading), {-1, 0, 0});
    EXPECT_FLOAT_EQ(b.position.w, 2.0f);
    // The joint: each segment knows the other's heading; the ends of the string have none.
    expectNear(xyz(a.nextHeading), {-1, 0, 0});
    expectNear(xyz(b.previousHeading), {0, 1, 0});
    expectNear(xyz(a.previousHeading), {0, 0, 0});
    expectNear(xyz(b.nextHeading), {0, 0, 0});
    expectNear(r.bounds.max, {0.5f, 1.5f, 0.5f});
    expectNear(r.bounds.min, {-2.5f, -0.5f, -0.5f});
}

TEST(TurtleCpu, PixelLinesAreBoundedByTheirEnds) {
    // cpfg's default line style, that of a model without a view: a line's width is the picture's, not the world's.
    ir::Grammar g = grammarFromText(lsystem("F+(90)F(2)", "", 0));
    ASSERT_EQ(g.view.lineStyle, ir::LineStyle::Pixel);
    turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 2u);
    EXPECT_EQ(r.organs[0].shape, shared::kLinePixel);
    EXPECT_FLOAT_EQ(r.organs[0].heading.w, 0.5f);
    expectNear(r.bounds.max, {0, 1, 0});
    expectNear(r.bounds.min, {-2, 0, 0});
}

TEST(TurtleCpu, BranchesRestoreTheStateAndDoNotContinueTheParent) {
    turtle::Interpretation r = interpret(lsystem("F[&(90)F]#(3)F", "", 0));
    ASSERT_EQ(r.count[shared::kOrganStem], 3u);
    expectNear(xyz(r.organs[1].position), {0, 1, 0});
    expectNear(xyz(r.organs[1].heading), {0, 0, -1}); // pitch down: heading toward -up
    expectNear(xyz(r.organs[1].previousHeading), {0, 0, 0});
    expectNear(xyz(r.organs[2].position), {0, 1, 0});
    expectNear(xyz(r.organs[2].heading), {0, 1, 0});
    EXPECT_FLOAT_EQ(r.organs[2].heading.w, 1.5f); // width 3: radius 1.5
    expectNear(xyz(r.organs[0].nextHeading), {0, 1, 0});
}

TEST(TurtleCpu, CpfgMultiModuleCommandsAndHomomorphism) {
    // `@O(2)` is `@` then `O(2)`; the homomorphism draws A as a sphere on a segment.
    turtle::Interpretation r = interpret(lsystem("A", "homomorphism\nA --> F(3);(5)@O(2)", 0));
    ASSERT_EQ(r.count[shared::kOrganStem], 1u);
    ASSERT_EQ(r.count[shared::kOrganSphere], 1u);
    const shared::OrganInstance& s = r.organs[r.first[shared::kOrganSphere]];
    expectNear(xyz(s.position), {0, 3, 0});
    EXPECT_FLOAT_EQ(s.heading.w, 1.0f);
    glm::vec4 red = turtle::defaultPalette()[5];
    EXPECT_FLOAT_EQ(s.color.x, red.r);
}

TEST(TurtleCpu, PolygonsBecomeTriangleFans) {
    turtle::Interpretation r = interpret(lsystem("{.f+(90)f+(90)f}", "", 0));
    ASSERT_EQ(r.count[shared::kOrganTriangle], 2u);
    EXPECT_EQ(r.count[shared::kOrganStem], 0u);
    const shared::OrganInstance& t = r.organs[r.first[shared::kOrganTriangle] + 1];
    expectNear(xyz(t.position), {0, 0, 0});
    expectNear(xyz(t.heading), {-1, 1, 0});
    expectNear(xyz(t.up), {-1, 0, 0});
}

TEST(TurtleCpu, InsideAPolygonSegmentsAreStillDrawnAndOnlyFfAndDotAddVertices) {
    // As cpfg: F draws its segment and adds a vertex; G draws and adds none; g moves and adds none.
    turtle::Interpretation r = interpret(lsystem("{.F+(90)G+(90)F+(90)g+(90)F}", "", 0));
    EXPECT_EQ(r.count[shared::kOrganStem], 4u);
    // Vertices: the `.` at (0,0), F's at (0,1), (-1,0) and (0,0) after g: two triangles.
    ASSERT_EQ(r.count[shared::kOrganTriangle], 2u);
    const shared::OrganInstance& t = r.organs[r.first[shared::kOrganTriangle]];
    expectNear(xyz(t.position), {0, 0, 0});
    expectNear(xyz(t.heading), {0, 1, 0});
    expectNear(xyz(t.up), {-1, 0, 0});
}

TEST(TurtleCpu, ATaperedSegmentNarrowsToTheWidthSetBeforeWhatEndsIt) {
    // Width 1, increments of 1: `#` draws the first segment 2 wide; `!` sets 1 before the branch ends it. The
    // branch's segment widens to the 2 set before its `]`; the last keeps the 1 restored after the branch.
    ir::Grammar g = grammarFromText(lsystem("#F!;[+F#]F", "", 0));
    g.view.taperedLines = true;
    turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 3u);
    EXPECT_FLOAT_EQ(r.organs[0].heading.w, 1.0f);
    EXPECT_FLOAT_EQ(r.organs[0].up.w, 0.5f);
    EXPECT_FLOAT_EQ(r.organs[1].heading.w, 0.5f);
    EXPECT_FLOAT_EQ(r.organs[1].up.w, 1.0f);
    EXPECT_FLOAT_EQ(r.organs[2].heading.w, 0.5f);
    EXPECT_FLOAT_EQ(r.organs[2].up.w, 0.5f);
    // Untapered, each segment keeps its width.
    g.view.taperedLines = false;
    r = interpretGrammar(g);
    EXPECT_FLOAT_EQ(r.organs[0].up.w, 1.0f);
}

TEST(TurtleCpu, AtDScalesTheWidthsSetAfterItAsInCpfg) {
    // Width 1, increment 1: after `@D(2)` the first segment is twice as long but as wide; `!(0.5)` then sets a
    // width of 1, `#` adds 2, a sphere without a size is the width across and one with a size twice it.
    ir::Grammar g = grammarFromText(lsystem("@D(2)F!(0.5)F#F@O@O(0.25)", "", 0));
    const turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 3u);
    EXPECT_FLOAT_EQ(r.organs[0].position.w, 2.0f);
    EXPECT_FLOAT_EQ(r.organs[0].heading.w, 0.5f);
    EXPECT_FLOAT_EQ(r.organs[1].heading.w, 0.5f);
    EXPECT_FLOAT_EQ(r.organs[2].heading.w, 1.5f);
    ASSERT_EQ(r.count[shared::kOrganSphere], 2u);
    EXPECT_FLOAT_EQ(r.organs[r.first[shared::kOrganSphere]].heading.w, 1.5f);
    EXPECT_FLOAT_EQ(r.organs[r.first[shared::kOrganSphere] + 1].heading.w, 0.25f);
}

TEST(TurtleCpu, RollsAsCpfgWhoseUpIsOursReversed) {
    // \(90) rolls left: cpfg's up (-z at the start) turns toward left (-x), so left turns toward +z; then + turns
    // the heading toward left.
    turtle::Interpretation r = interpret(lsystem("\\(90)+(90)F", "", 0));
    ASSERT_EQ(r.count[shared::kOrganStem], 1u);
    expectNear(xyz(r.organs[0].heading), {0, 0, 1});
}

TEST(TurtleCpu, DollarRollsLevelOutsideCpfgAndAtVRollsCpfgsUpUpright) {
    // Pitched down to the horizontal (heading -z, our up +y) and rolled 30 degrees, then rolled back level before
    // turning left. cpfg's @v keeps its own up (ours reversed) closest to up: left is +x.
    auto heading = [](const std::string& axiom, bool dollarRolls) {
        ir::Grammar g = grammarFromText(lsystem(axiom, "", 0));
        g.view.dollarRolls = dollarRolls;
        turtle::Interpretation r = interpretGrammar(g);
        return r.count[shared::kOrganStem] == 1 ? xyz(r.organs[0].heading) : glm::vec3(0.0f);
    };
    expectNear(heading("&(90)/(30)@v+(90)F", false), {1, 0, 0});
    // The quick grammars' `$`: our up closest to up, so left is -x.
    expectNear(heading("&(90)/(30)$+(90)F", true), {-1, 0, 0});
    // In a cpfg .l file `$` ends a sub-L-system call: the turtle stays rolled, and turns out of the horizontal.
    expectNear(heading("&(90)/(30)$+(90)F", false), {-0.8660254f, -0.5f, 0});
}

TEST(TurtleCpu, CpfgsTropismDirectionBendsAfterEveryMoveByTheArcsine) {
    // The view's old form: tropism toward -x, elasticity 0 raised to 0.5 by `_`. After the move f the heading turns
    // toward left (-x) by asin(0.5 x T.L) = 30 degrees, so F draws along it.
    ir::Grammar g = grammarFromText(lsystem("_fF", "", 0));
    g.view.tropismRule = ir::TropismRule::CpfgDirection;
    g.view.tropismDirection = {-1, 0, 0};
    g.view.initialElasticity = 0.0f;
    g.view.elasticityIncrement = 0.5f;
    turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 1u);
    expectNear(xyz(r.organs[0].heading), {-0.5f, std::sqrt(3.0f) / 2, 0});
    // ABOP's torque bends only after drawn segments: F still goes straight up.
    g.view.tropismRule = ir::TropismRule::Torque;
    r = interpretGrammar(g);
    expectNear(xyz(r.organs[0].heading), {0, 1, 0});
}

TEST(TurtleCpu, PlantsStandInAGridSpacedByTheWidestPlant) {
    turtle::Interpretation r = interpret(lsystem("+(90)F(4)", "", 0), 4);
    ASSERT_EQ(r.plantOrigins.size(), 4u);
    // Each plant is 4 wide (plus its radius 0.5 on either side): spacing 1.2 * 5.
    expectNear(r.plantOrigins[0], {-3, 0, -3});
    expectNear(r.plantOrigins[3], {3, 0, 3});
    EXPECT_EQ(r.organs[3].plant, 3u);
}

TEST(TurtleCpu, AScatteredFieldMovesEachPlantInItsCellAndTurnsIt) {
    turtle::FieldOptions field;
    field.scattered = true;
    const uint32_t plants = 9;
    turtle::Interpretation r = interpret(lsystem("+(90)F(4)", "", 0), plants, field);
    ASSERT_EQ(r.plantOrigins.size(), plants);
    EXPECT_TRUE(r.scattered);
    const float spacing = r.spacing;
    EXPECT_FLOAT_EQ(spacing, 6.0f); // as on the grid: from the widest plant
    std::vector<float> turns;
    for (uint32_t p = 0; p < plants; ++p) {
        // Within 0.3 of the spacing of its cell's centre along x and z, and on the ground.
        const glm::vec3 cell = turtle::fieldCell(p, plants) * spacing;
        const glm::vec3 offset = r.plantOrigins[p] - cell;
        EXPECT_LE(std::abs(offset.x), 0.3f * spacing) << p;
        EXPECT_LE(std::abs(offset.z), 0.3f * spacing) << p;
        EXPECT_GT(glm::length(offset), 1e-3f) << p;
        EXPECT_FLOAT_EQ(offset.y, 0.0f) << p;
        // Its one segment starts where it stands, still horizontal, turned about the vertical by an angle of its own.
        const shared::OrganInstance& stem = r.organs[r.first[shared::kOrganStem] + p];
        ASSERT_EQ(stem.plant, p);
        expectNear(xyz(stem.position), r.plantOrigins[p]);
        EXPECT_NEAR(stem.heading.y, 0.0f, 1e-6f) << p;
        turns.push_back(std::atan2(stem.heading.z, stem.heading.x));
    }
    std::sort(turns.begin(), turns.end());
    EXPECT_EQ(std::adjacent_find(turns.begin(), turns.end(), [](float a, float b) { return b - a < 1e-3f; }),
              turns.end());
}

// A generalized cylinder bends along the Hermite curve of the headings at its control points: from the
// origin heading up to (-1, 1, 0) heading -x, in the four segments @Gc(4) asks for, joined end to end (as tubes:
// cpfg's polygon lines; with its cylinder lines a cylinder is a mesh, test_cylinder_contour.cpp).
TEST(TurtleCpu, GeneralizedCylindersFollowTheHeadingsInSegments) {
    ir::Grammar g = grammarFromText(lsystem("@GsF(1)+(90)F(1)@Gc(4)", "", 0));
    g.view.lineStyle = ir::LineStyle::Polygon;
    turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 6u); // two F segments, four tube segments
    const shared::OrganInstance* tube = &r.organs[r.first[shared::kOrganStem] + 2];
    expectNear(xyz(tube[0].position), {0, 0, 0});
    float chord = std::sqrt(2.0f);
    // The curve at t = 1/2, off the chord: the tangents are cpfg's, 1.2 times the chord.
    glm::vec3 middle = glm::vec3(-0.5f, 0.5f, 0.0f) + 0.125f * 1.2f * chord * glm::vec3(1.0f, 1.0f, 0.0f);
    expectNear(xyz(tube[2].position), middle);
    glm::vec3 end = xyz(tube[3].position) + xyz(tube[3].heading) * tube[3].position.w;
    expectNear(end, {-1, 1, 0});
    EXPECT_GT(tube[0].heading.y, 0.8f);  // leaves the origin about upward
    EXPECT_LT(tube[3].heading.x, -0.8f); // arrives about along -x
    for (int k = 1; k < 4; ++k) {
        expectNear(xyz(tube[k].previousHeading), xyz(tube[k - 1].heading));
        expectNear(xyz(tube[k - 1].nextHeading), xyz(tube[k].heading));
        expectNear(xyz(tube[k].position), xyz(tube[k - 1].position) + xyz(tube[k - 1].heading) * tube[k - 1].position.w);
    }
}

// cpfg's tubes (its pixel and polygon line styles, general.c): `@Gt` sets the curve's tangents, `@Gc` without a
// number draws four pieces and `@Gc(2.7)` two, every piece is as wide as the control point it starts from, and the
// last narrows to the next point's width where polygons taper; each piece is drawn in the line style.
TEST(TurtleCpu, CpfgTubesTakeTheirPiecesTangentsAndWidthsAsCpfg) {
    for (ir::LineStyle style : {ir::LineStyle::Polygon, ir::LineStyle::Pixel}) {
        ir::Grammar g = grammarFromText(lsystem("@Gt(1)!(0.2)@Gsf(1)+(90)f(1)!(0.1)@Gc(2.7)f(1)@Gc", "", 0));
        g.view.lineStyle = style;
        const turtle::Interpretation r = interpretGrammar(g);
        ASSERT_EQ(r.count[shared::kOrganStem], 6u);
        const shared::OrganInstance* tube = &r.organs[r.first[shared::kOrganStem]];
        // The curve at r = t = 1/2 from the origin heading up to (-1, 1, 0) heading -x, tangents once the chord.
        const float chord = std::sqrt(2.0f);
        expectNear(xyz(tube[1].position), glm::vec3(-0.5f, 0.5f, 0.0f) + 0.125f * chord * glm::vec3(1.0f, 1.0f, 0.0f));
        const bool tapers = style == ir::LineStyle::Polygon;
        EXPECT_FLOAT_EQ(tube[0].heading.w, 0.1f);
        EXPECT_FLOAT_EQ(tube[0].up.w, 0.1f);
        EXPECT_FLOAT_EQ(tube[1].heading.w, 0.1f);
        EXPECT_FLOAT_EQ(tube[1].up.w, tapers ? 0.05f : 0.1f);
        for (int k = 2; k < 6; ++k) { // the next stretch, four pieces, all of the point's width
            EXPECT_FLOAT_EQ(tube[k].heading.w, 0.05f);
            EXPECT_FLOAT_EQ(tube[k].up.w, 0.05f);
        }
        for (int k = 0; k < 6; ++k) EXPECT_EQ(tube[k].shape, turtle::lineStyleCode(style));
        const glm::vec3 end = xyz(tube[5].position) + xyz(tube[5].heading) * tube[5].position.w;
        expectNear(end, {-2, 1, 0});
    }
}

// cpfg's torque rolls the turtle before every move, its up turning away from the torque's part across the heading
// by W . L radians: W along -x (our and cpfg's left at first) rolls the first F by 0.2 and the second by 0.2 cos 0.2
// (its left has turned); a torque of 3 rolls by 2 atan(3 tan 0.5), as cpfg's quaternion turns beyond a radian.
TEST(TurtleCpu, CpfgsTorqueRollsBeforeEveryMove) {
    ir::Grammar g = grammarFromText(lsystem("FfF", "", 0));
    g.view.lineStyle = ir::LineStyle::Cylinder;
    g.view.torque = {-0.2f, 0.0f, 0.0f};
    turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 2u);
    expectNear(xyz(r.organs[0].up), {-std::sin(0.2f), 0, std::cos(0.2f)});
    const float second = 0.2f + 0.2f * std::cos(0.2f), third = second + 0.2f * std::cos(second);
    expectNear(xyz(r.organs[1].up), {-std::sin(third), 0, std::cos(third)});
    expectNear(xyz(r.organs[1].heading), {0, 1, 0}); // the heading stays
    g.view.torque = {-3.0f, 0.0f, 0.0f};
    r = interpretGrammar(g);
    const float large = 2.0f * std::atan(3.0f * std::tan(0.5f));
    expectNear(xyz(r.organs[0].up), {-std::sin(large), 0, std::cos(large)});
}

TEST(TurtleCpu, CpfgsTropismLinesBendBeforeEveryMove) {
    // cpfg's `tropism:` form, toward -x with elasticity 0.5: before the move f the heading, H x T of length one,
    // turns by 0.5 rad toward -x; before F by 0.5 x |H x T| = 0.5 cos(0.5) more.
    ir::Grammar g = grammarFromText(lsystem("fF", "", 0));
    g.view.tropismRule = ir::TropismRule::CpfgTropism;
    g.view.tropismDirection = {-1, 0, 0};
    g.view.initialElasticity = 0.5f;
    turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 1u);
    const float angle = 0.5f + 0.5f * std::cos(0.5f);
    expectNear(xyz(r.organs[0].heading), {-std::sin(angle), std::cos(angle), 0});
    expectNear(xyz(r.organs[0].position), {-std::sin(0.5f), std::cos(0.5f), 0}); // f moved after bending
    // Beyond a radian cpfg's quaternion (made for at most one) turns by 2 atan(x tan 0.5): 2.44 rad for 5.
    g.view.initialElasticity = 5.0f;
    r = interpretGrammar(g);
    const float large = 2.0f * std::atan(5.0f * std::tan(0.5f));
    expectNear(xyz(r.organs[0].position), {-std::sin(large), std::cos(large), 0});
}

TEST(TurtleCpu, CpfgsElasticityCommandsSetRaiseAndLowerTheTropismsElasticity) {
    // Elasticity 0 at first: `@Ti(1, 0.5)` raises it to 0.5, so before f the heading turns by 0.5 rad toward -x;
    // `@Td(1, 0.5)` lowers it to 0 again, so F goes on straight; `@Ts(1, 0.5)` sets it for the last F.
    ir::Grammar g = grammarFromText(lsystem("@Ti(1,0.5)f@Td(1,0.5)F@Ts(1,0.5)F", "", 0));
    g.view.tropismRule = ir::TropismRule::CpfgTropism;
    g.view.tropismDirection = {-1, 0, 0};
    const turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 2u);
    expectNear(xyz(r.organs[0].heading), {-std::sin(0.5f), std::cos(0.5f), 0});
    const float angle = 0.5f + 0.5f * std::cos(0.5f);
    expectNear(xyz(r.organs[1].heading), {-std::sin(angle), std::cos(angle), 0});
}

TEST(TurtleCpu, TheViewsInitialScaleScalesTheSteps) {
    ir::Grammar g = grammarFromText(lsystem("fF(2)", "", 0));
    g.view.initialScale = 1.5f;
    const turtle::Interpretation r = interpretGrammar(g);
    ASSERT_EQ(r.count[shared::kOrganStem], 1u);
    EXPECT_FLOAT_EQ(r.organs[0].position.y, 1.5f);
    EXPECT_FLOAT_EQ(r.organs[0].position.w, 3.0f);
}

TEST(TurtleCpu, TropismBendsTheNextSegmentTowardTheDirection) {
    ir::Grammar g = grammarFromText(lsystem("F+(90)FF", "", 0));
    g.view.tropismDirection = {0, -1, 0};
    g.view.initialElasticity = 0.5f;
    stream::DeriveResult d = cpu::deriveCpu(g, {});
    turtle::Interpretation r =
        turtle::interpretCpu(d.string, turtle::turtleCommands(g.alphabet), {turtle::turtleSettings(g, g.alphabet)});
    ASSERT_EQ(r.count[shared::kOrganStem], 3u);
    // Up the y axis, H x T is zero: no bending. Heading -x: bent down by 0.5 rad.
    expectNear(xyz(r.organs[1].heading), {-1, 0, 0});
    expectNear(xyz(r.organs[2].heading), {-std::cos(0.5f), -std::sin(0.5f), 0});
}

} // namespace
