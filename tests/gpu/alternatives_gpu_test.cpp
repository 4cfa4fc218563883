// Productions with several alternatives (SimEco's prob() ... | ...): the match pass draws the alternative. Where
// the productions draw nothing else, the write pass applies the alternative recorded with the match's choice
// instead of drawing it again, and reads no draw starts; where a successor calls rand(), it draws the alternative
// again from the match's draw start. Both ways must give the CPU reference's strings.
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "codegen/derive_codegen.h"
#include "compare_strings.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/species.h"
#include "lang/eco_parser.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

using AlternativesGpuTest = GpuTest;

// Three-way alternatives, one of them empty, on more productions than two choice bits hold, with a context.
// `leafRule`: the production of L.
std::string threeWayScene(const std::string& leafRule) {
    return "ecosystem 1.0 \"alternatives\" {\n"
           "  Plant \"three ways\" {\n"
           "    DerivationLength = 14;\n"
           "    Grow {\n"
           "      w = A(0) S(0) A(1);\n"
           "      A(i) -> prob(0.45) A(i + 1) S(i) A(i + 2) | prob(0.35) [ L(i) ] A(i + 1) | null;\n"
           "      S(i) > A(1) -> S(i + 10);\n"
           "      S(i) -> prob(0.5) S(i + 1) | F(i);\n"
           "      F(i) -> F(i);\n"
           "      T(i) -> T(i);\n"
           "      " + leafRule + "\n"
           "    }\n"
           "  }\n"
           "}\n";
}

ir::Grammar scenePlant(const std::string& text) {
    ir::EcoScene scene = lang::parseEcoText(text, "alternatives.eco");
    return lang::compileEcoPlant(scene, 0);
}

ir::Grammar lantanaPlant() {
    return lang::compileEcoPlant(
        lang::parseEcoFile((fs::path(SIMECO_SOURCE_DIR) / "scenes" / "lantana-camara.eco").string()), 0);
}

// Whether the write pass generated for these species is given the alternatives (it reads no draw starts then).
bool writeIsGivenAlternatives(const std::vector<ir::Grammar>& species) {
    codegen::GeneratedKernels k = codegen::generateDeriveKernels(species, true);
    bool given = k.write.find("givenAlternative = choice >> kProductionBits;") != std::string::npos;
    bool draws = k.write.find("drawStartsAt(i)") != std::string::npos;
    EXPECT_NE(given, draws) << "a write pass either is given the alternatives or draws them";
    return given;
}

// The plants' strings on both engines, after checking that the plants took every alternative somewhere.
// Plant p is of species p mod species.size().
void expectEnginesAgree(const vk::Context& context, const std::vector<ir::Grammar>& species,
                        const std::vector<std::string>& seen) {
    const ir::Alphabet& alphabet = species.front().alphabet;
    for (std::uint32_t plants : {1u, 9u, 300u}) {
        SCOPED_TRACE(std::to_string(plants) + " plants");
        stream::DeriveOptions options;
        options.plants = plants;
        stream::DeriveResult want = cpu::deriveSpeciesCpu(species, options);
        if (plants == 300u) {
            std::string text = stream::formatModules(want.string, alphabet, 0, want.string.size());
            for (const std::string& module : seen) EXPECT_NE(text.find(module), std::string::npos) << module;
        }
        gpu::GpuDeriver deriver(context, species);
        EXPECT_EQ(firstDifference(want, deriver.derive(options), alphabet), "");
    }
}

TEST_F(AlternativesGpuTest, WriteGivenTheMatchsAlternativeMatchesTheCpu) {
    std::vector<ir::Grammar> lantana{lantanaPlant()};
    EXPECT_TRUE(writeIsGivenAlternatives(lantana));
    expectEnginesAgree(context(), lantana, {"S(99)", "S(6)"});

    std::vector<ir::Grammar> threeWays{scenePlant(threeWayScene("L(i) -> L(i + 1);"))};
    EXPECT_TRUE(writeIsGivenAlternatives(threeWays));
    expectEnginesAgree(context(), threeWays, {"[L(", "F(", "S(1"});

    // Both as species of one stream, whose productions and alternatives differ.
    std::vector<ir::Grammar> both = ir::unifySpecies({lantana.front(), threeWays.front()});
    EXPECT_TRUE(writeIsGivenAlternatives(both));
    expectEnginesAgree(context(), both, {"S(99)", "[L(", "F("});
}

TEST_F(AlternativesGpuTest, WriteThatDrawsItselfDrawsTheAlternativeAgain) {
    std::vector<ir::Grammar> draws{scenePlant(threeWayScene("L(i) -> prob(0.5) L(rand(0.0, 1.0)) T(i) | L(i + 1);"))};
    EXPECT_FALSE(writeIsGivenAlternatives(draws));
    expectEnginesAgree(context(), draws, {"[L(", "T(", "F("});

    // A species that draws makes the whole stream's write pass draw, the other species' alternatives included.
    std::vector<ir::Grammar> mixed = ir::unifySpecies({lantanaPlant(), draws.front()});
    EXPECT_FALSE(writeIsGivenAlternatives(mixed));
    expectEnginesAgree(context(), mixed, {"S(99)", "T("});
}

} // namespace
} // namespace simeco::test
