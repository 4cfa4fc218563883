// The GPU derivation moves each module's particle state as the CPU reference does (compute/shared/particle_layout.h):
// the fused and the separate scan, cuts, predecessors of several modules, decomposition, the homomorphism, the
// sequential strategy, and plants of several species that stop at different steps.
#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "../unit/grammar_text.h"
#include "compare_strings.h"
#include "compute/shared/particle_layout.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/species.h"
#include "lang/eco_parser.h"
#include "lang/load_grammar.h"
#include "vk/buffer.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

const fs::path kSource = SIMECO_SOURCE_DIR;

// Distinct states for the axioms' modules of `plants` plants, every slot different.
std::vector<shared::ParticleState> axiomStates(const std::vector<ir::Grammar>& species, std::uint32_t plants) {
    std::vector<shared::ParticleState> states;
    for (std::uint32_t plant = 0; plant < plants; ++plant) {
        std::size_t modules = species[ir::speciesOfPlant(plant, species.size())].axiom.size();
        for (std::size_t m = 0; m < modules; ++m) {
            shared::ParticleState s;
            for (std::uint32_t k = 0; k < shared::kParticleStateFloats; ++k)
                s.value[k] = float(states.size() + 1) + 0.0625f * float(k);
            states.push_back(s);
        }
    }
    return states;
}

// Empty when both engines give the same string and the same particle states; else the first difference.
std::string compareParticles(const vk::Context& context, const std::vector<ir::Grammar>& species,
                             stream::DeriveOptions options, gpu::GpuStrategy strategy) {
    options.particles = true;
    options.initialParticles = axiomStates(species, std::max<std::uint32_t>(options.plants, 1));
    stream::DeriveResult want = cpu::deriveSpeciesCpu(species, options);
    gpu::GpuDeriver deriver(context, species, strategy);
    stream::DeriveResult got = deriver.derive(options);
    std::string difference = firstDifference(want, got, species.front().alphabet);
    if (!difference.empty()) return difference;
    if (want.string.particles.size() != want.string.size())
        return fmt::format("the CPU carried {} states for {} modules", want.string.particles.size(), want.string.size());
    if (got.string.particles.size() != want.string.particles.size())
        return fmt::format("{} states from the GPU, {} from the CPU", got.string.particles.size(),
                           want.string.particles.size());
    auto differ = std::mismatch(want.string.particles.begin(), want.string.particles.end(), got.string.particles.begin());
    if (differ.first == want.string.particles.end()) return "";
    return fmt::format("module {}: the GPU's state starts {}, the CPU's {}", differ.first - want.string.particles.begin(),
                       differ.second->value[0], differ.first->value[0]);
}

class ParticleCarryGpuTest : public GpuTest {
protected:
    // Both strategies (the parallel one where the grammar allows it) must carry as the CPU does.
    void expectCarried(const std::vector<ir::Grammar>& species, const stream::DeriveOptions& options,
                       const std::string& what) {
        bool parallel = std::none_of(species.begin(), species.end(), [](const ir::Grammar& g) {
            return codegen::gpuParallelUnsupportedReason(g).has_value();
        });
        if (parallel) {
            EXPECT_EQ(compareParticles(context(), species, options, gpu::GpuStrategy::Parallel), "") << what;
        }
        EXPECT_EQ(compareParticles(context(), species, options, gpu::GpuStrategy::Sequential), "")
            << what << ", sequential strategy";
    }
    void expectCarried(const std::string& text, std::uint32_t plants = 1, bool homomorphism = false) {
        stream::DeriveOptions options;
        options.plants = plants;
        options.homomorphism = homomorphism;
        expectCarried({testing::grammarFromText(text)}, options, text);
    }
};

TEST_F(ParticleCarryGpuTest, CopiesAndSuccessorsWithTheFusedScan) {
    expectCarried(testing::lsystem("F[+F]A(1)", "A(x) --> F[-A(x+1)]+A(x*2)\nF --> FF", 5));
}

TEST_F(ParticleCarryGpuTest, ErasedAndCutModules) {
    expectCarried(testing::lsystem("A[BCD]EB[C]", "B --> %\nA --> AC\nE --> *", 3));
}

TEST_F(ParticleCarryGpuTest, PredecessorsOfSeveralModules) {
    expectCarried(testing::lsystem("CABDAB", "AB --> XYA\nX --> ABB", 4));
}

