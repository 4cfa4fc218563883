// The cpp subset cpfg files rely on: defines with and without arguments, conditionals, comments,
// continued lines, and locations that survive expansion.
#include <gtest/gtest.h>

#include <algorithm>

#include "lang/cpfg_preprocessor.h"

namespace {

using simeco::lang::preprocessText;

std::string expand(const std::string& text, const simeco::lang::PredefinedMacros& macros = {}) {
    return preprocessText(text, "test.l", macros).text();
}

TEST(Preprocessor, ObjectAndFunctionLikeMacros) {
    EXPECT_EQ(expand("#define N 18\n#define SQ(x) ((x)*(x))\nA(N)B(SQ(N+1))\n"), "\n\nA(18)B(((18+1)*(18+1)))\n");
}

TEST(Preprocessor, IdentifiersGluedToOtherNamesOrNumbersAreNotExpanded) {
    EXPECT_EQ(expand("#define A 5\nFA A 2A A_\n"), "\nFA 5 2A A_\n");
}

TEST(Preprocessor, ConditionalsSelectLines) {
    std::string text = "#define LEAVES 1\n#if LEAVES==1\nyes\n#elif LEAVES==2\nno\n#else\nnever\n#endif\n"
                       "#ifdef MISSING\nhidden\n#endif\n#ifndef MISSING\nshown\n#endif\n";
    std::string out = expand(text);
    EXPECT_NE(out.find("yes"), std::string::npos);
    EXPECT_EQ(out.find("no\n"), std::string::npos);
    EXPECT_EQ(out.find("never"), std::string::npos);
    EXPECT_EQ(out.find("hidden"), std::string::npos);
    EXPECT_NE(out.find("shown"), std::string::npos);
}

TEST(Preprocessor, CommentsKeepLinesAndContinuationsJoinThem) {
    EXPECT_EQ(expand("A /* one\ntwo */ B // rest\n#define L(x) \\\n\t(x+1)\nL(2)\n"), "A  \n B  \n\n(2+1)\n");
}

TEST(Preprocessor, PredefinedMacrosComeFromFunctionSets) {
    EXPECT_EQ(expand("func(WIDTH, 0.5)\n", {{"WIDTH", "1"}}), "func(1, 0.5)\n");
}

TEST(Preprocessor, ExpandedTextPointsAtTheUse) {
    simeco::lang::PreprocessedText out = preprocessText("#define X  abc\n  X\n", "test.l", {});
    size_t at = out.text().find("abc");
    ASSERT_NE(at, std::string::npos);
    EXPECT_EQ(out.locate(at).line, 2);
    EXPECT_EQ(out.locate(at).col, 3);
}

// Macros that double at each level would grow to 2^40 characters: the expansion stops at a bound, with an error
// at the use, in about a second; so does text that many uses make too long together.
TEST(Preprocessor, ExponentialMacroGrowthIsRefusedAtTheUse) {
    std::string bomb = "#define M0 x\n";
    for (int level = 1; level <= 40; ++level)
        bomb += "#define M" + std::to_string(level) + " M" + std::to_string(level - 1) + " M" +
                std::to_string(level - 1) + "\n";
    struct Case {
        const char* uses;
        int line; // the use that passes the bound: the fourth of M20 (2 MiB each)
    };
    for (Case c : {Case{"A --> M40\n", 43}, Case{"A --> M20\nB --> M20\nC --> M20\nD --> M20\nE --> M20\n", 46}}) {
        try {
            preprocessText(bomb + "\n" + c.uses, "test.l", {});
            ADD_FAILURE() << "no error for " << c.uses;
        } catch (const simeco::ir::InputError& e) {
            EXPECT_EQ(e.loc().line, c.line) << e.formatted();
            EXPECT_EQ(e.loc().col, 7) << e.formatted();
            EXPECT_NE(std::string(e.what()).find("grows past 8 MiB"), std::string::npos) << e.formatted();
        }
    }
    // Below the bound, the text is all there: 2^19 x's.
    std::string text = preprocessText(bomb + "\nA --> M19\n", "test.l", {}).text();
    EXPECT_EQ(std::count(text.begin(), text.end(), 'x'), 1 << 19);
}

TEST(Preprocessor, HashModulesAreNotDirectives) {
    EXPECT_EQ(expand("#(3)F\n"), "#(3)F\n");
}

} // namespace
