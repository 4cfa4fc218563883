// The seed documents' scripts and the quick-grammar examples, derived end to end by the CPU engine.
#include <gtest/gtest.h>

#include <filesystem>

#include "cpu/derive.h"
#include "lang/eco_parser.h"
#include "lang/load_grammar.h"

namespace {

namespace fs = std::filesystem;

uint64_t derivedModules(const simeco::ir::Grammar& g, int64_t seed = -1) {
    simeco::stream::DeriveOptions options;
    options.seed = seed;
    return simeco::cpu::deriveCpu(g, options).string.size();
}

TEST(SeedScripts, EveryPlantOfTheSeedScenesDerives) {
    fs::path dir = fs::path(SIMECO_SHARED_DIR) / "seed-scripts";
    int scenes = 0;
    for (const char* name : {"lantana-camara.eco", "rosa-rugosa.eco", "oxalis-corniculata.eco", "lgrammar-testplant.eco"}) {
        fs::path file = dir / name;
        ASSERT_TRUE(fs::exists(file)) << file;
        simeco::ir::EcoScene scene = simeco::lang::parseEcoFile(file.string());
        ASSERT_FALSE(scene.plants.empty()) << name;
        for (size_t p = 0; p < scene.plants.size(); ++p) {
            simeco::ir::Grammar g = simeco::lang::compileEcoPlant(scene, p);
            simeco::stream::DeriveResult r = simeco::cpu::deriveCpu(g, {});
            // Growth: the plant has more modules than its axiom, with balanced branches.
            EXPECT_GT(r.string.size(), g.axiom.size()) << name;
            int depth = 0;
            for (uint32_t s : r.string.sym) {
                depth += s == simeco::ir::kBranchOpen ? 1 : s == simeco::ir::kBranchClose ? -1 : 0;
                ASSERT_GE(depth, 0) << name;
            }
            EXPECT_EQ(depth, 0) << name;
        }
        ++scenes;
    }
    EXPECT_EQ(scenes, 4);
}

TEST(SeedScripts, StochasticPlantsRepeatForASeed) {
    fs::path file = fs::path(SIMECO_SHARED_DIR) / "seed-scripts" / "rosa-rugosa.eco";
    simeco::ir::Grammar g = simeco::lang::compileEcoPlant(simeco::lang::parseEcoFile(file.string()), 0);
    simeco::stream::DeriveOptions options;
    options.seed = 5;
    simeco::stream::DeriveResult a = simeco::cpu::deriveCpu(g, options), b = simeco::cpu::deriveCpu(g, options);
    EXPECT_EQ(a.string.sym, b.string.sym);
    EXPECT_EQ(a.string.params, b.string.params);
}

// Module counts (brackets included) worked out by plain string rewriting, independently of simeco:
// F=F[-XF]F, X=F[X] from F, 3 steps: 100 modules; the ABOP 1.24d tree from X, 7 steps: 13956.
TEST(QuickGrammarExamples, DeriveToTheirKnownLengths) {
    fs::path dir = fs::path(SIMECO_SOURCE_DIR) / "grammars" / "houdini";
    ASSERT_TRUE(fs::exists(dir / "rectangular-path.lsys"));
    ASSERT_TRUE(fs::exists(dir / "abop-1.24d-tree.lsys"));
    EXPECT_EQ(derivedModules(simeco::lang::loadGrammarFile((dir / "rectangular-path.lsys").string())), 100u);
    EXPECT_EQ(derivedModules(simeco::lang::loadGrammarFile((dir / "abop-1.24d-tree.lsys").string())), 13956u);
}

} // namespace
