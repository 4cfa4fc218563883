// Derivation step by step over simulated time (GpuDeriver::begin, advance, current, drawn) against its CPU
// reference (cpu::SteppedDerivation): plants due at different steps, particle state carried, the homomorphism
// drawn between steps without ending the derivation; and every plant due at every step is a derivation.
#include <cstdint>
#include <string>
#include <vector>

#include "../unit/grammar_text.h"
#include "compare_strings.h"
#include "compute/shared/random.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"

namespace simeco::test {
namespace {

using SteppedDeriveTest = GpuTest;

// Stochastic, with branches, a context, decomposition and a homomorphism.
const std::string kGrammar = "A(x) : 1 --> F(x)[+A(x+1)]B A(x+1) : 0.6\n"
                             "A(x) : 1 --> F(x)B A(x) : 0.4\n"
                             "F(x) < B --> C\n"
                             "decomposition\nmaximum depth: 2\n"
                             "C --> D E\n"
                             "homomorphism\nmaximum depth: 2\n"
                             "E --> G(2) H\n"
                             "H --> f\n";

stream::DeriveOptions fieldOf(std::uint32_t plants) {
    stream::DeriveOptions options;
    options.plants = plants;
    options.steps = 6;
    options.seed = 11;
    options.particles = true;
    // Distinct states for the axioms' modules (one per plant).
    for (std::uint32_t plant = 0; plant < plants; ++plant) {
        shared::ParticleState s;
        for (std::uint32_t k = 0; k < shared::kParticleStateFloats; ++k)
            s.value[k] = float(plant) + 0.25f * float(k);
        options.initialParticles.push_back(s);
    }
    return options;
}

stream::DeriveResult asResult(const stream::ModuleString& s) {
    stream::DeriveResult r;
    r.string = s;
    return r;
}

TEST_F(SteppedDeriveTest, EveryPlantDueAtEveryStepIsADerivation) {
    ir::Grammar g = testing::grammarFromText(testing::lsystem("A(0)", kGrammar, 6));
    stream::DeriveOptions options = fieldOf(5);
    gpu::GpuDeriver deriver(context(), g);
    ASSERT_TRUE(deriver.recordsSteps());
    deriver.begin(options);
    const std::vector<std::uint8_t> all(options.plants, 1);
    for (int step = 1; step <= options.steps; ++step)
        EXPECT_EQ(deriver.advance(all), options.plants) << step;
    EXPECT_EQ(deriver.advance(all), 0u); // no steps left
    stream::DeriveResult want = cpu::deriveCpu(g, options);
    EXPECT_EQ(firstDifference(want, readModules(context(), deriver.current(), want.steps), g.alphabet), "");
    options.homomorphism = true;
    stream::DeriveResult drawnWant = cpu::deriveCpu(g, options);
    EXPECT_EQ(firstDifference(drawnWant, readModules(context(), deriver.drawn(), drawnWant.steps), g.alphabet), "");
    // Drawing left the derived string as it was.
    EXPECT_EQ(firstDifference(want, readModules(context(), deriver.current(), want.steps), g.alphabet), "");
}

TEST_F(SteppedDeriveTest, PlantsDueAtDifferentStepsDeriveAsTheReference) {
    std::vector<ir::Grammar> species{testing::grammarFromText(testing::lsystem("A(0)", kGrammar, 6))};
    const stream::DeriveOptions options = fieldOf(40);
    cpu::SteppedDerivation reference(species, options);
    gpu::GpuDeriver deriver(context(), species);
    deriver.begin(options);
    std::uint32_t derivedSteps = 0;
    for (std::uint32_t tick = 0; tick < 12; ++tick) {
        std::vector<std::uint8_t> due(options.plants);
        for (std::uint32_t plant = 0; plant < options.plants; ++plant)
            due[plant] = shared::randomUnit(3, plant, tick, 0, 0) < 0.5f;
        const std::uint32_t derived = reference.advance(due);
        ASSERT_EQ(deriver.advance(due), derived) << "tick " << tick;
        derivedSteps += derived;
        const stream::DeriveResult got = readModules(context(), deriver.current(), 0);
        ASSERT_EQ(firstDifference(asResult(reference.current()), got, species[0].alphabet), "") << "tick " << tick;
        ASSERT_EQ(got.string.particles, reference.current().particles) << "tick " << tick;
        if (tick % 4 == 3) {
            ASSERT_EQ(firstDifference(asResult(reference.drawn()), readModules(context(), deriver.drawn(), 0),
                                      species[0].alphabet),
                      "")
                << "drawn at tick " << tick;
        }
    }
    // Some plants derived and some waited in most ticks: the due flags were not all alike.
    EXPECT_GT(derivedSteps, options.plants);
    EXPECT_LT(derivedSteps, 12 * options.plants);
}

} // namespace
} // namespace simeco::test
