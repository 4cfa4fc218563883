// Plants of different species in one stream, and plants that stop at different steps: the GPU derives them in
// the same passes and must give the CPU reference's strings, plant by plant.
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../unit/grammar_text.h"
#include "codegen/derive_codegen.h"
#include "codegen/species_classes.h"
#include "compare_strings.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/species.h"
#include "lang/eco_parser.h"
#include "lang/load_grammar.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = fs::path(SIMECO_SOURCE_DIR);
const fs::path kCorpusModels = fs::path(SIMECO_SHARED_DIR) / "corpus" / "cpfg-vlab" / "models";

using SpeciesGpuTest = GpuTest;

std::string plantText(const stream::DeriveResult& r, const ir::Alphabet& alphabet, std::size_t plant) {
    const stream::ModuleString& s = r.string;
    return stream::formatModules(s, alphabet, s.plantStart[plant], s.plantStart[plant + 1]);
}

// Derives `species` with `plants` plants on both engines and expects the same strings (under the homomorphism
// too, when asked).
void expectEnginesAgree(const vk::Context& context, const std::vector<ir::Grammar>& species, std::uint32_t plants,
                        bool homomorphism = false) {
    SCOPED_TRACE(std::to_string(plants) + " plants" + (homomorphism ? ", under the homomorphism" : ""));
    stream::DeriveOptions options;
    options.plants = plants;
    options.homomorphism = homomorphism;
    stream::DeriveResult want = cpu::deriveSpeciesCpu(species, options);
    ASSERT_EQ(want.string.plants(), plants);
    gpu::GpuDeriver deriver(context, species);
    ASSERT_TRUE(!homomorphism || deriver.appliesHomomorphism());
    EXPECT_EQ(firstDifference(want, deriver.derive(options), species.front().alphabet), "");
}

// An ecosystem's species, several of them copies of one another: a decomposition with a homomorphism (cpfg
// corpus), a func() table (corpus), a context filter (ABOP 1.31a, which ignores + - F), the same filter's
// grammar with another derivation length, which the host alone reads, and the decomposition's grammar without
// its productions, whose homomorphism is still the first one's: the homomorphism's kernels class the species
// otherwise than the derivation's.
std::vector<ir::Grammar> speciesWithCopies() {
    ir::Grammar decomposed = lang::loadGrammarFile((kCorpusModels / "01-Introduction" / "09-continuous-decomp" /
                                                    "leaf.l").string());
    ir::Grammar tabled = lang::loadGrammarFile((kCorpusModels / "02-Mod-vis-3D" / "05-monopodial" / "leaf.l").string());
    ir::Grammar filtered = lang::loadGrammarFile((kSource / "grammars" / "abop" / "fig1.31a.l").string());
    ir::Grammar shorter = filtered;
    shorter.derivationLength -= 3;
    ir::Grammar unproductive = decomposed;
    unproductive.productions = ir::RuleSet{};
    return ir::unifySpecies({decomposed, tabled, filtered, decomposed, shorter, unproductive, tabled, decomposed});
}

// Copies of a species share its code: one class each, whatever their place among the species. Species that differ
// only in the numbers of their productions share it too, the numbers that differ read from each species' row; a
// species whose code differs otherwise is a class of its own.
TEST(SpeciesClasses, CopiesAndSpeciesThatDifferInNumbersShareTheirCode) {
    std::vector<ir::Grammar> species = speciesWithCopies();
    codegen::SpeciesClasses classes = codegen::classifySpecies(species);
    EXPECT_EQ(classes.classOf, (std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3, 1, 0}));
    ASSERT_EQ(classes.representatives.size(), 4u);
    EXPECT_FALSE(classes.distinct());
    EXPECT_FALSE(classes.hoists());

    auto grammar = [](const std::string& successor) {
        return simeco::testing::grammarFromText("Lsystem: 1\nderivation length: 4\nAxiom: A(1)\nA(x) --> " + successor +
                                                "\nendlsystem\n");
    };
    ir::Grammar g = grammar("F(x)[+(30)A(x * 0.5)]A(x * 0.5)");
    ir::Grammar other = grammar("F(x)[+(30)A(x * 0.5)]A(x * 0.6)");
    ir::Grammar shaped = grammar("F(x)[+(30)A(x * 0.5)]A(x * 0.5 + 1)");
    classes = codegen::classifySpecies(ir::unifySpecies({g, other, g, shaped}));
    EXPECT_EQ(classes.classOf, (std::vector<std::uint32_t>{0, 0, 0, 1}));
    ASSERT_EQ(classes.hoisted.size(), 4u);
    EXPECT_EQ(classes.hoisted[0], std::vector<double>{0.5});
    EXPECT_EQ(classes.hoisted[1], std::vector<double>{0.6});
    EXPECT_EQ(classes.hoisted[2], std::vector<double>{0.5});
    EXPECT_TRUE(classes.hoisted[3].empty()) << "a class of one species keeps its numbers in its code";
}

