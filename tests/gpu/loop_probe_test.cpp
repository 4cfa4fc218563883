// Which generated kernels end with the probe for loops a driver cut (reportLoopsCut, derive_lib.glsl): those whose
// loops may run long, and no others, whose loops are bounded well inside lavapipe's 65535 iterations.
#include <gtest/gtest.h>

#include <string>

#include "../unit/grammar_text.h"
#include "codegen/derive_codegen.h"

namespace simeco {
namespace {

bool probes(const std::string& kernel) { return kernel.find("    reportLoopsCut();\n}") != std::string::npos; }

codegen::GeneratedKernels kernelsOf(const std::string& rules) {
    return codegen::generateDeriveKernels({simeco::testing::grammarFromText(simeco::testing::lsystem("A(1)B(2)", rules))});
}

// `count` calls of exp(), summed in one successor parameter.
std::string exponentials(int count) {
    std::string sum = "0";
    for (int k = 0; k < count; ++k) sum += "+exp(x*" + std::to_string(k) + ")";
    return "A(x) --> A(" + sum + ")\n";
}

TEST(LoopProbeTest, OnlyKernelsWhoseLoopsMayRunLongProbe) {
    struct Case {
        const char* what;
        std::string rules;
        bool matchProbes, writeProbes;
    };
    // The write pass walks a context only for the parameters its successor reads (or a condition that draws).
    const Case cases[] = {
        {"context-free", "A(x) --> A(x+1)[B(x)]\nB(x) --> B(x*2)\n", false, false},
        {"a few elementary functions", exponentials(10), false, false},
        {"a left context", "B(y) < A(x) --> A(x+y)\n", true, true},
        {"a right context", "A(x) > B(y) --> A(x+y)\n", true, true},
        {"a context only the match reads", "B(y) < A(x) : y > 1 --> A(x+1)\nA(x) > B(y) --> B(x)\n", true, false},
        {"a context a drawing condition reads", "B(y) < A(x) : y > ran(2) --> A(x+1)\n", true, true},
        {"a while statement", "A(x) : 1 { n = 0; while (n < x) { n = n + 1; } } --> A(n)\n", true, true},
        {"a binomial draw", "A(x) --> A(biran(x, 0.5))\n", true, true},
        {"very many elementary functions", exponentials(200), true, true},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        codegen::GeneratedKernels k = kernelsOf(c.rules);
        EXPECT_EQ(probes(k.match), c.matchProbes);
        EXPECT_EQ(probes(k.write), c.writeProbes);
    }
}

TEST(LoopProbeTest, DecompositionKernelsProbeForTheirOwnRules) {
    codegen::GeneratedKernels k = kernelsOf("A(x) --> A(x+1)\ndecomposition\nmaximum depth: 3\nC(z) < B(y) --> B(y+z)\n");
    EXPECT_FALSE(probes(k.match));
    EXPECT_TRUE(probes(k.decompositionMatch));
    EXPECT_TRUE(probes(k.decompositionWrite));
}

} // namespace
} // namespace simeco
