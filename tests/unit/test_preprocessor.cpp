// The cpp subset cpfg files rely on: defines with and without arguments, conditionals, comments,
// continued lines, and locations that survive expansion.
#include <gtest/gtest.h>

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

TEST(Preprocessor, HashModulesAreNotDirectives) {
    EXPECT_EQ(expand("#(3)F\n"), "#(3)F\n");
}

} // namespace
