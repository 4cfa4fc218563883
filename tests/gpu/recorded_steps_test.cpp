// Steps recorded one after the other with their sizes on the device: the strings equal the CPU reference's
// while the streams outgrow their room, across batches, at the module budget; the host waits once per batch.
#include <cstdint>
#include <string>

#include "../unit/grammar_text.h"
#include "codegen/derive_codegen.h"
#include "compare_strings.h"
#include "compute/shared/derive_layout.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/source_loc.h"

namespace simeco::test {
namespace {

using RecordedStepsTest = GpuTest;

// A fresh deriver starts with room for about a thousand modules: a string growing fivefold a step outgrows its
// streams, the batch stops there, and the rest runs again in the grown streams. A second derivation finds the room.
TEST_F(RecordedStepsTest, StreamsGrowAndTheStringsMatchTheCpu) {
    ir::Grammar g = simeco::testing::grammarFromText(
        simeco::testing::lsystem("F(1)", "F(x) --> F(x*2)[+F(x+1)]F(x)[-F(x/2)]F(x-1)\n", 7));
    for (std::uint32_t plants : {1u, 3u}) {
        SCOPED_TRACE(std::to_string(plants) + " plants");
        stream::DeriveOptions options;
        options.plants = plants;
        stream::DeriveResult want = cpu::deriveCpu(g, options);
        gpu::GpuDeriver deriver(context(), g);
        ASSERT_TRUE(deriver.recordsSteps());
        gpu::GpuDeriveStats first, again;
        EXPECT_EQ(firstDifference(want, deriver.derive(options, true, &first), g.alphabet), "");
        EXPECT_EQ(first.stepMillis.size(), 7u);
        EXPECT_EQ(first.peakModules, want.string.size());
        // Without reading the string back: one submission when the streams have room, the sizes included.
        deriver.derive(options, false, &again);
        EXPECT_EQ(again.waits, 1u);
        EXPECT_EQ(again.modules, want.string.size());
        gpu::GpuDeriver fresh(context(), g);
        gpu::GpuDeriveStats grown;
        stream::DeriveResult sizes = fresh.derive(options, false, &grown);
        EXPECT_EQ(sizes.string.plantStart, want.string.plantStart);
        EXPECT_GE(grown.waits, 2u) << "the string never outgrew the first room";
        EXPECT_LT(grown.waits, 7u) << "a wait per step";
    }
}

// Contexts while the streams grow: the first step builds a bracket tree, every later step reads the partners the
// step before wrote with its string, also across the submissions that the growth of the streams splits it into.
TEST_F(RecordedStepsTest, ContextsMatchTheCpuAcrossSubmissions) {
    ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem(
        "A", "ignore: + -\nA --> F[+A]F[-A]A\nF < F --> G\nG > [ --> F\nF > [ --> H\n", 8));
    ASSERT_TRUE(codegen::generateDeriveKernels({g}).carriesPartners);
    stream::DeriveOptions options;
    options.plants = 3;
    stream::DeriveResult want = cpu::deriveCpu(g, options);
    gpu::GpuDeriver deriver(context(), g);
    ASSERT_TRUE(deriver.recordsSteps());
    gpu::GpuDeriveStats grown, again;
    EXPECT_EQ(firstDifference(want, deriver.derive(options, true, &grown), g.alphabet), "");
    EXPECT_EQ(grown.bracketTrees, 1u);
    EXPECT_EQ(firstDifference(want, deriver.derive(options, true, &again), g.alphabet), "");
    EXPECT_GT(grown.waits, again.waits) << "the string never outgrew the first room";
}

// More steps than one submission records: a batch after another, the plant control a batch ahead of the device,
// its StartEach block changing a global that the productions read every step.
TEST_F(RecordedStepsTest, LongDerivationsRunInBatches) {
    const std::uint32_t steps = shared::kMostRecordedSteps * 2 + 5;
    ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem(
        "A(0)", "Start: {n = 0;}\nStartEach: {n = n + 1;}\nA(x) --> A(x+n)B\nB --> B\n", int(steps)));
    stream::DeriveOptions options;
    options.plants = 5;
    stream::DeriveResult want = cpu::deriveCpu(g, options);
    gpu::GpuDeriver deriver(context(), g);
    ASSERT_TRUE(deriver.recordsSteps());
    EXPECT_EQ(firstDifference(want, deriver.derive(options), g.alphabet), "");
    gpu::GpuDeriveStats stats;
    deriver.derive(options, false, &stats);
    EXPECT_EQ(stats.waits, 3u);
    EXPECT_EQ(stats.stepMillis.size(), steps);
}

// Steps whose match does not scan its counts itself: a cut drops the rest of its branch, and predecessors of
// several modules consume their neighbours in a greedy walk; both are sized on the device like any step, so the
// strings match while the streams grow, and a derivation whose streams have room is one submission.
TEST_F(RecordedStepsTest, CutsAndPredecessorsOfSeveralModulesRecord) {
    ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem(
        "XA(0)A(1)[B(0)]A(2)",
        "A(a)A(b) --> A(a+1)[B(a)]A(b)A(a+b)A(a)\nB(n) : n > 2 --> %\nB(n) --> A(n)A(n)B(n+1)\n", 9));
    ASSERT_FALSE(codegen::generateDeriveKernels({g}).fusedScan);
    stream::DeriveOptions options;
    options.plants = 3;
    stream::DeriveResult want = cpu::deriveCpu(g, options);
    ASSERT_GT(want.string.size(), 4000u);
    gpu::GpuDeriver deriver(context(), g);
    ASSERT_TRUE(deriver.recordsSteps());
    gpu::GpuDeriveStats grown, again;
    EXPECT_EQ(firstDifference(want, deriver.derive(options, true, &grown), g.alphabet), "");
    deriver.derive(options, false, &again);
    EXPECT_GE(grown.waits, 3u) << "the string never outgrew the first room";
    EXPECT_EQ(again.waits, 1u);
    EXPECT_EQ(again.modules, want.string.size());
}

// The budget ends a recorded derivation with the CPU's message, naming the step; the deriver stays usable.
TEST_F(RecordedStepsTest, TheModuleBudgetStopsTheStepThatPassesIt) {
    ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem("F", "F --> FF\n", 40));
    stream::DeriveOptions options;
    options.maxModules = 1000;
    std::string want;
    try {
        cpu::deriveCpu(g, options);
    } catch (const ir::LimitError& e) {
        want = e.what();
    }
    ASSERT_NE(want.find("in step 10"), std::string::npos) << want;
    gpu::GpuDeriver deriver(context(), g);
    ASSERT_TRUE(deriver.recordsSteps());
    try {
        deriver.derive(options);
        ADD_FAILURE() << "the module budget did not stop the derivation";
    } catch (const ir::LimitError& e) {
        EXPECT_EQ(std::string(e.what()), want);
    }
    // The deriver goes on from an error: the next derivation, within its budget, matches.
    options.maxModules = 0;
    options.steps = 12;
    EXPECT_EQ(firstDifference(cpu::deriveCpu(g, options), deriver.derive(options), g.alphabet), "");
}

} // namespace
} // namespace simeco::test
