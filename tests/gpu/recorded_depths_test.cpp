// Recorded steps that rewrite by depths: decomposition and the homomorphism, recorded with the steps into one
// submission (derive(), and record() into a caller's command buffer), match the CPU reference's strings; a
// decomposition deeper than the depths recorded stops the batch and runs again with more; the homomorphism's
// errors are located in its own productions.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "../unit/grammar_text.h"
#include "compare_strings.h"
#include "compute/shared/derive_layout.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/source_loc.h"
#include "vk/buffer.h"

namespace simeco::test {
namespace {

using RecordedDepthsTest = GpuTest;

// Each step's decomposition goes one depth deeper than the last: past the depths a step records at first, and in
// the later steps to the maximum depth, which ends it with modules left to rewrite and its string in the stream
// the step did not write (an odd depth): it is copied back.
const std::string kDeepening = "S(x) --> S(x+1) D(x+1)\n"
                               "decomposition\nmaximum depth: 9\n"
                               "D(x) : x > 0 --> B(x) D(x-1)\n"
                               "B(x) --> F(x)\n"
                               "homomorphism\nmaximum depth: 2\n"
                               "F(x) > F(y) --> F(x+y) G\n"
                               "G --> H\n";
// The same in branches, with a left context that reads the string being rewritten across a branch, draws that
// depend on the depth, and a string that doubles at every depth: a step that goes on with more depths in a later
// submission goes on from the depth it reached, with the bracket tree its first submission built, and runs again
// from its start when it then outgrows its streams.
const std::string kDeepeningInBranches = "S(x) --> S(x+1)[G][D(x+1)]E\n"
                                         "decomposition\nmaximum depth: 9\n"
                                         "D(x) : x > 0 --> B(x + ran(1)) D(x-1) D(x-1)\n"
                                         "S(y) < B(x) --> F(x+y)\n"
                                         "B(x) --> F(x)\n";

TEST_F(RecordedDepthsTest, DecompositionDeeperThanRecordedRunsAgainWithMoreDepths) {
    struct Case {
        const char* axiom;
        const std::string& productions;
        bool homomorphism;
        int steps;
    };
    // In branches the first step's decomposition stops in the middle of its rewriting, not at its last depth; from
    // S(9) it also outgrows the streams' first room after that.
    for (const Case& c : {Case{"S(0)", kDeepening, false, 12}, Case{"S(0)", kDeepening, true, 12},
                          Case{"S(5)", kDeepeningInBranches, false, 3}, Case{"S(9)", kDeepeningInBranches, false, 3}}) {
        SCOPED_TRACE(c.productions + (c.homomorphism ? "with the homomorphism" : ""));
        ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem(c.axiom, c.productions, c.steps));
        const bool homomorphism = c.homomorphism;
        stream::DeriveOptions options;
        options.plants = 3;
        options.homomorphism = homomorphism;
        stream::DeriveResult want = cpu::deriveCpu(g, options);
        gpu::GpuDeriver fresh(context(), g);
        ASSERT_TRUE(fresh.recordsSteps());
        EXPECT_EQ(firstDifference(want, fresh.derive(options), g.alphabet), "");
        gpu::GpuDeriver deriver(context(), g);
        gpu::GpuDeriveStats deepened, again;
        deriver.derive(options, false, &deepened);
        EXPECT_EQ(deepened.stepMillis.size(), size_t(c.steps)) << "a step time for each step, none for the rest";
        EXPECT_GE(deepened.waits, 2u) << "the decomposition never went deeper than the depths recorded";
        // The next derivation records the depths and the room the first one found it needs: one submission.
        deriver.derive(options, false, &again);
        EXPECT_EQ(again.waits, 1u);
        EXPECT_EQ(again.modules, want.string.size());
    }
}

// record(): the steps, their decomposition and the homomorphism in the caller's command buffer; the first
// recording stops where the decomposition goes deeper than the depths recorded, and says so, the next has them.
TEST_F(RecordedDepthsTest, TheHomomorphismIsRecordedWithTheSteps) {
    ir::Grammar g = simeco::testing::grammarFromText(simeco::testing::lsystem("S(0)", kDeepening, 12));
    stream::DeriveOptions options;
    options.plants = 4;
    options.homomorphism = true;
    stream::DeriveResult want = cpu::deriveCpu(g, options);
    gpu::GpuDeriver deriver(context(), g);
    const std::uint64_t room = 4 * want.string.size();
    std::optional<stream::DeriveResult> got;
    stream::DeviceModules modules;
    int recordings = 0;
    for (; recordings < 4 && !got; ++recordings) {
        context().submitAndWait([&](VkCommandBuffer cmd) { modules = deriver.record(cmd, options, room); });
        EXPECT_TRUE(modules.countOnDevice);
        got = deriver.recorded();
    }
    ASSERT_TRUE(got.has_value()) << "no recording had the depths it needs";
    EXPECT_GT(recordings, 1) << "the decomposition never went deeper than the depths recorded";
    EXPECT_EQ(got->string.plantStart, want.string.plantStart);
    EXPECT_EQ(firstDifference(want, readModules(context(), modules, got->steps), g.alphabet), "");
}

// An error in the homomorphism, found in the submission that also runs the steps, is located in the
// homomorphism's production, not at the site of the steps' kernels that has its number.
TEST_F(RecordedDepthsTest, TheHomomorphismsErrorsAreItsOwn) {
    ir::Grammar g = simeco::testing::grammarFromText(
        "Lsystem: 1\ndefine: { array a[2] = {1, 2}; }\nderivation length: 3\nAxiom: A(0)\n"
        "A(x) --> A(a[1]) B(5)\n"
        "homomorphism\n"
        "B(x) --> F(a[x])\n"
        "endlsystem\n");
    stream::DeriveOptions options;
    options.homomorphism = true;
    ir::SourceLoc want;
    try {
        cpu::deriveCpu(g, options);
        FAIL() << "the CPU reference read past the array";
    } catch (const ir::InputError& e) {
        want = e.loc();
    }
    ASSERT_EQ(want.line, 7);
    gpu::GpuDeriver deriver(context(), g);
    ASSERT_TRUE(deriver.recordsSteps());
    try {
        deriver.derive(options);
        ADD_FAILURE() << "the device read past the array";
    } catch (const ir::InputError& e) {
        EXPECT_EQ(e.loc().line, want.line);
        EXPECT_EQ(e.loc().col, want.col);
        EXPECT_NE(std::string(e.what()).find("out of range for array 'a'"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace simeco::test
