// The growth tick on the device (grow::GpuGrowth) against its CPU reference (grow::tickCpu, growSizesCpu): a
// garden of three SimEco species derived step by step whenever each plant's DeriveTime is due, every particle
// ticked between, the drawn strings' sizes from the particles.
#include <bit>
#include <cmath>
#include <cstdint>
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

namespace simeco::test {
namespace {

using GrowthTickTest = GpuTest;

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

TEST_F(GrowthTickTest, TheDeviceGrowsTheGardenAsTheReference) {
    const grow::GrowingSpecies g = grow::loadGrowingSpecies(std::string(SIMECO_SOURCE_DIR) + "/scenes/garden.eco");
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
    grow::TickSettings settings{&tables, uint32_t(g.species.size()), 0.5f, 0, 5};

    std::vector<float> nextStep = deriveTimes;
    float time = 0.0f;
    uint32_t steps = 0;
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
        ASSERT_EQ(firstDifference(want, got, g.species[0].alphabet), "") << "tick " << tick;
        ASSERT_EQ(particleDifference(reference.current().particles, got.string.particles), "") << "tick " << tick;
        if (tick % 10 != 9) continue;
        stream::DeriveResult drawnWant;
        drawnWant.string = reference.drawn();
        grow::growSizesCpu(settings, deriveTimes, drawnWant.string);
        const stream::DeviceModules drawn = deriver.drawn();
        growth.growSizes(drawn, settings);
        ASSERT_EQ(firstDifference(drawnWant, readModules(context(), drawn, 0), g.species[0].alphabet), "")
            << "drawn at tick " << tick;
    }
    EXPECT_GT(steps, 2 * options.plants); // every plant derived several steps
    // The particles grew: stems long and wide, leaves grown, some stem tilted by its cone noise.
    float longest = 0, widest = 0, tilted = 0;
    for (const shared::ParticleState& p : reference.current().particles) {
        longest = std::max(longest, p.value[shared::kParticleElongation]);
        widest = std::max(widest, p.value[shared::kParticleBroadening]);
        tilted = std::max(tilted, p.value[shared::kParticlePitch]);
    }
    EXPECT_GT(longest, 1.0f);
    EXPECT_GT(widest, 0.1f);
    EXPECT_GT(tilted, 0.0f);
}

} // namespace
} // namespace simeco::test
