// Quick (Houdini-style) grammars: the seed's examples, the rule forms Houdini users paste, and errors.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lang/quick_grammar.h"

namespace simeco {
namespace {

const std::string kHoudiniDir = std::string(SIMECO_SOURCE_DIR) + "/grammars/houdini/";

std::string spelled(const ir::Grammar& g, const std::vector<ir::SuccessorModule>& modules) {
    std::string out;
    for (const ir::SuccessorModule& m : modules) out += g.alphabet.name(m.sym);
    return out;
}

std::string spelledAxiom(const ir::Grammar& g) {
    std::string out;
    for (const ir::SuccessorModule& m : g.axiom) out += g.alphabet.name(m.sym);
    return out;
}

// Context-free, deterministic rewriting over symbol ids: enough to count the seed examples' modules.
size_t derivedLength(const ir::Grammar& g) {
    std::vector<ir::SymbolId> word;
    for (const ir::SuccessorModule& m : g.axiom) word.push_back(m.sym);
    for (int step = 0; step < g.derivationLength; ++step) {
        std::vector<ir::SymbolId> next;
        for (ir::SymbolId s : word) {
            const ir::Production* rule = nullptr;
            for (const ir::Production& p : g.productions.productions)
                if (p.strict[0].sym == s) rule = rule ? rule : &p;
            if (!rule) {
                next.push_back(s);
                continue;
            }
            for (const ir::SuccessorModule& m : rule->alternatives[0].modules) next.push_back(m.sym);
        }
        word = std::move(next);
    }
    return word.size();
}

TEST(QuickGrammar, SeedRectangularPath) {
    std::string path = kHoudiniDir + "rectangular-path.lsys";
    ASSERT_TRUE(std::filesystem::exists(path));
    ir::Grammar g = lang::parseQuickGrammarFile(path);
    EXPECT_EQ(spelledAxiom(g), "F");
    EXPECT_TRUE(g.view.present);
    EXPECT_FLOAT_EQ(g.view.angleIncrement, 90.0f);
    EXPECT_EQ(g.derivationLength, 3);
    ASSERT_EQ(g.productions.productions.size(), 2u);
    const ir::Production& f = g.productions.productions[0];
    EXPECT_EQ(g.alphabet.name(f.strict[0].sym), "F");
    ASSERT_EQ(f.alternatives.size(), 1u);
    EXPECT_EQ(spelled(g, f.alternatives[0].modules), "F[-XF]F");
    EXPECT_EQ(f.alternatives[0].modules[1].sym, ir::kBranchOpen);
    EXPECT_LT(f.weight, 0.0f);
    EXPECT_EQ(spelled(g, g.productions.productions[1].alternatives[0].modules), "F[X]");
    EXPECT_EQ(derivedLength(g), 100u);
}

TEST(QuickGrammar, SeedAbopTree) {
    std::string path = kHoudiniDir + "abop-1.24d-tree.lsys";
    ASSERT_TRUE(std::filesystem::exists(path));
    ir::Grammar g = lang::parseQuickGrammarFile(path);
    EXPECT_EQ(spelledAxiom(g), "X");
    EXPECT_FLOAT_EQ(g.view.angleIncrement, 20.0f);
    EXPECT_EQ(g.derivationLength, 7);
    ASSERT_EQ(g.productions.productions.size(), 2u);
    EXPECT_EQ(spelled(g, g.productions.productions[0].alternatives[0].modules), "F[+X]F[-X]+X");
    EXPECT_EQ(spelled(g, g.productions.productions[1].alternatives[0].modules), "FF");
    EXPECT_EQ(g.productions.productions[0].loc.line, 5);
    EXPECT_EQ(derivedLength(g), 13956u);
}

TEST(QuickGrammar, ArrowsSynonymsAndComments) {
    ir::Grammar g = lang::parseQuickGrammar("# a comment\n"
                                            "\n"
                                            "premise: F X\n"
                                            "generations: 2\n"
                                            "angle: 22.5\xc2\xb0\n"
                                            "step: 0.5\n"
                                            "F=FF\n"
                                            "  X -> F[+X][-X]\n"
                                            "Y \xe2\x86\x92 F\\/^&|\n",
                                            "syn.lsys");
    EXPECT_EQ(spelledAxiom(g), "FX");
    EXPECT_EQ(g.derivationLength, 2);
    EXPECT_FLOAT_EQ(g.view.angleIncrement, 22.5f);
    EXPECT_FLOAT_EQ(g.view.stepSize, 0.5f);
    ASSERT_EQ(g.productions.productions.size(), 3u);
    EXPECT_EQ(spelled(g, g.productions.productions[0].alternatives[0].modules), "FF");
    EXPECT_EQ(spelled(g, g.productions.productions[1].alternatives[0].modules), "F[+X][-X]");
    EXPECT_EQ(spelled(g, g.productions.productions[2].alternatives[0].modules), "F\\/^&|");
    EXPECT_EQ(g.productions.productions[1].loc.line, 8);
    EXPECT_EQ(g.productions.productions[1].loc.col, 3);
}

TEST(QuickGrammar, ContextsWeightsParametersAndIgnore) {
    ir::Grammar g = lang::parseQuickGrammar("axiom: A B(2) C D +(30)\n"
                                            "iterations: 1\n"
                                            "ignore: +-\n"
                                            "A < B > CD = B(0.5)B : 0.25\n"
                                            "B = F : 0.75\n"
                                            "%=\n",
                                            "ctx.lsys");
    ASSERT_EQ(g.axiom.size(), 5u);
    ASSERT_EQ(g.axiom[1].args.size(), 1u);
    EXPECT_FLOAT_EQ(g.axiom[1].args[0].value, 2.0f);
    ASSERT_EQ(g.axiom[4].args.size(), 1u);
    EXPECT_FLOAT_EQ(g.axiom[4].args[0].value, 30.0f);
    EXPECT_TRUE(g.axiom[0].args.empty());
    EXPECT_FLOAT_EQ(g.view.angleIncrement, 90.0f);
    const auto& prods = g.productions.productions;
    ASSERT_EQ(prods.size(), 3u);
    ASSERT_EQ(prods[0].left.size(), 1u);
    EXPECT_EQ(g.alphabet.name(prods[0].left[0].sym), "A");
    EXPECT_EQ(g.alphabet.name(prods[0].strict[0].sym), "B");
    ASSERT_EQ(prods[0].right.size(), 2u);
    EXPECT_EQ(g.alphabet.name(prods[0].right[1].sym), "D");
    EXPECT_FLOAT_EQ(prods[0].weight, 0.25f);
    EXPECT_FLOAT_EQ(prods[1].weight, 0.75f);
    ASSERT_EQ(prods[0].alternatives[0].modules.size(), 2u);
    ASSERT_EQ(prods[0].alternatives[0].modules[0].args.size(), 1u);
    EXPECT_FLOAT_EQ(prods[0].alternatives[0].modules[0].args[0].value, 0.5f);
    EXPECT_TRUE(prods[0].alternatives[0].modules[1].args.empty());
    // `%=` erases the cut symbol's successor: an empty successor is allowed.
    EXPECT_EQ(prods[2].strict[0].sym, ir::kCut);
    EXPECT_TRUE(prods[2].alternatives[0].modules.empty());
    EXPECT_TRUE(g.skippedInContext(*g.alphabet.find("+")));
    EXPECT_TRUE(g.skippedInContext(*g.alphabet.find("-")));
    EXPECT_FALSE(g.skippedInContext(*g.alphabet.find("A")));
}

struct Malformed {
    const char* what;
    std::string text;
    int line;
    int col;
    const char* message;
};

TEST(QuickGrammar, MalformedGrammarsReportLineAndColumn) {
    const std::string head = "axiom: F\niterations: 3\n";
    const std::vector<Malformed> cases = {
        {"missing axiom", "iterations: 3\nF = FF\n", 1, 1, "missing axiom"},
        {"missing iterations", "axiom: F\nF = FF\n", 1, 1, "missing iteration count"},
        {"arrow without predecessor", head + "  = FF\n", 3, 3, "without a predecessor"},
        {"multi-character predecessor", head + "FX -> FF\n", 3, 2, "predecessor is one module"},
        {"unclosed bracket", head + "F = F[+F\n", 3, 6, "'[' is never closed"},
        {"stray closing bracket", head + "F = F]F\n", 3, 6, "']' without a matching '['"},
        {"unbalanced axiom", "axiom: F[X\niterations: 3\n", 1, 9, "'[' is never closed in the axiom"},
        {"bad angle", head + "angle: 2x0\n", 3, 8, "bad number '2x0'"},
        {"fractional iterations", "axiom: F\niterations: 7.5\n", 2, 13, "whole number"},
        {"unknown setting", head + "colour: 3\n", 3, 1, "unknown setting 'colour'"},
        {"line without a rule", head + "FFF\n", 3, 1, "expected a rule"},
        {"axiom twice", head + "premise: X\n", 3, 1, "axiom given twice"},
        {"probability above 1", head + "F = FF : 1.5\n", 3, 10, "between 0 and 1"},
        {"condition", head + "F : t > 1 = FF\n", 3, 3, "conditions"},
        {"two arrows", head + "F = F = F\n", 3, 7, "one arrow"},
        {"non-ASCII module", head + "F = F\xc3\xa9\n", 3, 6, "non-ASCII"},
        {"bracket in a context", head + "[ < F = FF\n", 3, 1, "brackets cannot appear"},
        {"empty axiom", "axiom:\niterations: 3\n", 1, 7, "empty axiom"},
    };
    for (const Malformed& m : cases) {
        SCOPED_TRACE(m.what);
        try {
            ir::Grammar g = lang::parseQuickGrammar(m.text, "bad.lsys");
            ADD_FAILURE() << "parsed without error";
        } catch (const ir::InputError& e) {
            EXPECT_EQ(e.loc().file, "bad.lsys");
            EXPECT_EQ(e.loc().line, m.line) << e.formatted();
            EXPECT_EQ(e.loc().col, m.col) << e.formatted();
            EXPECT_NE(std::string(e.what()).find(m.message), std::string::npos) << e.formatted();
        }
    }
}

} // namespace
} // namespace simeco
