// Plants of different species in one stream, and plants that stop at different steps: the GPU derives them in
// the same passes and must give the CPU reference's strings, plant by plant.
#include <cstdint>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "../unit/grammar_text.h"
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

using SpeciesGpuTest = GpuTest;

std::string plantText(const stream::DeriveResult& r, const ir::Alphabet& alphabet, std::size_t plant) {
    const stream::ModuleString& s = r.string;
    return stream::formatModules(s, alphabet, s.plantStart[plant], s.plantStart[plant + 1]);
}

// Derives `species` with `plants` plants on both engines and expects the same strings.
void expectEnginesAgree(const vk::Context& context, const std::vector<ir::Grammar>& species, std::uint32_t plants) {
    SCOPED_TRACE(std::to_string(plants) + " plants");
    stream::DeriveOptions options;
    options.plants = plants;
    stream::DeriveResult want = cpu::deriveSpeciesCpu(species, options);
    ASSERT_EQ(want.string.plants(), plants);
    gpu::GpuDeriver deriver(context, species);
    EXPECT_EQ(firstDifference(want, deriver.derive(options), species.front().alphabet), "");
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
}

} // namespace
} // namespace simeco::test
