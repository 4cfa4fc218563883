// The grammars shipped under grammars/abop, grammars/clouds and grammars/cpfg: each loads with its view file, derives,
// and grows to the size worked out without simeco.
//
// Where the expected numbers come from:
// - Figures 1.24 a-f are D0L systems. Their strings are rebuilt here by plain character replacement
//   (rewriteD0L below), and the module counts are the closed forms: for F -> w with k F's and m other
//   symbols, |w_n| = 1 + (|w| - 1)(k^n - 1)/(k - 1); for X -> u, F -> FF, X_n = k^n, F_n = 2F_{n-1} + f X_{n-1}
//   and the other symbols grow by m X_{n-1} a step (worked out per figure next to the table).
// - Figures 1.31 a-e were derived by a separate Python script: bracketed context-sensitive rewriting as
//   ABOP section 1.8 and the cpfg manual describe it (ignored symbols skipped; on the way left a `[` is
//   passed and a closed branch skipped; on the way right a branch is skipped and a `]` ends the context;
//   first matching production wins; no match copies the module). Its step-5 word of figure 1.31a,
//   F1F1F1F1[-F0F1]F1, also agrees with the derivation worked by hand.
// - Figures 2.6-2.8: the branching structure does not depend on the parameters (no conditions), so the
//   counts follow from the apex recurrences given next to each test, checked by the same script with the
//   parameters dropped; parameter values are the book's products (200 * 1.109^6, ...).
// - The stochastic figure 1.27 variant: bounds and invariants that hold for every choice of successors.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "cpu/derive.h"
#include "lang/load_grammar.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_settings.h"

namespace simeco {
namespace {

const std::string kGrammarDir = std::string(SIMECO_SOURCE_DIR) + "/grammars/";

struct Derived {
    ir::Grammar grammar;
    stream::DeriveResult result;
    std::string text; // cpfg notation

