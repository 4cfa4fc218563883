// The growth tick on the device (grow::GpuGrowth) against its CPU reference (grow::tickCpu, growSizesCpu): a
// garden of three SimEco species derived step by step whenever each plant's DeriveTime is due, every particle
// ticked between, the drawn strings' sizes from the particles; and the same garden with organs that die and
// stems that bend under their weight.
#include <unistd.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "compare_strings.h"
#include "compute/shared/growth_layout.h"
#include "compute/shared/particle_layout.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "grow/growing_species.h"
#include "grow/growth_tables.h"
#include "grow/tick_cpu.h"
#include "grow/tick_gpu.h"
#include "lang/eco_parser.h"

namespace simeco::test {
namespace {

// Empty when the states agree: identities exactly, values within float rounding of the device's arithmetic.
std::string particleDifference(const std::vector<shared::ParticleState>& want,
                               const std::vector<shared::ParticleState>& got) {
    if (want.size() != got.size())
        return fmt::format("{} states on the device, {} on the CPU", got.size(), want.size());
    for (size_t i = 0; i < want.size(); ++i)
        for (uint32_t k = 0; k < shared::kParticleStateFloats; ++k) {
            const float a = want[i].value[k], b = got[i].value[k];
            const bool same = k == shared::kParticleId ? std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b)
                                                       : std::fabs(a - b) <= 1e-5f * std::max(1.0f, std::fabs(a));
            if (!same) return fmt::format("module {} slot {}: {} on the device, {} on the CPU", i, k, b, a);
        }
    return "";
}

std::string gardenText() {
    std::ifstream in(std::string(SIMECO_SOURCE_DIR) + "/scenes/garden.eco");
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every occurrence of `from` in `text` followed by `more`.
std::string appendAfterEach(std::string text, const std::string& from, const std::string& more) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + from.size() + more.size()))
        text.insert(at + from.size(), more);
    return text;
}

class GrowthTickTest : public GpuTest {
protected:
    // Nine plants of the scene's species derived whenever each plant's DeriveTime is due and ticked in 30 ticks of
    // 0.5 s on both engines, their strings and particles compared after every tick and their drawn strings with
    // grown sizes every 10 ticks. Returns the CPU's last drawn string.
    stream::ModuleString growOnBoth(const std::string& text) {
        return growOnBoth(grow::growingSpecies(lang::parseEcoText(text, "garden.eco")));
    }
    stream::ModuleString growOnBoth(const grow::GrowingSpecies& g) {
        stream::DeriveOptions options;
        options.plants = 9;
        options.seed = 5;
        options.particles = true;
        const grow::GrowthTables tables = grow::growthTables(g.species, g.ecoPlants);
        const std::vector<float> deriveTimes = grow::plantDeriveTimes(g.ecoPlants, options.plants, 5);
        cpu::SteppedDerivation reference(g.species, options);
        gpu::GpuDeriver deriver(context(), g.species);
        deriver.begin(options);
        grow::GpuGrowth growth(context(), tables, deriveTimes);
        grow::TickSettings settings{&tables, uint32_t(g.species.size()), 0.5f, 0, 5, g.relativeGravity()};

        std::vector<float> nextStep = deriveTimes;
        float time = 0.0f;
        uint32_t steps = 0;
        stream::DeriveResult drawnWant;
        for (uint32_t tick = 0; tick < 30; ++tick) {
            time += settings.dt;
            std::vector<uint8_t> due(options.plants, 0);
            for (uint32_t plant = 0; plant < options.plants; ++plant)
                if (time >= nextStep[plant]) {
                    due[plant] = 1;
                    nextStep[plant] += deriveTimes[plant];
                }
            steps += reference.advance(due);
            deriver.advance(due);
            settings.tick = tick;
            grow::tickCpu(settings, reference.current());
            growth.tick(deriver.current(), settings);
            const stream::DeriveResult got = readModules(context(), deriver.current(), 0);
            stream::DeriveResult want;
            want.string = reference.current();
            EXPECT_EQ(firstDifference(want, got, g.species[0].alphabet), "") << "tick " << tick;
            EXPECT_EQ(particleDifference(reference.current().particles, got.string.particles), "") << "tick " << tick;
            if (tick % 10 != 9) continue;
            drawnWant.string = reference.drawn();
            grow::growSizesCpu(settings, deriveTimes, drawnWant.string);
            stream::DeviceModules drawn = deriver.drawn();
            // A grammar without a homomorphism draws its derived string: its segments shorten a copy.
            if (drawn.symbols == deriver.current().symbols) drawn = growth.copyForDrawing(drawn);
            growth.growSizes(drawn, settings);
            EXPECT_EQ(firstDifference(drawnWant, readModules(context(), drawn, 0), g.species[0].alphabet), "")
                << "drawn at tick " << tick;
        }
        EXPECT_GT(steps, 2 * options.plants); // every plant derived several steps
        particles_ = reference.current().particles;
        alphabet_ = g.species[0].alphabet;
        return drawnWant.string;
    }
    std::vector<shared::ParticleState> particles_; // the CPU's last derived string's
    ir::Alphabet alphabet_;
};

