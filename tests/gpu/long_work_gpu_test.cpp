// Work that runs long in one invocation: a production's loop of many iterations, a context walk over very many
// ignored modules, a decomposition thousands of levels deep. Some drivers end an invocation's loops early
// (lavapipe after 65535 iterations in all); the device must then derive the CPU reference's string anyway, or
// refuse with a clear error, never hand back a wrong string.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "../unit/grammar_text.h"
#include "compare_strings.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "ir/source_loc.h"

namespace simeco::test {
namespace {

using LongWorkGpuTest = GpuTest;

constexpr const char* kDriverCut = "ended a shader loop early";

struct Strategy {
    gpu::GpuStrategy strategy;
    const char* name;
};
const Strategy kStrategies[] = {{gpu::GpuStrategy::Parallel, "parallel"}, {gpu::GpuStrategy::Sequential, "sequential"}};

// Derives `g` on the device; true when it matched the CPU, false when it refused because the driver cut a loop.
// Anything else fails the test.
bool matchesOrRefuses(const vk::Context& context, const ir::Grammar& g, gpu::GpuStrategy strategy) {
    stream::DeriveResult want = cpu::deriveCpu(g, {});
    gpu::GpuDeriver deriver(context, g, strategy);
    try {
        stream::DeriveResult got = deriver.derive({});
        EXPECT_EQ(firstDifference(want, got, g.alphabet), "");
        return true;
    } catch (const ir::LimitError& e) {
        EXPECT_NE(std::string(e.what()).find(kDriverCut), std::string::npos) << e.what();
        return false;
    }
}

TEST_F(LongWorkGpuTest, LongProductionLoopMatchesOrIsRefused) {
    ir::Grammar g = simeco::testing::grammarFromText(
        simeco::testing::lsystem("A(0)", "A(n) : 1 { k = 0; while (k < 70000) { k = k + 1; } } --> B(k)\n"));
    for (const Strategy& s : kStrategies) {
        SCOPED_TRACE(s.name);
        bool matched = matchesOrRefuses(context(), g, s.strategy);
        std::printf("%s: a loop of 70000 iterations %s\n", s.name, matched ? "matched the CPU" : "was refused");
    }
}

// B's left context lies beyond 2^17 ignored modules.
TEST_F(LongWorkGpuTest, LongContextWalkMatchesOrIsRefused) {
    ir::Grammar g = simeco::testing::grammarFromText(
        simeco::testing::lsystem("A(1)XB(0)", "ignore: X\nX --> XX\nA(a) < B(b) --> B(a + b)\n", 17));
    for (const Strategy& s : kStrategies) {
        SCOPED_TRACE(s.name);
        bool matched = matchesOrRefuses(context(), g, s.strategy);
        std::printf("%s: a context walk over 2^17 modules %s\n", s.name, matched ? "matched the CPU" : "was refused");
    }
}

// 5000 levels of decomposition from one module, more than lavapipe lets one invocation loop: the sequential
// kernel goes on in later dispatches. (The parallel passes run one pass per level; no invocation loops long.)
TEST_F(LongWorkGpuTest, DeepSequentialDecompositionMatchesTheCpu) {
    ir::Grammar g = simeco::testing::grammarFromText("Lsystem: 1\nDerivation length: 1\nAxiom: A(0)\n"
                                             "decomposition\nmaximum depth: 5000\n"
                                             "A(n) : n < 100000 --> [B(n)C]A(n+1)\n"
                                             "endlsystem\n");
    stream::DeriveResult want = cpu::deriveCpu(g, {});
    ASSERT_EQ(want.string.size(), 20001u);
    gpu::GpuDeriver deriver(context(), g, gpu::GpuStrategy::Sequential);
    EXPECT_EQ(firstDifference(want, deriver.derive({}), g.alphabet), "");
}

} // namespace
} // namespace simeco::test
