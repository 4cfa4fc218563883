// The CPU reference engine's semantics, case by case, with strings worked out by hand from cpfg's rules.
#include <gtest/gtest.h>

#include "grammar_text.h"

namespace {

using simeco::testing::deriveText;
using simeco::testing::lsystem;

TEST(DeriveCpu, DolRewritesEveryModuleInParallel) {
    EXPECT_EQ(deriveText(lsystem("A", "A --> AB\nB --> A", 4)), "ABAABABA");
}

TEST(DeriveCpu, ZeroStepsGiveTheAxiom) { EXPECT_EQ(deriveText(lsystem("F[+F]", "F --> FF", 0)), "F[+F]"); }

TEST(DeriveCpu, ParametersAreEvaluatedAsFloatsAndPrintedWithNineDigits) {
    EXPECT_EQ(deriveText(lsystem("A(1)", "A(x) --> A(x/3)B(x*2)", 1)), "A(0.333333343)B(2)");
}

TEST(DeriveCpu, ParameterCountIsPartOfTheMatch) {
    EXPECT_EQ(deriveText(lsystem("A A(1) A(1,2)", "A(x) --> B", 1)), "AB" "A(1,2)");
}

TEST(DeriveCpu, FirstApplicableProductionInFileOrderWins) {
    EXPECT_EQ(deriveText(lsystem("A(1)A(5)", "A(x) : x > 3 --> B\nA(x) : x > 0 --> C\nA(x) --> D", 1)), "CB");
}

TEST(DeriveCpu, RightContextSkipsClosedBranches) {
    EXPECT_EQ(deriveText(lsystem("AB[C]D", "B > D --> X", 1)), "AX[C]D");
}

TEST(DeriveCpu, RightContextEndsAtTheEndOfTheBranch) {
    EXPECT_EQ(deriveText(lsystem("A[B]C", "B > C --> X", 1)), "A[B]C");
}

TEST(DeriveCpu, RightContextEntersABranchOnlyWhenThePatternDoes) {
    EXPECT_EQ(deriveText(lsystem("B[C]D", "B > [C]D --> X", 1)), "X[C]D");
    EXPECT_EQ(deriveText(lsystem("B[CE]D", "B > [C]D --> X", 1)), "B[CE]D");
}

TEST(DeriveCpu, EqualsInRightContextJumpsToTheEndOfTheBranch) {
    EXPECT_EQ(deriveText(lsystem("A[BCD]", "A > [B=] --> X", 1)), "X[BCD]");
}

TEST(DeriveCpu, LeftContextPassesOpeningBracketsAndSkipsBranches) {
    // The left context of C is A: the `[` of its branch is passed, the branch [B] before it is skipped.
    EXPECT_EQ(deriveText(lsystem("A[B][C]", "A < C --> X", 1)), "A[B][X]");
    EXPECT_EQ(deriveText(lsystem("A[B]C", "A < C --> X\nB < C --> Y", 1)), "A[B]X");
}

TEST(DeriveCpu, IgnoredSymbolsAreInvisibleToContext) {
    std::string body = "ignore: +-\nA < B --> X";
    EXPECT_EQ(deriveText(lsystem("A+-B", body, 1)), "A+-X");
}

TEST(DeriveCpu, ConsiderListsTheOnlyVisibleSymbolsAndLooksThroughBrackets) {
    std::string body = "consider: AB\nA > B --> X";
    EXPECT_EQ(deriveText(lsystem("AC[B]", body, 1)), "XC[B]");
}

TEST(DeriveCpu, ContextParametersBindToTheProduction) {
    EXPECT_EQ(deriveText(lsystem("A(2)B(3)C(4)", "A(a) < B(b) > C(c) --> B(a+b+c)", 1)), "A(2)B(9)C(4)");
}

TEST(DeriveCpu, MultiModuleStrictPredecessor) {
    EXPECT_EQ(deriveText(lsystem("ABAB", "AB --> C", 1)), "CC");
}

TEST(DeriveCpu, SignalPropagatesOneModulePerStep) {
    // ABOP 1.6: a signal b moves right through a string of a's.
    std::string body = "b < a --> b\nb --> a";
    EXPECT_EQ(deriveText(lsystem("baaaaaaa", body, 3)), "aaabaaaa");
}

// A ring L-system's contexts go on from the other end of the string, once per pattern.
TEST(DeriveCpu, RingContextsWrapAroundTheString) {
    EXPECT_EQ(deriveText(lsystem("SBBB", "ring lsystem\nS --> B\nS < B --> S", 4)), "SBBB");
    EXPECT_EQ(deriveText(lsystem("SBBB", "S --> B\nS < B --> S", 4)), "BBBB");
    EXPECT_EQ(deriveText(lsystem("BBBS", "ring lsystem\nS --> B\nB > S --> S", 4)), "BBBS");
    EXPECT_EQ(deriveText(lsystem("AB", "ring lsystem\nA > BAB --> X", 1)), "XB");
    EXPECT_EQ(deriveText(lsystem("AB", "ring lsystem\nA > BABA --> X", 1)), "AB");
    EXPECT_EQ(deriveText(lsystem("AB", "ring lsystem\nBAB < A --> X", 1)), "AB");
    EXPECT_EQ(deriveText(lsystem("AB", "ring lsystem\nAB < A --> X", 1)), "XB");
}

TEST(DeriveCpu, CutRemovesTheRestOfTheBranchInTheNextStep) {
    std::string body = "B --> %";
    EXPECT_EQ(deriveText(lsystem("A[BCD]E", body, 1)), "A[%CD]E");
    EXPECT_EQ(deriveText(lsystem("A[BCD]E", body, 2)), "A[]E");
}

TEST(DeriveCpu, EmptySuccessorErases) { EXPECT_EQ(deriveText(lsystem("ABA", "B --> *", 1)), "AA"); }

TEST(DeriveCpu, DecompositionAppliesAfterEachStepUpToMaximumDepth) {
    std::string body = "A --> AB\ndecomposition\nmaximum depth: 2\nB --> CD\nC --> E";
    // Step 1: A -> AB; B decomposes to CD (depth 1), C to E (depth 2).
    EXPECT_EQ(deriveText(lsystem("A", body, 1)), "AED");
    std::string shallow = "A --> AB\ndecomposition\nB --> CD\nC --> E";
    EXPECT_EQ(deriveText(lsystem("A", shallow, 1)), "ACD");
}

TEST(DeriveCpu, DecompositionIsNotAppliedToTheAxiom) {
    EXPECT_EQ(deriveText(lsystem("B", "decomposition\nB --> C", 0)), "B");
}

TEST(DeriveCpu, StatementsLocalsAndGlobals) {
    std::string body = "Start: {n = 10;}\nEndEach: {n = n + 1;}\nA(x) : {y = x * 2;} y < 100 {z = y + n;} --> A(z)";
    // Step 1: y = 2, z = 2 + 10; step 2: y = 24, z = 24 + 11.
    EXPECT_EQ(deriveText(lsystem("A(1)", body, 2)), "A(35)");
}

TEST(DeriveCpu, ControlFlowStatements) {
    std::string body = "A(x) : {s = 0; i = 0; while (i < x) { s = s + i; i = i + 1; } if (s > 5) { s = -s; } else { s = s; }} --> A(s)";
    EXPECT_EQ(deriveText(lsystem("A(4)", body, 1)), "A(-6)");
}

TEST(DeriveCpu, StepCounterQAndLengthZ) {
    EXPECT_EQ(deriveText(lsystem("A(0)", "A(x) --> A(x + Q * 10 + Z)", 2)), "A(34)");
}

TEST(DeriveCpu, ArraysAreRowMajor) {
    std::string body = "A(x) --> A(m[1][2] + m[0][0])";
    std::string text = "Lsystem: 1\ndefine: { array m[2][3] = {1, 2, 3, 4, 5, 6}; }\nderivation length: 1\n"
                       "Axiom: A(0)\n" + body + "\nendlsystem\n";
    EXPECT_EQ(deriveText(text), "A(7)");
}

TEST(DeriveCpu, CpfgMathConventions) {
    // Degrees in trigonometry, `^` as a left-associative power below unary minus, trunc rounding.
    EXPECT_EQ(deriveText(lsystem("A", "A --> B(sin(90), -2^2, 2^3^2, trunc(2.5), 7%3)", 1)), "B(1,4,64,3,1)");
}

TEST(DeriveCpu, TabContinuesAProductionOntoTheNextLine) {
    EXPECT_EQ(deriveText(lsystem("A", "A -->\n\tB\n\tC", 1)), "BC");
}

TEST(DeriveCpu, StochasticChoiceIsDeterministicPerSeedAndVariesAcrossSeeds) {
    std::string text = "Lsystem: 1\nseed: 7\nderivation length: 6\nAxiom: F\nF --> FA : 1\nF --> FB : 1\nendlsystem\n";
    std::string a = deriveText(text), b = deriveText(text);
    EXPECT_EQ(a, b);
    std::string other = deriveText(text, -1, 12345);
    EXPECT_NE(a, other);
    EXPECT_EQ(a.size(), 7u); // F and one of A or B per step
}

TEST(DeriveCpu, RanDrawsFromTheCounterBasedStream) {
    std::string text = lsystem("A(0)A(0)", "A(x) --> A(ran(1))", 1);
    std::string first = deriveText(text, -1, 1), again = deriveText(text, -1, 1), other = deriveText(text, -1, 2);
    EXPECT_EQ(first, again);
    EXPECT_NE(first, other);
    // Two modules draw from different counters: their values differ.
    size_t split = first.find(")A(");
    ASSERT_NE(split, std::string::npos);
    std::string firstValue = first.substr(2, split - 2);
    std::string secondValue = first.substr(split + 3, first.size() - split - 4);
    EXPECT_NE(firstValue, secondValue);
}

TEST(DeriveCpu, PlantsHaveTheirOwnRandomStreams) {
    simeco::ir::Grammar g = simeco::testing::grammarFromText(lsystem("A(0)", "A(x) --> A(ran(1))", 1));
    simeco::stream::DeriveOptions options;
    options.plants = 3;
    simeco::stream::DeriveResult r = simeco::cpu::deriveCpu(g, options);
    ASSERT_EQ(r.string.plants(), 3u);
    EXPECT_NE(r.string.params[0], r.string.params[static_cast<size_t>(r.string.stride)]);
}

TEST(DeriveCpu, LongModuleNamesFromPredecessors) {
    std::string body = "Apex(x) --> Stem(x)Apex(x+1)\nStem(x) --> Stem(x)";
    EXPECT_EQ(deriveText(lsystem("Apex(0)", body, 2)), "Stem(0)Stem(1)Apex(2)");
}

TEST(DeriveCpu, DeclaredModuleNamesAreReadLongestFirst) {
    std::string text = "Lsystem: 1\nmodule Bud BudScale\nderivation length: 2\nAxiom: Bud\n"
                       "Bud --> F BudScale Bud\nendlsystem\n";
    EXPECT_EQ(deriveText(text), "FBudScaleFBudScaleBud");
}

} // namespace