    size_t modules() const { return result.string.size(); }
    std::string name(size_t i) const { return grammar.alphabet.name(result.string.sym[i]); }
    size_t count(const std::string& symbol) const {
        size_t n = 0;
        for (size_t i = 0; i < modules(); ++i)
            n += name(i) == symbol;
        return n;
    }
};

// Loads grammars/<relative> (failing when the file or the view file it finds is missing) and derives it.
void derive(const std::string& relative, Derived& out, int steps = -1, int64_t seed = -1) {
    std::string path = kGrammarDir + relative;
    ASSERT_TRUE(std::filesystem::is_regular_file(path)) << path << " is missing";
    ASSERT_FALSE(lang::findViewFile(path).empty()) << path << " has no view file";
    out.grammar = lang::loadGrammarFile(path);
    stream::DeriveOptions options;
    options.steps = steps;
    options.seed = seed;
    out.result = cpu::deriveCpu(out.grammar, options);
    out.text = stream::formatModules(out.result.string, out.grammar.alphabet, 0, out.result.string.size());
}

// Plain D0L rewriting of one-character symbols, independent of simeco's engine.
std::string rewriteD0L(std::string word, const std::map<char, std::string>& rules, int steps) {
    for (int i = 0; i < steps; ++i) {
        std::string next;
        for (char c : word) {
            auto it = rules.find(c);
            next += it == rules.end() ? std::string(1, c) : it->second;
        }
        word = std::move(next);
    }
    return word;
}

// ---- figures 1.24 a-f: bracketed OL-systems ----------------------------------------------------

struct BracketedPlant {
    const char* file;
    const char* axiom;
    std::map<char, std::string> rules;
    int steps;
    float angle;
    size_t modules;
    size_t f;
};

// a) F -> F[+F]F[-F]F, 5 F of 11:           1 + 10 (5^5 - 1)/4 = 7811, F = 5^5 = 3125
// b) F -> F[+F]F[-F][F], 5 F of 13:         1 + 12 (5^5 - 1)/4 = 9373
// c) F -> FF-[-F+F+F]+[+F-F-F], 8 F of 20:  1 + 19 (8^4 - 1)/7 = 11116, F = 8^4 = 4096
// d) X -> F[+X]F[-X]+X (2 F, 3 X, 7 others), F -> FF: X = 3^7 = 2187, F = 2(3^7 - 2^7) = 4118,
//    others 7 (3^7 - 1)/2 = 7651: 13956
// e) X -> F[+X][-X]FX (2 F, 3 X, 6 others): 2187 + 4118 + 6 * 1093 = 12863
// f) X -> F-[[X]+X]+F[+FX]-X (3 F, 4 X, 11 others), n=5: X = 4^5 = 1024, F = 3(4^5 - 2^5)/2 = 1488,
//    others 11 (4^5 - 1)/3 = 3751: 6263
const std::vector<BracketedPlant> kBracketedPlants = {
    {"abop/fig1.24a.l", "F", {{'F', "F[+F]F[-F]F"}}, 5, 25.7f, 7811, 3125},
    {"abop/fig1.24b.l", "F", {{'F', "F[+F]F[-F][F]"}}, 5, 20.0f, 9373, 3125},
    {"abop/fig1.24c.l", "F", {{'F', "FF-[-F+F+F]+[+F-F-F]"}}, 4, 22.5f, 11116, 4096},
    {"abop/fig1.24d.l", "X", {{'X', "F[+X]F[-X]+X"}, {'F', "FF"}}, 7, 20.0f, 13956, 4118},
    {"abop/fig1.24e.l", "X", {{'X', "F[+X][-X]FX"}, {'F', "FF"}}, 7, 25.7f, 12863, 4118},
    {"abop/fig1.24f.l", "X", {{'X', "F-[[X]+X]+F[+FX]-X"}, {'F', "FF"}}, 5, 22.5f, 6263, 1488},
};

TEST(ShippedGrammars, BracketedPlantsOfFigure1_24) {
    for (const BracketedPlant& plant : kBracketedPlants) {
        SCOPED_TRACE(plant.file);
        Derived d;
        ASSERT_NO_FATAL_FAILURE(derive(plant.file, d));
        EXPECT_EQ(d.grammar.derivationLength, plant.steps);
        EXPECT_TRUE(d.grammar.view.present);
        EXPECT_FLOAT_EQ(d.grammar.view.angleIncrement, plant.angle);
        EXPECT_EQ(d.result.steps, plant.steps);
        EXPECT_EQ(d.modules(), plant.modules);
        EXPECT_EQ(d.count("F"), plant.f);
        EXPECT_EQ(d.text, rewriteD0L(plant.axiom, plant.rules, plant.steps));
    }
}

// ---- figures 1.31 a-e: context-sensitive plants (Hogeweg and Hesper) -----------------------------

struct SignalPlant {
    const char* file;
    int steps;
    float angle;
    size_t modules;
    size_t f, zeros, ones, branches;
    const char* prefix;
};

// Derived by the Python reference described at the top of this file.
const std::vector<SignalPlant> kSignalPlants = {
    {"abop/fig1.31a.l", 30, 22.5f, 6910, 2501, 762, 1739, 636, "F1F0F0F0[+F1F1F1F1]F0[-F1F0F0F1][+F1F1F1"},
    {"abop/fig1.31b.l", 30, 22.5f, 19199, 5626, 2060, 3566, 2649, "F1F0F0F0[-F1F1F1]F1F1F1F1[+F0[+F0F1][+F0"},
    {"abop/fig1.31c.l", 26, 25.75f, 2926, 944, 228, 716, 346, "F1F0F1F1[+F1F1][-F0F1]F0[-F0F1]F0[+F1F1]"},
    {"abop/fig1.31d.l", 24, 25.75f, 5789, 1924, 456, 1468, 647, "F0F1F1F0F0F0F1F1[+F1F1]F1F1F1F1[+F0F1]F1"},
    {"abop/fig1.31e.l", 26, 22.5f, 2428, 824, 191, 633, 260, "F1F1F1F1[+F0F1]F1[-F0F1[-F1F1]F1]F0F1[-F"},
};

TEST(ShippedGrammars, ContextSensitivePlantsOfFigure1_31) {
    for (const SignalPlant& plant : kSignalPlants) {
        SCOPED_TRACE(plant.file);
        Derived d;
        ASSERT_NO_FATAL_FAILURE(derive(plant.file, d));
        EXPECT_EQ(d.grammar.derivationLength, plant.steps);
        EXPECT_FLOAT_EQ(d.grammar.view.angleIncrement, plant.angle);
        EXPECT_EQ(d.modules(), plant.modules);
        EXPECT_EQ(d.count("F"), plant.f);
        EXPECT_EQ(d.count("0"), plant.zeros);
        EXPECT_EQ(d.count("1"), plant.ones);
        EXPECT_EQ(d.count("["), plant.branches);
        EXPECT_EQ(d.count("]"), plant.branches);
        EXPECT_EQ(d.text.substr(0, std::string(plant.prefix).size()), plant.prefix);
    }
}

TEST(ShippedGrammars, Figure1_31aEarlyStepsAsWorkedByHand) {
    // Step by step from F1F1F1 (the + and - swap every step): F1F0F1, F1F1F1F1, F1F0F0F1,
    // F1F0F1[+F1F1]F1, F1F1F1F1[-F0F1]F1.
    const char* words[] = {"F1F1F1", "F1F0F1", "F1F1F1F1", "F1F0F0F1", "F1F0F1[+F1F1]F1", "F1F1F1F1[-F0F1]F1"};
    for (int step = 0; step <= 5; ++step) {
        Derived d;
        ASSERT_NO_FATAL_FAILURE(derive("abop/fig1.31a.l", d, step));
        EXPECT_EQ(d.text, words[step]) << "step " << step;
    }
}

// ---- figures 2.6-2.8: parametric trees ---------------------------------------------------------

TEST(ShippedGrammars, MonopodialTreeOfFigure2_6) {
    // Apices A, B, C double every step (A -> A + B, B -> 2 C, C -> 2 B) and each rewritten apex adds 7
    // modules, a B or C one more for its `@` `v` (all but the trunk's 10): 1 + 7 (2^10 - 1) + 1013 = 8175; every
    // apex rewrite leaves one ! and one F: 1023 of each.
    Derived d;
    ASSERT_NO_FATAL_FAILURE(derive("abop/fig2.6-monopodial.l", d));
    EXPECT_EQ(d.grammar.derivationLength, 10);
    EXPECT_EQ(d.modules(), 8175u);
    EXPECT_EQ(d.count("v"), 1013u);
    EXPECT_EQ(d.count("A"), 1u);
    EXPECT_EQ(d.count("B") + d.count("C"), 1023u);
    EXPECT_EQ(d.count("F"), 1023u);
    EXPECT_EQ(d.count("!"), 1023u);
    EXPECT_EQ(d.count("/"), 10u);
    // The trunk starts with !(10)F(1) and ends in the apex A(0.9^10, 10 * 0.707^10).
    ASSERT_GE(d.modules(), 2u);
    EXPECT_EQ(d.name(0), "!");
    EXPECT_FLOAT_EQ(d.result.string.paramsOf(0)[0], 10.0f);
    EXPECT_EQ(d.name(1), "F");
    EXPECT_FLOAT_EQ(d.result.string.paramsOf(1)[0], 1.0f);
    EXPECT_EQ(d.text.substr(0, 5), "!(10)");
    EXPECT_EQ(d.name(d.modules() - 1), "A");
    EXPECT_NEAR(d.result.string.paramsOf(d.modules() - 1)[0], std::pow(0.9, 10), 1e-5);
    EXPECT_NEAR(d.result.string.paramsOf(d.modules() - 1)[1], 10 * std::pow(0.707, 10), 1e-4);
}

TEST(ShippedGrammars, SympodialTreeOfFigure2_7) {
    // A -> 11 modules with 2 B; B -> 14 modules with 2 B (two `@` `v`): 11 + 13 (2 + 4 + ... + 2^9) = 13297.
    Derived d;
    ASSERT_NO_FATAL_FAILURE(derive("abop/fig2.7-sympodial.l", d));
    EXPECT_EQ(d.grammar.derivationLength, 10);
    EXPECT_EQ(d.modules(), 13297u);
    EXPECT_EQ(d.count("B"), 1024u);
    EXPECT_EQ(d.count("F"), 1023u);
    EXPECT_EQ(d.count("v"), 2044u);
    EXPECT_EQ(d.count("["), 2046u);
}

TEST(ShippedGrammars, TernaryTreeOfFigure2_8) {
    // Axiom of 4 modules; A -> 19 modules with 3 A: 4 + 18 (3^6 - 1)/2 = 6556, A = 3^6 = 729.
    Derived d;
    ASSERT_NO_FATAL_FAILURE(derive("abop/fig2.8-ternary.l", d));
    EXPECT_EQ(d.grammar.derivationLength, 6);
    EXPECT_EQ(d.modules(), 6556u);
    EXPECT_EQ(d.count("A"), 729u);
    EXPECT_EQ(d.count("F"), 1457u);
    EXPECT_EQ(d.count("!"), 365u);
    EXPECT_EQ(d.count("&"), 1092u);
    // The trunk keeps thickening and elongating: !(1.732^6) F(200 * 1.109^6).
    ASSERT_GE(d.modules(), 2u);
    EXPECT_EQ(d.name(0), "!");
    EXPECT_NEAR(d.result.string.paramsOf(0)[0], std::pow(1.732, 6), 1e-3);
    EXPECT_EQ(d.name(1), "F");
    EXPECT_NEAR(d.result.string.paramsOf(1)[0], 200 * std::pow(1.109, 6), 1e-2);
}

// ---- figure 1.27: stochastic ------------------------------------------------------------------

// Every F takes F[+F]F[-F]F (4 new F, 2 branches) or F[+F]F / F[-F]F (2 new F, 1 branch), so with B
// branches the word has 2B + 1 F and 5B + 1 modules; all-short gives 1 + 5 (3^5 - 1)/2 = 606, all-long
// 1 + 10 (5^5 - 1)/4 = 7811.
void expectStochasticInvariants(const Derived& d) {
    size_t branches = d.count("[");
    EXPECT_EQ(d.count("]"), branches);
    EXPECT_EQ(d.count("+") + d.count("-"), branches);
    EXPECT_EQ(d.count("F"), 2 * branches + 1);
    EXPECT_EQ(d.modules(), 5 * branches + 1);
    EXPECT_GE(d.modules(), 606u);
    EXPECT_LE(d.modules(), 7811u);
}

TEST(ShippedGrammars, StochasticPlantOfFigure1_27) {
    const char* file = "abop/fig1.27-stochastic.l";
    Derived fromFile, again, seedOne;
    ASSERT_NO_FATAL_FAILURE(derive(file, fromFile));
    ASSERT_NO_FATAL_FAILURE(derive(file, again));
    ASSERT_NO_FATAL_FAILURE(derive(file, seedOne, -1, 1));
    EXPECT_EQ(fromFile.grammar.seed, 1u);
    EXPECT_EQ(fromFile.grammar.derivationLength, 5);
    EXPECT_FLOAT_EQ(fromFile.grammar.view.angleIncrement, 25.7f);
    EXPECT_EQ(fromFile.text, again.text);
    EXPECT_EQ(fromFile.text, seedOne.text); // the file's `seed: 1`
    expectStochasticInvariants(fromFile);

    std::set<std::string> words = {fromFile.text};
    for (int64_t seed = 2; seed <= 6; ++seed) {
        SCOPED_TRACE(seed);
        Derived d;
        ASSERT_NO_FATAL_FAILURE(derive(file, d, -1, seed));
        expectStochasticInvariants(d);
        words.insert(d.text);
    }
    EXPECT_GE(words.size(), 4u) << "different seeds should give different plants";
}

// ---- the oriental clouds ---------------------------------------------------------------------------

TEST(ShippedGrammars, OrientalClouds) {
    // Axiom Cloud1(2,1,1,1): structure SYM 2 puts one C1-A cloud on each side; a C1-A cloud lays 5
    // spheres O on its spiral, then curls its end (C1Aend_e) and grows a tail.
    Derived d;
    ASSERT_NO_FATAL_FAILURE(derive("clouds/oriental-clouds.l", d, -1, 7));
    EXPECT_EQ(d.grammar.derivationLength, 25);
    EXPECT_EQ(d.result.steps, 25);
    EXPECT_TRUE(d.grammar.homomorphism.present);
    EXPECT_EQ(d.count("O"), 10u);
    EXPECT_GE(d.count("@"), 10u);
    EXPECT_EQ(d.count("C1Aend_e"), 2u);
    EXPECT_EQ(d.count("milt-tail"), 2u);
    EXPECT_EQ(d.count("["), d.count("]"));
    // Nothing of the construction is left over: every cloud and structure call has been expanded.
    for (const char* gone : {"Cloud1", "C", "C1A", "C1Aend"})
        EXPECT_EQ(d.count(gone), 0u) << gone;
    // Spheres start at 2.5 and grow by `ori` every step, and C1-A adds ran(0.5) to each next one.
    for (size_t i = 0; i < d.modules(); ++i) {
        if (d.name(i) != "O") continue;
        float radius = d.result.string.paramsOf(i)[0];
        EXPECT_GT(radius, 2.5f);
        EXPECT_LT(radius, 2.5f + 4 * 0.5f + 25 * 0.07f + 1e-3f);
    }
}

TEST(ShippedGrammars, EveryCpfgModelLoadsWithItsViewFile) {
    size_t found = 0;
    for (const char* dir : {"abop", "clouds", "cpfg"}) {
        std::filesystem::path folder = kGrammarDir + dir;
        ASSERT_TRUE(std::filesystem::is_directory(folder)) << folder;
        for (const auto& entry : std::filesystem::directory_iterator(folder)) {
            if (entry.path().extension() != ".l") continue;
            SCOPED_TRACE(entry.path().string());
            ++found;
            EXPECT_FALSE(lang::findViewFile(entry.path().string()).empty());
            ir::Grammar g = lang::loadGrammarFile(entry.path().string());
            EXPECT_TRUE(g.view.present);
            EXPECT_GT(g.derivationLength, 0);
        }
    }
    // Figures 1.24 a-f, 1.27, 1.31 a-e, 2.6, 2.7, 2.8; the clouds' example and the library's 28 parts; the herb,
    // the tulip leaves and the sedge.
    EXPECT_EQ(found, 15u + 29u + 3u);
}

// Every part of the cloud library derives to something drawn, and looks as the library's view says: outlined, on
// the colour map's background, without a ground or cast shadows, seen from the front in parallel as cpfg shows it.
TEST(ShippedGrammars, TheCloudLibrarysPartsDeriveAndShareItsLook) {
    size_t parts = 0;
    for (const auto& entry : std::filesystem::directory_iterator(kGrammarDir + "clouds")) {
        if (entry.path().extension() != ".l") continue;
        const std::string name = entry.path().filename().string();
        SCOPED_TRACE(name);
        ++parts;
        Derived d;
        ASSERT_NO_FATAL_FAILURE(derive("clouds/" + name, d, -1, 1));
        EXPECT_EQ(d.result.steps, d.grammar.derivationLength);
        EXPECT_EQ(d.count("["), d.count("]"));
        // Spheres (`@O`) or generalized cylinders (`@Gc`): something of the cloud is drawn.
        EXPECT_GT(d.count("@"), 0u);
        const ir::PictureLook& look = d.grammar.view.look;
        EXPECT_EQ(look.style, ir::PictureStyle::Outline);
        EXPECT_EQ(look.ground, false);
        EXPECT_EQ(look.shadows, false);
        ASSERT_TRUE(look.background);
        EXPECT_EQ(look.background->kind, ir::Background::Kind::Colormap);
        EXPECT_EQ(look.viewpoint, (std::array<float, 3>{0, 0, 1}));
        EXPECT_EQ(look.parallel, true);
        ASSERT_EQ(d.grammar.view.palette.size(), 256u); // clouds.map
    }
    EXPECT_EQ(parts, 29u);
}

// The herb draws its sixteen leaves and five petals from its two surfaces, the leaves largest half way up.
TEST(ShippedGrammars, TheHerbDrawsItsLeavesAndPetalsFromItsSurfaces) {
    ir::DrawAssets assets;
    const ir::Grammar g = lang::loadSpecies(kGrammarDir + "cpfg/herb.l", nullptr, &assets).front();
    ASSERT_EQ(assets.models.size(), 2u); // leaf.s and petal.s
    const stream::ModuleString string = cpu::deriveCpu(g, {}).string;
    const turtle::Interpretation r =
        turtle::interpretCpu(string, turtle::turtleCommands(g.alphabet), {turtle::turtleSettings(g, g.alphabet)});
    std::map<uint32_t, std::vector<float>> lengthsByShape;
    for (uint32_t k = 0; k < r.count[shared::kOrganLeaf]; ++k) {
        const shared::OrganInstance& o = r.organs[r.first[shared::kOrganLeaf] + k];
        lengthsByShape[o.shape].push_back(o.position.w);
    }
    const std::vector<float>& leaves = lengthsByShape[shared::kSurfaceLastShape + 1];
    ASSERT_EQ(leaves.size(), 16u);
    EXPECT_EQ(lengthsByShape[shared::kSurfaceLastShape + 2].size(), 5u);
    // In pairs from the ground: the largest pair at node 4 of 8, and larger than node 0's by half.
    const size_t largest = size_t(std::max_element(leaves.begin(), leaves.end()) - leaves.begin());
    EXPECT_TRUE(largest == 8 || largest == 9) << largest;
    EXPECT_GT(leaves[8], 1.5f * leaves[0]);
}

} // namespace
} // namespace simeco
