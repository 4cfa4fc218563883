// The cpfg reader: sections, contexts, conditions and statement blocks land in the IR where they belong.
#include <gtest/gtest.h>

#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <string>

#include "grammar_text.h"
#include "temporary_folder.h"

namespace {

using simeco::testing::grammarFromText;

TEST(CpfgParser, ReadsHeaderSectionsAndProductions) {
    simeco::ir::Grammar g = grammarFromText(
        "#define STEPS 7\nLsystem: 1\nderivation length: STEPS\nignore: +-\nAxiom: A(1)\n"
        "B(a) < A(x) > [C]D : {y = x;} y > 0 {z = 1;} --> A(x + 1)\nA(x) --> *\n"
        "decomposition\nmaximum depth: 3\nA(x) --> B(x)\nhomomorphism\nmaximum depth: 2\nB(x) --> F(x)\n"
        "endlsystem\n");
    EXPECT_EQ(g.derivationLength, 7);
    ASSERT_EQ(g.productions.productions.size(), 2u);
    const simeco::ir::Production& p = g.productions.productions[0];
    EXPECT_EQ(p.left.size(), 1u);
    EXPECT_EQ(p.strict.size(), 1u);
    EXPECT_EQ(p.right.size(), 4u); // [ C ] D
    EXPECT_EQ(p.before.size(), 1u);
    EXPECT_TRUE(p.condition.has_value());
    EXPECT_EQ(p.after.size(), 1u);
    EXPECT_EQ(p.slotNames, (std::vector<std::string>{"a", "x", "y", "z"}));
    EXPECT_TRUE(g.productions.productions[1].alternatives[0].modules.empty());
    EXPECT_EQ(g.decomposition.maxDepth, 3);
    EXPECT_EQ(g.homomorphism.maxDepth, 2);
    EXPECT_EQ(g.homomorphism.productions.size(), 1u);
    EXPECT_TRUE(g.skippedInContext(*g.alphabet.find("+")));
    EXPECT_FALSE(g.skippedInContext(*g.alphabet.find("A")));
}

TEST(CpfgParser, TurtleModulesAreOneCharacterEachAsInCpfg) {
    simeco::ir::Grammar g = grammarFromText("Lsystem: 1\nAxiom: @Gs~l?P(1,2)$\nendlsystem\n");
    std::vector<std::string> names;
    for (const simeco::ir::SuccessorModule& m : g.axiom) names.push_back(g.alphabet.name(m.sym));
    EXPECT_EQ(names, (std::vector<std::string>{"@", "G", "s", "~", "l", "?", "P", "$"}));
    EXPECT_EQ(g.axiom[6].args.size(), 2u);
}

TEST(CpfgParser, ArrowsInAllSpellings) {
    simeco::ir::Grammar g = grammarFromText("Lsystem: 1\nAxiom: A\nA --> B\nB -> C\nC \xE2\x86\x92 A\nendlsystem\n");
    EXPECT_EQ(g.productions.productions.size(), 3u);
}

TEST(CpfgParser, StochasticFactorsMakeEveryProductionWeighted) {
    simeco::ir::Grammar g = grammarFromText("Lsystem: 1\nseed: 3\nAxiom: F\nF --> FF : 30\nF --> F\nendlsystem\n");
    EXPECT_EQ(g.seed, 3u);
    EXPECT_FLOAT_EQ(g.productions.productions[0].weight, 30.0f);
    EXPECT_FLOAT_EQ(g.productions.productions[1].weight, 1.0f);
}

TEST(CpfgParser, ViewFileGivesAngleAndFunctions) {
    namespace fs = std::filesystem;
    fs::path dir = fs::temp_directory_path() / ("simeco-view-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    std::ofstream(dir / "m.l") << "Lsystem: 1\nAxiom: A(func(1, 0.5))\nendlsystem\n";
    std::ofstream(dir / "m.v") << "angle increment: 30\nfunction: f.func\n";
    std::ofstream(dir / "f.func") << "fver 1 1\nname: f\nsamples: 0\nflip: off\npoints: 4\n0 0\n0.33 0.33\n0.66 0.66\n1 1\n";
    simeco::ir::Grammar g = simeco::lang::loadGrammarFile((dir / "m.l").string());
    EXPECT_FLOAT_EQ(g.view.angleIncrement, 30.0f);
    ASSERT_EQ(g.functions.size(), 1u);
    // The curve through collinear points is the line y = x; bisection stops within 0.001 in x.
    EXPECT_NEAR(simeco::ir::evaluateCurve(g.functions[0], 0.5), 0.5, 0.002);
    fs::remove_all(dir);
}

// A one-segment model in a folder of its own, read with the view file a test writes beside it.
class CpfgView : public simeco::testing::TemporaryFolderTest {
protected:
    // The view a model reads with `view` as its view file (none when empty).
    simeco::ir::ViewSettings viewWith(const std::string& view) {
        std::ofstream(dir_ / "m.l") << "Lsystem: 1\nAxiom: F\nendlsystem\n";
        if (view.empty()) std::filesystem::remove(dir_ / "m.v");
        else std::ofstream(dir_ / "m.v") << view;
        return simeco::lang::loadGrammarFile((dir_ / "m.l").string()).view;
    }
};

TEST_F(CpfgView, LinesAreTaperedUnlessTheViewSaysOffAndDollarLeavesTheTurtleAlone) {
    // cpfg's default, without a view file and with one that does not say.
    EXPECT_TRUE(viewWith("").taperedLines);
    EXPECT_FALSE(viewWith("").dollarRolls);
    EXPECT_TRUE(viewWith("angle increment: 30\n").taperedLines);
    EXPECT_FALSE(viewWith("angle increment: 30\ntapered lines: off\n").taperedLines);
}

TEST_F(CpfgView, TropismLinesAddUpAsCpfgTurnsTowardTheirSum) {
    simeco::ir::ViewSettings v = viewWith("tropism: T: 0,-2,0 E: 0.2\n");
    EXPECT_EQ(v.tropismRule, simeco::ir::TropismRule::CpfgTropism);
    EXPECT_FLOAT_EQ(v.tropismDirection[1], -1.0f); // unit
    EXPECT_FLOAT_EQ(v.initialElasticity, 0.2f);
    // 0.3 down and 0.4 x (elasticity 0.8, half the intensity) toward +x; a line at 90 degrees adds nothing.
    v = viewWith("tropism: T: 0 -1 0 E: 0.3\ntropism: T: 1 0 0 I: 0.5 E: 0.8\ntropism: T: 0 0 1 A: 90 E: 1\n");
    EXPECT_NEAR(v.initialElasticity, 0.5f, 1e-6f);
    EXPECT_NEAR(v.tropismDirection[0], 0.8f, 1e-6f);
    EXPECT_NEAR(v.tropismDirection[1], -0.6f, 1e-6f);
    EXPECT_NEAR(v.tropismDirection[2], 0.0f, 1e-6f);
}

TEST_F(CpfgView, TorqueLinesAddUpTheirDirectionsTimesTheirElasticities) {
    EXPECT_EQ(viewWith("torque: T: 0,1,0\n").torque, (std::array{0.f, 0.f, 0.f})); // no E: no torque
    // Unit T times 0.5, plus T of length 2 at intensity 0.5 (so of length 0.5) times 0.4.
    const std::array<float, 3> w = viewWith("torque: T: 0 2 0 E: 0.5\ntorque: T: 2,0,0 I: 0.5 E: 0.4\n").torque;
    EXPECT_NEAR(w[0], 0.2f, 1e-6f);
    EXPECT_NEAR(w[1], 0.5f, 1e-6f);
    EXPECT_NEAR(w[2], 0.0f, 1e-6f);
    EXPECT_THROW(viewWith("torque: T: 0,0,0 E: 1\n"), simeco::ir::InputError);
}

TEST_F(CpfgView, TheFirstDirectionalLightIsTheSunAndTheInitialScaleTheTurtles) {
    EXPECT_FALSE(viewWith("angle increment: 30\n").look.sunDirection);
    auto sun = [&](const std::string& view) {
        return viewWith(view).look.sunDirection.value_or(std::array{9.f, 9.f, 9.f});
    };
    EXPECT_EQ(sun("light: V: 0,0,2 A: 0.2 0.2 0.2\nlight: V: 1 0 0\n"), (std::array{0.f, 0.f, 1.f}));
    EXPECT_EQ(sun("light: O: 1 2 3\nlight direction: 3.0,0,4.0\n"), (std::array{0.6f, 0.f, 0.8f}));
    EXPECT_FLOAT_EQ(viewWith("").initialScale, 1.0f);
    EXPECT_FLOAT_EQ(viewWith("initial scale: 2.5\n").initialScale, 2.5f);
    EXPECT_FLOAT_EQ(viewWith("initial scale: 0\n").initialScale, 1.0f); // as cpfg
}

TEST_F(CpfgView, LineStyleFollowsTheViewAsCpfgReadsIt) {
    using simeco::ir::LineStyle;
    auto styleWith = [&](const std::string& view) { return viewWith(view).lineStyle; };
    EXPECT_EQ(styleWith(""), LineStyle::Pixel); // cpfg's default
    EXPECT_EQ(styleWith("angle increment: 30\n"), LineStyle::Pixel);
    EXPECT_EQ(styleWith("initial line width: 2\n"), LineStyle::Polygon);
    EXPECT_EQ(styleWith("initial line width: 0.5 /* world space units */\n"), LineStyle::Polygon);
    EXPECT_EQ(styleWith("initial line width: 2 pixels\n"), LineStyle::Pixel);
    EXPECT_EQ(styleWith("initial line width: 2 p\n"), LineStyle::Pixel);
    EXPECT_EQ(styleWith("initial line width: 2 s\n"), LineStyle::Cylinder);
    // The last word read wins.
    EXPECT_EQ(styleWith("initial line width: 2 pixels\nline style: cylinder\n"), LineStyle::Cylinder);
    EXPECT_EQ(styleWith("line style: polygon\ninitial line width: 2 pixels\n"), LineStyle::Pixel);
}

TEST_F(CpfgView, ViewLinesSayHowThePictureLooks) {
    using simeco::ir::Background;
    auto lookWith = [&](const std::string& view) { return viewWith(view).look; };
    simeco::ir::PictureLook none = lookWith("angle increment: 30\n");
    EXPECT_FALSE(none.style || none.shadows || none.ground || none.background || none.viewpoint ||
                 none.viewReferencePoint || none.parallel);

    simeco::ir::PictureLook look = lookWith("render style: paper-cut\nground: off\nbackground: #ff0000\n"
                                            "viewpoint: 0,0,-1\nview reference point: 1, 2, 3\nshadows: none\n");
    EXPECT_EQ(look.style, simeco::ir::PictureStyle::PaperCut);
    EXPECT_EQ(look.shadows, false);
    EXPECT_EQ(lookWith("shadows: volume\n").shadows, true);
    EXPECT_EQ(lookWith("projection: parallel\n").parallel, true);
    EXPECT_EQ(lookWith("projection: perspective\n").parallel, false);
    EXPECT_EQ(look.ground, false);
    ASSERT_TRUE(look.background);
    EXPECT_EQ(look.background->kind, Background::Kind::Color);
    EXPECT_FLOAT_EQ(look.background->color[0], 1.0f); // sRGB ff is linear 1; 00 is 0
    EXPECT_FLOAT_EQ(look.background->color[1], 0.0f);
    EXPECT_EQ(look.viewpoint, (std::array<float, 3>{0, 0, -1}));
    EXPECT_EQ(look.viewReferencePoint, (std::array<float, 3>{1, 2, 3}));
    EXPECT_EQ(lookWith("background: paper\n").background->kind, Background::Kind::Paper);
    EXPECT_EQ(lookWith("background: colormap\n").background->kind, Background::Kind::Colormap);
    EXPECT_EQ(lookWith("render style: outline\n").style, simeco::ir::PictureStyle::Outline);

    // A value none of those a line takes: the error points at it.
    struct Bad {
        std::string view;
        int line, col;
    };
    for (const Bad& bad : {Bad{"render style: sketchy\n", 1, 15}, Bad{"angle increment: 9\nground:  maybe\n", 2, 10},
                           Bad{"background: #12345\n", 1, 13}, Bad{"shadows: soft\n", 1, 10},
                           Bad{"projection: fisheye\n", 1, 13}}) {
        SCOPED_TRACE(bad.view);
        try {
            viewWith(bad.view);
            ADD_FAILURE() << "no error";
        } catch (const simeco::ir::InputError& e) {
            EXPECT_EQ(e.loc().file, (dir_ / "m.v").string());
            EXPECT_EQ(e.loc().line, bad.line);
            EXPECT_EQ(e.loc().col, bad.col);
        }
    }
}

} // namespace