TEST_F(GrowthTickTest, TheDeviceGrowsTheGardenAsTheReference) {
    growOnBoth(gardenText());
    // The particles grew: stems long and wide, leaves grown, some stem tilted by its cone noise.
    float longest = 0, widest = 0, tilted = 0;
    for (const shared::ParticleState& p : particles_) {
        longest = std::max(longest, p.value[shared::kParticleElongation]);
        widest = std::max(widest, p.value[shared::kParticleBroadening]);
        tilted = std::max(tilted, p.value[shared::kParticlePitch]);
    }
    EXPECT_GT(longest, 1.0f);
    EXPECT_GT(widest, 0.1f);
    EXPECT_GT(tilted, 0.0f);
}

TEST_F(GrowthTickTest, TheDeviceShedsAndBendsAsTheReference) {
    // The garden with leaves that live 4 to 9 s and stems that live 9 to 14 s and bend under their weight.
    std::string text = appendAfterEach(gardenText(), "Texture = \"seafloor.bmp\";",
                                       " LifeTime = rand(9.0, 14.0); WeightFactor = 0.1;");
    for (const char* species : {"馬櫻丹", "酢醬草", "玫瑰"})
        text = appendAfterEach(text, fmt::format("Texture = \"{}.bmp\";", species), " LifeTime = rand(4.0, 9.0);");
    const stream::ModuleString drawn = growOnBoth(text);
    // Some stems were shed, some leaves old, some fallen, some bent, as the drawn string says.
    const auto alive = alphabet_.find("alive"), tropism = alphabet_.find("tropism");
    ASSERT_TRUE(alive && tropism);
    uint32_t shed = 0, bent = 0;
    for (size_t i = 0; i < drawn.size(); ++i) {
        if (drawn.sym[i] == *alive && drawn.paramsOf(i)[0] == 0.0f) ++shed;
        if (drawn.sym[i] == *tropism && drawn.paramsOf(i)[0] > 0.0f) ++bent;
    }
    EXPECT_GT(shed, 0u);
    EXPECT_GT(bent, 0u);
}
TEST_F(GrowthTickTest, TheDeviceGrowsAGrammarsSegmentsAsTheReference) {
    // ABOP's figure 1.24d: its segments (F, and F F as F doubles) grow over their first DeriveTime.
    const stream::ModuleString drawn =
        growOnBoth(grow::loadGrowingSpecies(std::string(SIMECO_SOURCE_DIR) + "/grammars/abop/fig1.24d.l"));
    // Some drawn segment is shorter than the step: it was growing when the field was drawn.
    bool growing = false;
    for (size_t i = 0; i < drawn.size(); ++i) growing |= drawn.paramCount[i] == 1 && drawn.paramsOf(i)[0] < 1.0f;
    EXPECT_TRUE(growing);
}

TEST_F(GrowthTickTest, TheDeviceGrowsAGrammarsSpheresAndDiscsAsTheReference) {
    // Every step a segment, a sphere `@O` and a disc `@c`: their radii grow over their first DeriveTime, as the
    // cloud grammars' spheres do.
    const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("simeco-spheres-" + std::to_string(::getpid()) + ".l");
    std::ofstream(file) << "Lsystem: 1\nderivation length: 9\nAxiom: A\nA --> F(1)[@O(0.5)]@c(0.3)A\nendlsystem\n";
    const grow::GrowingSpecies g = grow::loadGrowingSpecies(file.string());
    std::filesystem::remove(file);
    const stream::ModuleString drawn = growOnBoth(g);
    const ir::SymbolId sphere = *g.species[0].alphabet.find("O");
    bool growing = false;
    size_t spheres = 0;
    for (size_t i = 0; i < drawn.size(); ++i) {
        if (drawn.sym[i] != sphere) continue;
        ++spheres;
        ASSERT_EQ(drawn.paramCount[i], 1);
        EXPECT_LE(drawn.paramsOf(i)[0], 0.5f);
        growing |= drawn.paramsOf(i)[0] < 0.5f;
    }
    EXPECT_GT(spheres, 9u);
    EXPECT_TRUE(growing);
}

} // namespace
} // namespace simeco::test
