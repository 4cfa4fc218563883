// Derivation step by step over simulated time (GpuDeriver::begin, advance, current, drawn) against its CPU
// reference (cpu::SteppedDerivation): plants due at different steps, particle state carried, the homomorphism
// drawn between steps without ending the derivation, and drawn again while no step derives; and every plant due at
// every step is a derivation. Steps recorded into the caller's submission derive the same.
#include <bit>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "../unit/grammar_text.h"
#include "compare_strings.h"
#include "compute/shared/random.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "vk/barriers.h"
#include "vk/buffer.h"

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

// Each plant due at the tick with the given chance, drawn from random stream `stream`.
std::vector<std::uint8_t> dueAtRandom(std::uint32_t plants, std::uint32_t stream, std::uint32_t tick, float chance) {
    std::vector<std::uint8_t> due(plants);
    for (std::uint32_t plant = 0; plant < plants; ++plant)
        due[plant] = shared::randomUnit(stream, plant, tick, 0, 0) < chance;
    return due;
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
        const std::vector<std::uint8_t> due = dueAtRandom(options.plants, 3, tick, 0.5f);
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

// A drawn string stands until a step derives. Drawn again, it is the string the homomorphism wrote, whatever the
// drawing did to its symbols and parameters since, with the particles its derived modules have now: what drawn()
// would write.
TEST_F(SteppedDeriveTest, ADrawnStringStandsUntilAStepDerivesAndIsDrawnAgainAsWritten) {
    const ir::Grammar g = testing::grammarFromText(testing::lsystem("A(0)", kGrammar, 6));
    const stream::DeriveOptions options = fieldOf(12);
    gpu::GpuDeriver deriver(context(), g);
    deriver.begin(options);
    const std::vector<std::uint8_t> all(options.plants, 1);
    EXPECT_EQ(deriver.advance(all), options.plants);
    EXPECT_EQ(deriver.advance(all), options.plants);
    EXPECT_FALSE(deriver.drawnStands());
    const stream::DeriveResult written = readModules(context(), deriver.drawn(), 0);
    ASSERT_TRUE(deriver.drawnStands());
    ASSERT_GT(written.string.size(), options.plants);

    // What a drawing does to the drawn string in place, and a growth tick to the derived string's particles.
    const stream::DeviceModules shown = deriver.lastDrawn(), derived = deriver.current();
    context().submitAndWait([&](VkCommandBuffer cmd) {
        vk::cmdFill(cmd, *shown.symbols, 7u);
        vk::cmdFill(cmd, *shown.params, std::bit_cast<std::uint32_t>(9.5f));
        vk::cmdFill(cmd, *derived.particles, std::bit_cast<std::uint32_t>(2.5f));
        vk::memoryBarrier(cmd, vk::Hazard::TransferToAny);
    });
    context().submitAndWait([&](VkCommandBuffer cmd) { deriver.recordDrawnAgain(cmd); });
    const stream::DeriveResult again = readModules(context(), deriver.lastDrawn(), 0);
    EXPECT_EQ(firstDifference(written, again, g.alphabet), "");
    ASSERT_EQ(again.string.particles.size(), written.string.size());
    for (const shared::ParticleState& p : again.string.particles)
        for (float value : p.value) ASSERT_EQ(value, 2.5f);
    const stream::DeriveResult fresh = readModules(context(), deriver.drawn(), 0);
    EXPECT_EQ(firstDifference(fresh, again, g.alphabet), "");
    EXPECT_EQ(fresh.string.particles, again.string.particles);

    EXPECT_EQ(deriver.advance(all), options.plants);
    EXPECT_FALSE(deriver.drawnStands());
    EXPECT_THROW(deriver.lastDrawn(), std::logic_error);
    context().submitAndWait(
        [&](VkCommandBuffer cmd) { EXPECT_THROW(deriver.recordDrawnAgain(cmd), std::logic_error); });
}

// A step recorded into the caller's submission derives what advance() derives. Until it is read, the string it
// writes is counted only on the device, within the bound current() gives, and the calls that need the host's count
// are refused. A step that outgrew its streams' room (the first one does: the streams start at the axioms' size) is
// derived again when it is read, and says so; the string is then the reference's all the same. The homomorphism is
// recorded after the step, and its string stands until the next.
TEST_F(SteppedDeriveTest, ARecordedStepDerivesAsAdvanceAndIsDerivedAgainWhereItOutgrewItsRoom) {
    std::vector<ir::Grammar> species{testing::grammarFromText(testing::lsystem("A(0)", kGrammar, 6))};
    // Plants enough that the first step outgrows the streams' first room, before the homomorphism's growth makes more.
    const stream::DeriveOptions options = fieldOf(300);
    cpu::SteppedDerivation reference(species, options);
    gpu::GpuDeriver deriver(context(), species);
    deriver.begin(options);
    vk::Buffer counted(context(), 4, vk::MemoryUsage::Readback);
    int fit = 0, outgrown = 0;
    for (std::uint32_t tick = 0; tick < 8; ++tick) {
        const std::vector<std::uint8_t> due = dueAtRandom(options.plants, 5, tick, 0.7f);
        const std::uint32_t derived = reference.advance(due);
        std::uint32_t recorded = 0, bound = 0;
        context().submitAndWait([&](VkCommandBuffer cmd) {
            recorded = deriver.recordAdvance(cmd, due);
            const stream::DeviceModules string = deriver.current();
            EXPECT_EQ(string.countOnDevice, recorded > 0);
            bound = string.count;
            // What a pass recorded after the step reads as its count: the plant table's last entry.
            vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
            const VkBufferCopy last{4ull * options.plants, 0, 4};
            vkCmdCopyBuffer(cmd, string.plantStarts->handle(), counted.handle(), 1, &last);
            vk::memoryBarrier(cmd, vk::Hazard::TransferToHost);
        });
        ASSERT_EQ(recorded, derived) << "tick " << tick;
        if (recorded == 0) continue;
        EXPECT_THROW(deriver.advance(due), std::logic_error);
        EXPECT_THROW(deriver.drawn(), std::logic_error);
        EXPECT_THROW(deriver.save(), std::logic_error);
        const gpu::GpuDeriver::Advanced outcome = deriver.advanced();
        const std::uint32_t onDevice = *reinterpret_cast<const std::uint32_t*>(counted.mapped());
        if (outcome == gpu::GpuDeriver::Advanced::DerivedAgain) {
            ++outgrown;
            EXPECT_LE(onDevice, bound) << "tick " << tick;
            EXPECT_GT(deriver.current().count, bound) << "tick " << tick;
        } else {
            ++fit;
            EXPECT_EQ(onDevice, deriver.current().count) << "tick " << tick;
        }
        EXPECT_FALSE(deriver.current().countOnDevice);
        const stream::DeriveResult got = readModules(context(), deriver.current(), 0);
        ASSERT_EQ(firstDifference(asResult(reference.current()), got, species[0].alphabet), "") << "tick " << tick;
        ASSERT_EQ(got.string.particles, reference.current().particles) << "tick " << tick;
        // The homomorphism was recorded after the step: its string stands, as drawn() would write it.
        ASSERT_TRUE(deriver.drawnStands()) << "tick " << tick;
        const stream::DeriveResult drawn = readModules(context(), deriver.lastDrawn(), 0);
        ASSERT_EQ(firstDifference(asResult(reference.drawn()), drawn, species[0].alphabet), "") << "tick " << tick;
        ASSERT_EQ(drawn.string.particles, reference.drawn().particles) << "tick " << tick;
    }
    EXPECT_GE(fit, 2);
    EXPECT_GE(outgrown, 1);
    EXPECT_THROW(deriver.advanced(), std::logic_error);
    ASSERT_EQ(
        firstDifference(asResult(reference.drawn()), readModules(context(), deriver.drawn(), 0), species[0].alphabet),
        "");
}

} // namespace
} // namespace simeco::test
