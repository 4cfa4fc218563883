// cpfg's sub-L-systems: several L-systems in one file, `?(label, s) ... $` handing modules to another one's
// productions and scaling what it draws. Strings and geometry worked out by hand from cpfg's rules.
#include <gtest/gtest.h>

#include <string>

#include "compute/shared/organ_layout.h"
#include "grammar_text.h"
#include "ir/source_loc.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_settings.h"

namespace {

using namespace simeco;
using simeco::testing::deriveText;
using simeco::testing::grammarFromText;

std::string file(const std::string& mainBody, const std::string& subBody, int length = 1) {
    return "Lsystem: 1\nderivation length: " + std::to_string(length) + "\n" + mainBody + "\nendlsystem\n\n" +
           "Lsystem: 2\nderivation length: 9\n" + subBody + "\nendlsystem\n";
}

TEST(SubLsystems, EachLsystemRewritesTheModulesOfItsCalls) {
    // Main's B becomes X; the B that a call hands to L-system 2 grows F by F there, and main's rule leaves it.
    const std::string text = file("Axiom: AB\nA --> F?(2,0.5)B$A\nB --> X", "Axiom: B\nB --> FB", 2);
    EXPECT_EQ(deriveText(text), "F?(2,0.5)FB$F?(2,0.5)B$AX");
}

TEST(SubLsystems, OnlyTheMainLsystemsAxiomAndDerivationLengthCount) {
    EXPECT_EQ(deriveText(file("Axiom: ?(2,1)B$", "Axiom: C\nB --> BB", 3)), "?(2,1)BBBBBBBB$");
}

TEST(SubLsystems, ContextMatchesModulesOfEveryLsystemByName) {
    // The left context of the call's B is main's A, past the ignored `?`; the right context of main's A is the
    // sub-L-system's B.
    const std::string text = file("Axiom: A?(2,1)B$\nignore: ?\nA > B --> D", "Axiom: B\nignore: ?\nA < B --> C", 1);
    EXPECT_EQ(deriveText(text), "D?(2,1)C$");
}

TEST(SubLsystems, CallsNest) {
    const std::string text = "Lsystem: 1\nderivation length: 1\nAxiom: ?(2,1)A$\nendlsystem\n"
                             "Lsystem: 2\nAxiom: A\nA --> ?(3,1)A$B\nendlsystem\n"
                             "Lsystem: 3\nAxiom: A\nA --> Y\nB --> Z\nendlsystem\n";
    EXPECT_EQ(deriveText(text), "?(2,1)?(3,1)A$B$");
    // One more step: A is L-system 3's (Y), B stays L-system 2's (no production).
    EXPECT_EQ(deriveText(text, 2), "?(2,1)?(3,1)Y$B$");
}

TEST(SubLsystems, ASubLsystemsDecompositionAppliesToItsModules) {
    const std::string text = file("Axiom: A?(2,1)A$", "Axiom: A\ndecomposition:\nA --> BC", 0);
    EXPECT_EQ(deriveText(text, 1), "A?(2,1)BC$");
}

// What the turtle draws of a grammar's string.
turtle::Interpretation draw(const std::string& text) {
    ir::Grammar g = grammarFromText(text);
    g.view.lineStyle = ir::LineStyle::Cylinder;
    stream::DeriveOptions options;
    options.homomorphism = true;
    stream::DeriveResult r = cpu::deriveCpu(g, options);
    return turtle::interpretCpu(r.string, turtle::turtleCommands(g.alphabet), {turtle::turtleSettings(g, g.alphabet)});
}

TEST(SubLsystems, ACallScalesLengthsAndWidthsUntilItsReturn) {
    // Steps 1, 0.5 (and 0.25 in the nested call), then 1 again; widths 2, 1, 0.5, 2. A branch does not end a call.
    const turtle::Interpretation r = draw("Lsystem: 1\nAxiom: !(2)F?(2,0.5)F[?(3,0.5)F$]F$F\nendlsystem\n"
                                          "Lsystem: 2\nAxiom: B\nendlsystem\nLsystem: 3\nAxiom: C\nendlsystem\n");
    ASSERT_EQ(r.count[shared::kOrganStem], 5u);
    const float lengths[] = {1.0f, 0.5f, 0.25f, 0.5f, 1.0f};
    const float radii[] = {1.0f, 0.5f, 0.25f, 0.5f, 1.0f};
    for (int k = 0; k < 5; ++k) {
        EXPECT_FLOAT_EQ(r.organs[k].position.w, lengths[k]) << k;
        EXPECT_FLOAT_EQ(r.organs[k].heading.w, radii[k]) << k;
    }
    EXPECT_FLOAT_EQ(r.organs[4].position.y, 2.0f);
}

// The message of the error loading `text` gives, with its line.
std::string errorOf(const std::string& text) {
    try {
        grammarFromText(text);
    } catch (const ir::InputError& e) {
        return std::to_string(e.loc().line) + ": " + e.what();
    }
    return "no error";
}

TEST(SubLsystems, WhatSimecoCannotReadIsAnErrorAtItsLine) {
    EXPECT_NE(errorOf(file("Axiom: A\nA --> ?(7,1)B$", "Axiom: B")).find("4: no L-system is labelled 7"),
              std::string::npos);
    EXPECT_NE(errorOf(file("Axiom: A", "Axiom: B\nB --> ?(1,1)B$")).find("cannot be called"), std::string::npos);
    EXPECT_NE(errorOf(file("Axiom: A", "Axiom: B\nB --> ?(2,1)B$")).find("calls itself"), std::string::npos);
    EXPECT_NE(errorOf(simeco::testing::lsystem("A", "A --> ?(1,1)B$")).find("cannot be called"), std::string::npos);
    EXPECT_NE(errorOf(file("Axiom: A", "Start: {x = 1;}\nAxiom: B")).find("in the main (first) L-system only"),
              std::string::npos);
    EXPECT_NE(errorOf(file("Axiom: A(1)\nA(n) --> ?(n,1)B$", "Axiom: B")).find("label must be a constant"),
              std::string::npos);
    EXPECT_NE(errorOf(file("Axiom: A", "Axiom: B\nB --> F$C")).find("cannot tell which L-system"), std::string::npos);
    EXPECT_NE(errorOf(file("Axiom: A", "Axiom: B\n$ --> F")).find("does not rewrite"), std::string::npos);
    EXPECT_NE(errorOf(file("Axiom: A\nignore: +\nA > B --> C", "Axiom: B\nignore: -\nA < B --> C"))
                  .find("the same 'ignore:'"),
              std::string::npos);
}

} // namespace