// The kernels' size follows the distinct rules, not the species: thirty copies of three species generate
// kernels about as large as the three do (a table of classes aside).
TEST(SpeciesClasses, KernelsGrowWithDistinctRulesNotWithSpecies) {
    std::vector<ir::Grammar> three = speciesWithCopies(); // distinct species
    three.resize(3);
    std::vector<ir::Grammar> thirty;
    for (int copy = 0; copy < 10; ++copy) thirty.insert(thirty.end(), three.begin(), three.end());
    codegen::GeneratedKernels few = codegen::generateDeriveKernels(three, true);
    codegen::GeneratedKernels many = codegen::generateDeriveKernels(thirty, true);
    using K = codegen::GeneratedKernels;
    for (auto kernel : {&K::match, &K::write, &K::decompositionMatch, &K::decompositionWrite}) {
        ASSERT_GT((few.*kernel).size(), 1000u);
        EXPECT_LT((many.*kernel).size(), (few.*kernel).size() + 200);
    }
    EXPECT_EQ(many.errors.size(), few.errors.size());
    EXPECT_EQ(many.functionTables, few.functionTables);
    EXPECT_EQ(many.speciesTable.size(), few.speciesTable.size() + thirty.size());
}

// Plants of species that share code derive as the CPU reference derives each species, with each class's
// func() tables, context filter and decomposition, and under each class's homomorphism.
TEST_F(SpeciesGpuTest, SpeciesThatShareCodeDeriveAsTheirOwn) {
    std::vector<ir::Grammar> species = speciesWithCopies();
    for (std::uint32_t plants : {8u, 19u}) expectEnginesAgree(context(), species, plants);
    expectEnginesAgree(context(), species, 8, true);
}

// Species that differ only in numbers, in conditions that guard context walks, successors, statements and a
// decomposition, derive as their own on both strategies, through one class's code.
TEST_F(SpeciesGpuTest, SpeciesThatDifferInNumbersDeriveAsTheirOwn) {
    auto variant = [](double angle, double threshold, double rate) {
        return simeco::testing::grammarFromText(fmt::format(
            "Lsystem: 1\nderivation length: 6\nAxiom: B(1)A(1)\n"
            "A(x) : x < {1} --> F(x)[+({0})A(x * {2})]A(x + {2})\n"
            "B(y) < A(x) : x > {1} && y < 4 --> A(x - 1)B(y + {2})\n"
            "A(x) : {{ z = x * {2}; }} x > 0 --> A(z)\n"
            "B(y) --> B(y - {2})\n"
            "decomposition\nmaximum depth: 2\n"
            "F(l) : l > {1} / 2 --> F(l / 2)F(l / 2)\nendlsystem\n",
            angle, threshold, rate));
    };
    std::vector<ir::Grammar> species = ir::unifySpecies(
        {variant(30, 2, 0.5), variant(45, 3, 0.75), variant(30, 2, 0.5), variant(25.5, 1.5, 0.25), variant(60, 4, 1)});
    codegen::SpeciesClasses classes = codegen::classifySpecies(species);
    ASSERT_EQ(classes.representatives.size(), 1u);
    ASSERT_TRUE(classes.hoists());
    for (std::uint32_t plants : {5u, 13u}) expectEnginesAgree(context(), species, plants);
    stream::DeriveOptions options;
    options.plants = 10;
    stream::DeriveResult want = cpu::deriveSpeciesCpu(species, options);
    gpu::GpuDeriver sequential(context(), species, gpu::GpuStrategy::Sequential);
    EXPECT_EQ(firstDifference(want, sequential.derive(options), species.front().alphabet), "") << "sequentially";
    // Each plant's branches turn by its own species' angle.
    const char* angles[] = {"+(30)", "+(45)", "+(30)", "+(25.5)", "+(60)"};
    for (std::size_t p = 0; p < 5; ++p)
        EXPECT_NE(plantText(want, species.front().alphabet, p).find(angles[p]), std::string::npos) << "plant " << p;
}

TEST_F(SpeciesGpuTest, SceneSpeciesDeriveInOnePass) {
    ir::EcoScene scene = lang::parseEcoFile((kSource / "scenes" / "garden.eco").string());
    ASSERT_EQ(scene.plants.size(), 3u);
    std::vector<ir::Grammar> grammars;
    for (std::size_t i = 0; i < scene.plants.size(); ++i) grammars.push_back(lang::compileEcoPlant(scene, i));
    std::vector<ir::Grammar> species = ir::unifySpecies(grammars);

    // The species really differ: three distinct strings, and rules that are not all alike.
    stream::DeriveOptions three;
    three.plants = 3;
    stream::DeriveResult r = cpu::deriveSpeciesCpu(species, three);
    std::set<std::string> distinct;
    for (std::size_t p = 0; p < 3; ++p) distinct.insert(plantText(r, species.front().alphabet, p));
    EXPECT_EQ(distinct.size(), 3u);
    for (std::uint32_t plants : {3u, 301u}) expectEnginesAgree(context(), species, plants);
}