TEST_F(ParticleCarryGpuTest, Decomposition) {
    expectCarried(testing::lsystem("AC", "A --> AB\ndecomposition\nmaximum depth: 3\nB --> CD\nC --> EE\nE --> F", 4));
}

TEST_F(ParticleCarryGpuTest, Homomorphism) {
    expectCarried(testing::lsystem("A[B]", "A --> AB\nhomomorphism\nmaximum depth: 2\nA --> FG\nG --> [H]", 3), 1, true);
}

TEST_F(ParticleCarryGpuTest, ManyPlants) { expectCarried(testing::lsystem("A(0)B", "A(x) --> A(x+1)[B]", 4), 300); }

// Species of different derivation lengths: a plant that stopped copies its modules with their states.
TEST_F(ParticleCarryGpuTest, SpeciesThatStopAtDifferentSteps) {
    std::vector<ir::Grammar> grammars;
    for (const char* file : {"fig1.24d.l", "fig1.31a.l"})
        grammars.push_back(lang::loadGrammarFile((kSource / "grammars" / "abop" / file).string()));
    std::vector<ir::Grammar> species = ir::unifySpecies(grammars);
    species[0].derivationLength = 3;
    species[1].derivationLength = 6;
    stream::DeriveOptions options;
    options.plants = 5;
    expectCarried(species, options, "fig1.24d and fig1.31a");
}

// Steps recorded with their sizes on the device carry the states too, also when a string outgrows its stream in
// the middle of a batch and its states move to the grown buffers with its modules.
TEST_F(ParticleCarryGpuTest, RecordedStepsCarryThemWhileTheStreamsGrow) {
    ir::Grammar g = testing::grammarFromText(
        testing::lsystem("F(1)", "F(x) --> F(x*2)[+F(x+1)]F(x)[-F(x/2)]F(x-1)\n", 7));
    stream::DeriveOptions options;
    options.plants = 3;
    EXPECT_EQ(compareParticles(context(), {g}, options, gpu::GpuStrategy::Parallel), "");
    gpu::GpuDeriver deriver(context(), g, gpu::GpuStrategy::Parallel);
    ASSERT_TRUE(deriver.recordsSteps());
    options.particles = true;
    options.initialParticles = axiomStates({g}, options.plants);
    gpu::GpuDeriveStats stats;
    deriver.derive(options, false, &stats);
    // A batch that stops where the string outgrows its room, and the rest (the axioms' states go up with it).
    EXPECT_GE(stats.waits, 2u) << "the string never outgrew the first room";
    EXPECT_LT(stats.waits, 8u) << "a wait per step";
}

// The stream the turtle kernels read (lastString) holds the states the derivation returned, or none.
TEST_F(ParticleCarryGpuTest, TheDeviceStringHoldsTheStates) {
    ir::Grammar g = testing::grammarFromText(testing::lsystem("AB", "A --> AB[A]", 4));
    gpu::GpuDeriver deriver(context(), g);
    stream::DeriveOptions options;
    options.particles = true;
    options.initialParticles = axiomStates({g}, 1);
    stream::DeriveResult carried = deriver.derive(options);
    stream::DeviceModules modules = deriver.lastString();
    ASSERT_NE(modules.particles, nullptr);
    ASSERT_EQ(modules.count, carried.string.size());
    EXPECT_EQ(vk::downloadVector<shared::ParticleState>(context(), *modules.particles, modules.count),
              carried.string.particles);
    deriver.derive(stream::DeriveOptions{});
    EXPECT_EQ(deriver.lastString().particles, nullptr);
}

TEST_F(ParticleCarryGpuTest, ExampleGrammars) {
    std::vector<fs::path> files;
    for (const fs::directory_entry& entry : fs::recursive_directory_iterator(kSource / "grammars"))
        if (entry.is_regular_file() && (entry.path().extension() == ".l" || entry.path().extension() == ".lsys"))
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    ASSERT_GE(files.size(), 15u);
    int compared = 0;
    for (const fs::path& file : files) {
        ir::Grammar g = lang::loadGrammarFile(file.string());
        if (codegen::gpuUnsupportedReason(g)) continue;
        stream::DeriveOptions options;
        options.steps = std::min(g.derivationLength, 5); // the paths, not the sizes, matter here
        expectCarried({g}, options, file.filename().string());
        ++compared;
    }
    EXPECT_GE(compared, 15);
}

} // namespace
} // namespace simeco::test
