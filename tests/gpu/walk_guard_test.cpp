// Which modules walk the contexts their productions read (prefetchContexts, production_codegen.cpp): of a symbol
// with such productions, those whose own parameters pass the comparisons the conditions start with, up to the first
// part of a condition that may draw or fail; all of them when a production has no such comparison.
#include <gtest/gtest.h>

#include <string>

#include "../unit/grammar_text.h"
#include "codegen/derive_codegen.h"

namespace simeco {
namespace {

// The generated prefetchContexts() of the step's match pass.
std::string matchPrefetch(const std::string& rules) {
    codegen::GeneratedKernels k =
        codegen::generateDeriveKernels({simeco::testing::grammarFromText(simeco::testing::lsystem("B(1)A(2)", rules))});
    size_t begin = k.match.find("void prefetchContexts(");
    EXPECT_NE(begin, std::string::npos);
    return k.match.substr(begin, k.match.find("\n}\n", begin) - begin);
}

bool walks(const std::string& prefetch) { return prefetch.find("walkLeft(") != std::string::npos; }
bool guarded(const std::string& prefetch) { return prefetch.find("ownParam(") != std::string::npos; }

TEST(WalkGuardTest, OwnParametersDecideWhichModulesWalk) {
    struct Case {
        const char* what;
        std::string rules;
        std::string guard; // the comparison the walk waits for; empty: every A walks
    };
    const Case cases[] = {
        {"no condition", "B(y) < A(x) --> A(x+y)\n", ""},
        {"a comparison", "B(y) < A(x) : x == 3 --> A(x+y)\n", "(ownParam(i, 0u) == (3.0LF))"},
        {"after the context's", "B(y) < A(x) : y > 1 && x < 2 --> A(x+y)\n", "(ownParam(i, 0u) < (2.0LF))"},
        {"a negated one", "B(y) < A(x) : !(x >= 2) --> A(x+y)\n", "(ownParam(i, 0u) >= (2.0LF))"},
        {"after a draw", "B(y) < A(x) : ran(1) < 0.5 && x == 3 --> A(x+y)\n", ""},
        {"after a division", "B(y) < A(x) : y / x > 1 && x == 3 --> A(x+y)\n", ""},
        {"after statements", "B(y) < A(x) : { z = 1; } x == 3 --> A(x+z)\n", ""},
        {"a sum", "B(y) < A(x) : x + 1 == 3 --> A(x+y)\n", ""},
        {"one production without", "B(y) < A(x) : x == 3 --> A(x+y)\nB(y) < A(x) --> A(y)\n", ""},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.what);
        std::string prefetch = matchPrefetch(c.rules);
        EXPECT_TRUE(walks(prefetch)) << prefetch;
        if (c.guard.empty())
            EXPECT_FALSE(guarded(prefetch)) << prefetch;
        else
            EXPECT_NE(prefetch.find(c.guard), std::string::npos) << prefetch;
    }
}

// Productions of one symbol with different comparisons: a module walks when it passes any of them.
TEST(WalkGuardTest, AnyProductionsComparisonLetsAModuleWalk) {
    std::string prefetch = matchPrefetch("B(y) < A(x) : x == 3 --> A(x+y)\nB(y) < A(x) : x > 5 --> A(y)\n");
    EXPECT_NE(prefetch.find("(ownParam(i, 0u) == (3.0LF)) || (ownParam(i, 0u) > (5.0LF))"), std::string::npos)
        << prefetch;
}

} // namespace
} // namespace simeco