// cpfg models with different alphabets, derivation lengths (7, 10, 30) and context filters (1.31a ignores
// + - F): each plant derives its own length and matches context with its own filter.
TEST_F(SpeciesGpuTest, CpfgModelsOfDifferentLengthsShareTheStream) {
    std::vector<ir::Grammar> grammars;
    for (const char* file : {"fig1.24d.l", "fig2.6-monopodial.l", "fig1.31a.l"})
        grammars.push_back(lang::loadGrammarFile((kSource / "grammars" / "abop" / file).string()));
    std::vector<ir::Grammar> species = ir::unifySpecies(grammars);
    for (std::size_t i = 0; i < grammars.size(); ++i) {
        // Each species alone, as its own grammar derives it: unification changes no plant.
        stream::DeriveResult alone = cpu::deriveCpu(grammars[i], {});
        stream::DeriveOptions options;
        options.plants = static_cast<std::uint32_t>(i + 1);
        stream::DeriveResult together = cpu::deriveSpeciesCpu(species, options);
        EXPECT_EQ(plantText(together, species.front().alphabet, i), plantText(alone, grammars[i].alphabet, 0))
            << "species " << i;
    }
    for (std::uint32_t plants : {3u, 30u}) expectEnginesAgree(context(), species, plants);
}

// stop() in a control block ends one plant's derivation; the others go on.
TEST_F(SpeciesGpuTest, PlantsStopAtTheirOwnStep) {
    ir::Grammar g = simeco::testing::grammarFromText("Lsystem: 1\n"
                                                     "derivation length: 12\n"
                                                     "EndEach: { if (ran(1) < 0.25) { stop(); } }\n"
                                                     "Axiom: A\n"
                                                     "A --> F[+A]A\n"
                                                     "endlsystem\n");
    std::vector<ir::Grammar> species{g};
    stream::DeriveOptions options;
    options.plants = 40;
    stream::DeriveResult want = cpu::deriveSpeciesCpu(species, options);
    std::set<std::uint64_t> lengths;
    for (std::size_t p = 0; p < 40; ++p) lengths.insert(want.string.plantStart[p + 1] - want.string.plantStart[p]);
    EXPECT_GE(lengths.size(), 3u) << "the plants should stop at different steps";
    gpu::GpuDeriver deriver(context(), g);
    EXPECT_EQ(firstDifference(want, deriver.derive(options), g.alphabet), "");
}

// Productions that write a global, read a local their previous application left, and call stop(): the
// order of rewriting matters, so the deriver takes the sequential strategy, plant by plant in one pass.
TEST_F(SpeciesGpuTest, OrderDependentProductionsDeriveSequentially) {
    ir::Grammar g = simeco::testing::grammarFromText("Lsystem: 1\n"
                                                     "derivation length: 9\n"
                                                     "Start: { n = 0; }\n"
                                                     "Axiom: A(0)\n"
                                                     "A(x) : ran(1) < 0.7 { n = n + 1; if (x > 1) { last = x * 2; } } --> "
                                                     "F(n)[+A(last)]A(x + 1)\n"
                                                     "A(x) : n > 60 { stop(); } --> B(n)\n"
                                                     "F(l) : l > 4 --> F(l - 1)\n"
                                                     "endlsystem\n");
    ASSERT_TRUE(codegen::gpuParallelUnsupportedReason(g).has_value());
    ASSERT_FALSE(codegen::gpuUnsupportedReason(g).has_value()) << *codegen::gpuUnsupportedReason(g);
    gpu::GpuDeriver deriver(context(), g);
    EXPECT_EQ(deriver.strategy(), gpu::GpuStrategy::Sequential);
    for (std::uint32_t plants : {1u, 250u}) {
        SCOPED_TRACE(std::to_string(plants) + " plants");
        stream::DeriveOptions options;
        options.plants = plants;
        stream::DeriveResult want = cpu::deriveCpu(g, options);
        std::set<std::uint64_t> lengths;
        for (std::size_t p = 0; p < plants; ++p) lengths.insert(want.string.plantStart[p + 1] - want.string.plantStart[p]);
        if (plants > 1) {
            EXPECT_GE(lengths.size(), 3u) << "the plants should differ";
        }
        EXPECT_EQ(firstDifference(want, deriver.derive(options), g.alphabet), "");
    }
    // Copies of it among other species share the sequential kernel's code.
    ir::Grammar other = g;
    other.derivationLength = 5;
    expectEnginesAgree(context(), ir::unifySpecies({g, other, g}), 30);
}

} // namespace
} // namespace simeco::test
