// SimEco `.eco` scripts: the thesis and generator scripts parse unchanged into the scene and grammars they
// describe, and malformed scripts fail at the right line and column.
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lang/eco_parser.h"

namespace simeco {
namespace {

const std::string kSeedScripts = std::string(SIMECO_SHARED_DIR) + "/seed-scripts/";

ir::EcoScene parseSeedScript(const std::string& name) {
    std::string path = kSeedScripts + name;
    if (!std::filesystem::exists(path)) throw std::runtime_error("seed script missing: " + path);
    return lang::parseEcoFile(path);
}

// Evaluates the arithmetic and logic of a condition or argument over a frame (no calls but light()).
float eval(const ir::Expr& e, const std::vector<float>& frame) {
    auto arg = [&](size_t i) { return eval(e.args.at(i), frame); };
    switch (e.op) {
    case ir::Op::Const: return e.value;
    case ir::Op::Local: return frame.at(static_cast<size_t>(e.slot));
    case ir::Op::Neg: return -arg(0);
    case ir::Op::Not: return arg(0) == 0.0f ? 1.0f : 0.0f;
    case ir::Op::Add: return arg(0) + arg(1);
    case ir::Op::Sub: return arg(0) - arg(1);
    case ir::Op::Mul: return arg(0) * arg(1);
    case ir::Op::Div: return arg(0) / arg(1);
    case ir::Op::Lt: return arg(0) < arg(1);
    case ir::Op::Le: return arg(0) <= arg(1);
    case ir::Op::Gt: return arg(0) > arg(1);
    case ir::Op::Ge: return arg(0) >= arg(1);
    case ir::Op::Eq: return arg(0) == arg(1);
    case ir::Op::Ne: return arg(0) != arg(1);
    case ir::Op::And: return (arg(0) != 0.0f && arg(1) != 0.0f) ? 1.0f : 0.0f;
    case ir::Op::Or: return (arg(0) != 0.0f || arg(1) != 0.0f) ? 1.0f : 0.0f;
    case ir::Op::Call:
        if (e.fn == ir::Builtin::Light) return 1.0f; // no light grid
        ADD_FAILURE() << "unexpected call in test evaluator";
        return NAN;
    default: ADD_FAILURE() << "unexpected op in test evaluator"; return NAN;
    }
}

bool holds(const ir::Production& p, const std::vector<float>& frame) {
    return !p.condition || eval(*p.condition, frame) != 0.0f;
}

// Symbol names of an alternative, space separated: "S [ rotr S L ] S".
std::string spelled(const ir::Grammar& g, const ir::Alternative& alt) {
    std::string out;
    for (const ir::SuccessorModule& m : alt.modules) out += (out.empty() ? "" : " ") + g.alphabet.name(m.sym);
    return out;
}

std::string name(const ir::Grammar& g, const ir::PatternModule& m) { return g.alphabet.name(m.sym); }

// The production rewriting `letter` whose condition holds for `frame` first, as the engine picks it.
const ir::Production* firstMatch(const ir::Grammar& g, const std::string& letter, const std::vector<float>& frame) {
    for (const ir::Production& p : g.productions.productions)
        if (name(g, p.strict[0]) == letter && p.left.empty() && p.right.empty() &&
            static_cast<size_t>(p.frameSize) == frame.size() && holds(p, frame))
            return &p;
    return nullptr;
}

void expectNumber(const ir::EcoNumber& n, float value) {
    EXPECT_FALSE(n.random);
    EXPECT_FLOAT_EQ(n.min, value);
}

void expectRange(const ir::EcoNumber& n, float lo, float hi) {
    EXPECT_TRUE(n.random);
    EXPECT_FLOAT_EQ(n.min, lo);
    EXPECT_FLOAT_EQ(n.max, hi);
}

TEST(EcoParser, AllSeedScriptsParseUnchanged) {
    const char* names[] = {"lantana-camara.eco", "rosa-rugosa.eco", "oxalis-corniculata.eco",
                           "lgrammar-testplant.eco"};
    int parsed = 0;
    for (const char* n : names) {
        SCOPED_TRACE(n);
        ASSERT_TRUE(std::filesystem::exists(kSeedScripts + n)) << "missing " << kSeedScripts + n;
        ir::EcoScene scene = parseSeedScript(n);
        ASSERT_EQ(scene.plants.size(), 1u);
        ir::Grammar g = lang::compileEcoPlant(scene, 0);
        EXPECT_FALSE(g.axiom.empty());
        EXPECT_FALSE(g.productions.productions.empty());
        EXPECT_EQ(g.maxParams(), 1);
        ++parsed;
    }
    EXPECT_EQ(parsed, 4);
}

TEST(EcoParser, LantanaSceneValues) {
    ir::EcoScene scene = parseSeedScript("lantana-camara.eco");
    EXPECT_EQ(scene.name, "MySys");
    EXPECT_FLOAT_EQ(scene.version, 1.0f);
    expectNumber(scene.soilPH, 7.0f);
    expectNumber(scene.rainRate, 0.9f);
    expectNumber(scene.dayLight, 12.0f);
    EXPECT_TRUE(scene.warnings.empty());

    const ir::EcoPlant& plant = scene.plants[0];
    EXPECT_EQ(plant.name, "Lantan camara");
    expectNumber(plant.position.x, 0.0f);
    expectNumber(plant.direction.y, 0.1f);
    expectNumber(plant.deriveTime, 3.0f);
    EXPECT_FALSE(plant.derivationLength.has_value());

    const ir::EcoOrgan& apex = plant.organ(ir::EcoOrganKind::Apex);
    EXPECT_TRUE(apex.present);
    EXPECT_TRUE(apex.stages.empty());
    EXPECT_FALSE(plant.organ(ir::EcoOrganKind::Root).present);

    const ir::EcoOrgan& stem = plant.organ(ir::EcoOrganKind::Stem);
    EXPECT_EQ(stem.stages.size(), 12u);
    EXPECT_EQ(stem.stages.count(5), 0u);
    EXPECT_EQ(stem.stages.count(99), 1u);
    ASSERT_TRUE(stem.defaultStage.has_value());
    const ir::EcoStage& s3 = stem.stages.at(3);
    EXPECT_EQ(*s3.model, "DefaultStem.i");
    EXPECT_EQ(*s3.texture, "seafloor.bmp");
    expectNumber(*s3.growRate, 0.5f);
    expectNumber(*s3.growTime, 3.0f);
    expectNumber(*s3.broadenRate, 0.2f);
    expectRange(*s3.coneNoise, 0.0f, 0.007f);
    expectNumber(*s3.noiseTime, 0.5f);
    expectNumber(s3.color->g, 1.0f);
    expectNumber(s3.color->r, 0.0f);
    expectNumber(s3.material->values[0], 0.5f);
    expectNumber(s3.material->values[5], 0.1f);
    EXPECT_EQ(s3.loc.line, 28);
    // Stage 5 is not declared: the Default stage answers for it.
    EXPECT_EQ(stem.stageFor(5), &*stem.defaultStage);
    EXPECT_EQ(stem.stageFor(3), &s3);
    EXPECT_FALSE(stem.stages.at(0).growRate.has_value());

    const ir::EcoOrgan& leaf = plant.organ(ir::EcoOrganKind::Leaf);
    EXPECT_EQ(leaf.stages.size(), 5u);
    EXPECT_EQ(*leaf.stages.at(0).model, "馬櫻丹.i");
    expectNumber(leaf.stages.at(2).material->values[0], 1.5f);

    EXPECT_EQ(plant.grow.rules.size(), 12u);
    ASSERT_EQ(plant.grow.axiom.size(), 1u);
    EXPECT_EQ(plant.grow.axiom[0].name, "A");
}

TEST(EcoParser, LantanaGrammar) {
    ir::EcoScene scene = parseSeedScript("lantana-camara.eco");
    ir::Grammar g = lang::compileEcoPlant(scene, 0);
    EXPECT_EQ(g.sourceFile, kSeedScripts + "lantana-camara.eco");
    ASSERT_EQ(g.axiom.size(), 1u);
    EXPECT_EQ(g.alphabet.name(g.axiom[0].sym), "A");
    ASSERT_EQ(g.axiom[0].args.size(), 1u);
    EXPECT_FLOAT_EQ(g.axiom[0].args[0].value, 0.0f);
    EXPECT_EQ(g.axiomLoc.line, 151);
    EXPECT_EQ(g.productions.productions.size(), 12u);
    // No DerivationLength: the longer of 10 steps and one step per rule.
    EXPECT_EQ(g.derivationLength, 12);

    // Fixed symbol numbering: brackets and cut, then A S L F T R, then the rotations.
    EXPECT_EQ(*g.alphabet.find("A"), 3u);
    EXPECT_EQ(*g.alphabet.find("R"), 8u);
    EXPECT_EQ(*g.alphabet.find("rotr"), 9u);
    // Rotations are attachments, not plant parts: context matching looks through them.
    EXPECT_TRUE(g.skippedInContext(*g.alphabet.find("rotr")));
    EXPECT_TRUE(g.skippedInContext(*g.alphabet.find("rotu")));
    EXPECT_FALSE(g.skippedInContext(*g.alphabet.find("S")));

    // S(1) -> prob(0.7) S(2)[...]x4 S(0) | S(99);
    const ir::Production* s1 = firstMatch(g, "S", {1.0f});
    ASSERT_NE(s1, nullptr);
    ASSERT_EQ(s1->alternatives.size(), 2u);
    EXPECT_FLOAT_EQ(s1->alternatives[0].probability, 0.7f);
    EXPECT_FLOAT_EQ(s1->alternatives[1].probability, 1.0f);
    EXPECT_EQ(s1->alternatives[0].modules.size(), 30u);
    // rotu turns about the parent's axis: lowered before the rotr it follows; a branch then rolls a quarter turn
    // back to take its parent's direction as its reference axis (eco_compile.cpp).
    EXPECT_EQ(spelled(g, s1->alternatives[0]).substr(0, 24), "S [ rotu rotr / S L ] [ ");
    EXPECT_EQ(spelled(g, s1->alternatives[1]), "S");
    EXPECT_FLOAT_EQ(s1->alternatives[1].modules[0].args[0].value, 99.0f);
    const ir::SuccessorModule& rotu = s1->alternatives[0].modules[2];
    EXPECT_EQ(g.alphabet.name(rotu.sym), "rotu");
    ASSERT_TRUE(rotu.args[0].isConst());
    EXPECT_FLOAT_EQ(rotu.args[0].value, 1.5708f);
    EXPECT_EQ(s1->alternatives[0].modules[1].sym, ir::kBranchOpen);
    const ir::SuccessorModule& roll = s1->alternatives[0].modules[4];
    EXPECT_EQ(g.alphabet.name(roll.sym), "/");
    ASSERT_TRUE(roll.args[0].isConst());
    EXPECT_FLOAT_EQ(roll.args[0].value, -90.0f);
    EXPECT_TRUE(g.skippedInContext(roll.sym));
    EXPECT_EQ(s1->alternatives[0].modules[7].sym, ir::kBranchClose);

    // S(2) -> S(3): the literal stage is a slot with the condition slot == 2.
    const ir::Production* s2 = firstMatch(g, "S", {2.0f});
    ASSERT_NE(s2, nullptr);
    EXPECT_EQ(s2->frameSize, 1);
    EXPECT_EQ(s2->strict[0].paramSlots, std::vector<int>{0});
    EXPECT_FLOAT_EQ(s2->alternatives[0].modules[0].args[0].value, 3.0f);

    // L(1) -> L(2) comes before the step production and wins for L(1).
    const ir::Production* l1 = firstMatch(g, "L", {1.0f});
    ASSERT_NE(l1, nullptr);
    EXPECT_FLOAT_EQ(l1->alternatives[0].modules[0].args[0].value, 2.0f);

    // L(i) -> L(i + 1, 1 < i < 6): advances L(2) .. L(5), leaves L(0) and L(6) alone.
    const ir::Production* step = nullptr;
    for (const ir::Production& p : g.productions.productions)
        if (p.slotNames == std::vector<std::string>{"i"}) step = &p;
    ASSERT_NE(step, nullptr);
    ASSERT_TRUE(step->condition.has_value());
    EXPECT_EQ(step->condition->op, ir::Op::And);
    EXPECT_FALSE(holds(*step, {0.0f}));
    EXPECT_FALSE(holds(*step, {1.0f}));
    EXPECT_TRUE(holds(*step, {2.0f}));
    EXPECT_TRUE(holds(*step, {5.0f}));
    EXPECT_FALSE(holds(*step, {6.0f}));
    ASSERT_EQ(step->alternatives.size(), 1u);
    EXPECT_FLOAT_EQ(step->alternatives[0].probability, 1.0f);
    EXPECT_FLOAT_EQ(eval(step->alternatives[0].modules[0].args[0], {3.0f}), 4.0f);
    EXPECT_EQ(firstMatch(g, "L", {4.0f}), step);

    // S(3) > S(3) -> S(4): right context, both stages tested.
    const ir::Production* right = nullptr;
    const ir::Production* left = nullptr;
    for (const ir::Production& p : g.productions.productions) {
        if (!p.right.empty()) right = &p;
        if (!p.left.empty()) left = &p;
    }
    ASSERT_NE(right, nullptr);
    ASSERT_EQ(right->right.size(), 1u);
    EXPECT_EQ(right->frameSize, 2);
    EXPECT_EQ(right->strict[0].paramSlots, std::vector<int>{0});
    EXPECT_EQ(right->right[0].paramSlots, std::vector<int>{1});
    EXPECT_TRUE(holds(*right, {3.0f, 3.0f}));
    EXPECT_FALSE(holds(*right, {3.0f, 4.0f}));
    EXPECT_FALSE(holds(*right, {4.0f, 3.0f}));

    // S(4) < S(10) -> S(6): left context S(10), in text order: the context is slot 0.
    ASSERT_NE(left, nullptr);
    EXPECT_EQ(name(g, left->left[0]), "S");
    EXPECT_EQ(left->left[0].paramSlots, std::vector<int>{0});
    EXPECT_EQ(left->strict[0].paramSlots, std::vector<int>{1});
    EXPECT_TRUE(holds(*left, {4.0f, 10.0f}));
    EXPECT_FALSE(holds(*left, {10.0f, 4.0f}));
    EXPECT_EQ(left->loc.line, 167);
}

TEST(EcoParser, RosaAlternativesAndRandomAngles) {
    ir::EcoScene scene = parseSeedScript("rosa-rugosa.eco");
    const ir::EcoPlant& plant = scene.plants[0];
    EXPECT_EQ(plant.name, "Rose Rugosa");
    const ir::EcoOrgan& stem = plant.organ(ir::EcoOrganKind::Stem);
    EXPECT_EQ(stem.stages.size(), 20u);
    expectRange(*stem.stages.at(22).growRate, 0.02f, 0.045f);
    expectNumber(*stem.stages.at(0).geotropism, -0.5f);
    expectNumber(*stem.stages.at(0).strength, 0.9f);
    expectRange(plant.organ(ir::EcoOrganKind::Leaf).stages.at(2).material->values[1], 1.1f, 1.5f);

    ir::Grammar g = lang::compileEcoPlant(scene, 0);
    EXPECT_EQ(g.productions.productions.size(), 23u);
    EXPECT_EQ(g.derivationLength, 23);
    ASSERT_EQ(g.axiom.size(), 1u);

    // S(10) -> prob(0.5) S(11) | prob(0.5) S(12) | S(14)[...][...];
    const ir::Production* s10 = firstMatch(g, "S", {10.0f});
    ASSERT_NE(s10, nullptr);
    ASSERT_EQ(s10->alternatives.size(), 3u);
    EXPECT_FLOAT_EQ(s10->alternatives[0].probability, 0.5f);
    EXPECT_FLOAT_EQ(s10->alternatives[1].probability, 0.5f);
    EXPECT_FLOAT_EQ(s10->alternatives[2].probability, 1.0f);
    EXPECT_EQ(spelled(g, s10->alternatives[2]), "S [ rotr / S L ] [ rotu rotr / S L ]");

    // S(6) -> prob(0.8) S(7)[rotr(1.2472) rotu(rand(0.0, 6.2832)) S(20) S(21)] | S(7);
    const ir::Production* s6 = firstMatch(g, "S", {6.0f});
    ASSERT_NE(s6, nullptr);
    const ir::Expr& angle = s6->alternatives[0].modules[2].args[0];
    EXPECT_EQ(g.alphabet.name(s6->alternatives[0].modules[2].sym), "rotu");
    ASSERT_EQ(angle.op, ir::Op::Add);
    EXPECT_FLOAT_EQ(angle.args[0].value, 0.0f);
    ASSERT_EQ(angle.args[1].op, ir::Op::Call);
    EXPECT_EQ(angle.args[1].fn, ir::Builtin::Ran);
    EXPECT_FLOAT_EQ(angle.args[1].args[0].value, 6.2832f);

    // Contexts with both letters: S(18) < L(1) -> L(3).
    bool found = false;
    for (const ir::Production& p : g.productions.productions) {
        if (p.left.size() == 1 && name(g, p.strict[0]) == "L" && holds(p, {18.0f, 1.0f})) {
            EXPECT_FLOAT_EQ(p.alternatives[0].modules[0].args[0].value, 3.0f);
            found = true;
        }
    }
    EXPECT_TRUE(found);
}

TEST(EcoParser, OxalisRandomRotationWithNegativeBound) {
    ir::EcoScene scene = parseSeedScript("oxalis-corniculata.eco");
    const ir::EcoOrgan& stem = scene.plants[0].organ(ir::EcoOrganKind::Stem);
    expectRange(*stem.stages.at(0).growRate, 0.25625f, 0.5f);
    expectRange(*stem.stages.at(0).growTime, 2.0f, 4.0f);
    ir::Grammar g = lang::compileEcoPlant(scene, 0);
    EXPECT_EQ(g.productions.productions.size(), 4u);
    const ir::Production* a0 = firstMatch(g, "A", {0.0f});
    ASSERT_NE(a0, nullptr);
    EXPECT_FLOAT_EQ(a0->alternatives[0].probability, 0.99f);
    EXPECT_EQ(spelled(g, a0->alternatives[1]), "A");
    // S(0) -> prob(0.5) rotr(rand(-1.2, 1.2)) S(1)[...] S(0) | S(0);
    const ir::Production* s0 = firstMatch(g, "S", {0.0f});
    ASSERT_NE(s0, nullptr);
    const ir::Expr& angle = s0->alternatives[0].modules[0].args[0];
    ASSERT_EQ(angle.op, ir::Op::Add);
    EXPECT_FLOAT_EQ(angle.args[0].value, -1.2f);
    EXPECT_FLOAT_EQ(angle.args[1].args[0].value, 2.4f);
    EXPECT_EQ(spelled(g, s0->alternatives[0]), "rotr S [ rotu rotr / A ] S");
}

TEST(EcoParser, GeneratorScriptWithPageBreakBraces) {
    ir::EcoScene scene = parseSeedScript("lgrammar-testplant.eco");
    EXPECT_EQ(scene.name, "TestSys");
    const ir::EcoPlant& plant = scene.plants[0];
    EXPECT_EQ(plant.name, "TestPlant");
    expectNumber(plant.direction.y, 1.0f);
    // Stages 7..17 of Stem and 7..24 of Leaf come after their blocks have closed.
    const ir::EcoOrgan& stem = plant.organ(ir::EcoOrganKind::Stem);
    const ir::EcoOrgan& leaf = plant.organ(ir::EcoOrganKind::Leaf);
    EXPECT_EQ(stem.stages.size(), 18u);
    EXPECT_EQ(leaf.stages.size(), 24u);
    EXPECT_EQ(leaf.stages.count(0), 0u);
    expectNumber(*stem.stages.at(17).growRate, 0.079221f);
    expectNumber(*leaf.stages.at(24).growRate, 0.042f);
    EXPECT_EQ(*stem.stages.at(2).texture, "seafloor.bmp"); // TextureFront
    expectNumber(stem.stages.at(2).material->values[5], 0.1f); // MaterialFront across two lines
    EXPECT_TRUE(plant.organ(ir::EcoOrganKind::Root).present);
    EXPECT_TRUE(plant.organ(ir::EcoOrganKind::Fruit).present);
    EXPECT_TRUE(plant.organ(ir::EcoOrganKind::Flower).present);
    // Three stray braces and two runs of stages outside their blocks, each reported once.
    ASSERT_EQ(scene.warnings.size(), 5u);
    EXPECT_EQ(scene.warnings[0].loc.line, 75);
    EXPECT_NE(scene.warnings[0].message.find("added to the Stem block"), std::string::npos);

    ir::Grammar g = lang::compileEcoPlant(scene, 0);
    EXPECT_EQ(g.productions.productions.size(), 19u);
    EXPECT_EQ(g.derivationLength, 19);
    // S(4) -> S(0) [rotr rotu S(9)] [rotr rotu S(12)] rotr rotu S(5);
    const ir::Production* s4 = firstMatch(g, "S", {4.0f});
    ASSERT_NE(s4, nullptr);
    EXPECT_EQ(spelled(g, s4->alternatives[0]), "S [ rotu rotr / S ] [ rotu rotr / S ] rotu rotr S");
    EXPECT_FLOAT_EQ(s4->alternatives[0].modules[2].args[0].value, -2.102210f);
}

const char* kMiniScript = R"(ecosystem 2.0 "two" {
  soilph = rand(6.0, 7.5);
  Gravity = vector(0.0, -1.0, 0.0);
  PLANT "first" {
    position = vector(1.0, 0.0, rand(-2.0, 2.0));
    DerivationLength = 4;
    stem { stage 1 { growrate = 0.2; } default { GrowRate = 0.1; } }
    grow {
      w = S(1) [ rotr(0.5) L(0) ];
      L(i) -> prob(0.5) L(i + 1, i < 3) | S(0);
      S(1) -> prob(0.25) null | S(2);
      L(5) -> null;
    }
  }
  Plant "second" {
    DeriveTime = rand(2.0, 4.0);
    Grow { w = A(0); A(0) -> A(0) S(0); }
  }
}
)";

TEST(EcoParser, KeywordsAnyCaseAndSeveralPlants) {
    ir::EcoScene scene = lang::parseEcoText(kMiniScript, "mini.eco");
    EXPECT_EQ(scene.file, "mini.eco");
    EXPECT_FLOAT_EQ(scene.version, 2.0f);
    expectRange(scene.soilPH, 6.0f, 7.5f);
    expectNumber(scene.gravity.y, -1.0f);
    ASSERT_EQ(scene.plants.size(), 2u);
    const ir::EcoPlant& first = scene.plants[0];
    expectNumber(first.position.x, 1.0f);
    expectRange(first.position.z, -2.0f, 2.0f);
    EXPECT_EQ(first.derivationLength, 4);
    const ir::EcoOrgan& stem = first.organ(ir::EcoOrganKind::Stem);
    expectNumber(*stem.stageFor(1)->growRate, 0.2f);
    expectNumber(*stem.stageFor(7)->growRate, 0.1f);
    expectRange(scene.plants[1].deriveTime, 2.0f, 4.0f);
    EXPECT_EQ(scene.plants[1].deriveTime.loc.line, 16);

    ir::Grammar g = lang::compileEcoPlant(scene, 0);
    EXPECT_EQ(g.derivationLength, 4);
    ASSERT_EQ(g.axiom.size(), 5u);
    EXPECT_EQ(g.axiom[1].sym, ir::kBranchOpen);
    ASSERT_EQ(g.axiom[2].args.size(), 1u);
    EXPECT_TRUE(g.axiom[2].args[0].isConst());
    EXPECT_FLOAT_EQ(g.axiom[2].args[0].value, 0.5f);

    // A step successor with a fallback: the step production, then the fallback without the step condition.
    const auto& prods = g.productions.productions;
    ASSERT_EQ(prods.size(), 4u);
    EXPECT_TRUE(holds(prods[0], {2.0f}));
    EXPECT_FALSE(holds(prods[0], {3.0f}));
    ASSERT_EQ(prods[0].alternatives.size(), 2u);
    EXPECT_FLOAT_EQ(prods[0].alternatives[0].probability, 0.5f);
    EXPECT_EQ(spelled(g, prods[0].alternatives[1]), "S");
    EXPECT_FALSE(prods[1].condition.has_value());
    ASSERT_EQ(prods[1].alternatives.size(), 1u);
    EXPECT_EQ(spelled(g, prods[1].alternatives[0]), "S");

    // `null` erases: an empty alternative, here drawn with probability 0.25.
    ASSERT_EQ(prods[2].alternatives.size(), 2u);
    EXPECT_TRUE(prods[2].alternatives[0].modules.empty());
    EXPECT_FLOAT_EQ(prods[2].alternatives[0].probability, 0.25f);
    EXPECT_TRUE(prods[3].alternatives[0].modules.empty());
    EXPECT_TRUE(holds(prods[3], {5.0f}));

    ir::Grammar second = lang::compileEcoPlant(scene, 1);
    EXPECT_EQ(second.derivationLength, lang::kDefaultEcoDerivationLength);
    EXPECT_EQ(second.productions.productions.size(), 1u);
    EXPECT_EQ(*second.alphabet.find("S"), *g.alphabet.find("S"));

    EXPECT_THROW(lang::compileEcoPlant(scene, 2), ir::InputError);
}

TEST(EcoParser, UnreachableAlternativeIsWarned) {
    ir::EcoScene scene = lang::parseEcoText(
        "EcoSystem 1.0 \"w\" { Plant \"p\" { Grow { w = A(0);\nA(0) -> S(1) | S(2); } } }", "w.eco");
    ASSERT_EQ(scene.warnings.size(), 1u);
    EXPECT_EQ(scene.warnings[0].loc.line, 2);
    EXPECT_EQ(scene.warnings[0].loc.col, 16);
    EXPECT_NE(scene.warnings[0].message.find("never taken"), std::string::npos);
}

TEST(EcoParser, ARuleMayHoldOnTheLightAndItsStages) {
    ir::EcoScene scene = lang::parseEcoText("EcoSystem 1.0 \"w\" { Plant \"p\" { Grow { w = A(0);\n"
                                            "A(s) : s < 3 && light() > 0.5 -> A(s + 1)S(0);\n"
                                            "S(0) : light() < 0.2 -> S(1); } } }",
                                            "w.eco");
    const ir::Grammar g = lang::compileEcoPlant(scene, 0);
    // A condition is the rule's own, conjoined with its literal stages'.
    ASSERT_EQ(g.productions.productions.size(), 2u);
    const ir::Production& apex = g.productions.productions[0];
    ASSERT_TRUE(apex.condition.has_value());
    EXPECT_EQ(apex.condition->op, ir::Op::And);
    const ir::Production& stem = g.productions.productions[1];
    ASSERT_TRUE(stem.condition.has_value());
    EXPECT_EQ(stem.condition->op, ir::Op::And); // S(0)'s stage and the light
    bool callsLight = false;
    std::function<void(const ir::Expr&)> walk = [&](const ir::Expr& e) {
        if (e.op == ir::Op::Call && e.fn == ir::Builtin::Light) callsLight = true;
        for (const ir::Expr& a : e.args) walk(a);
    };
    walk(*stem.condition);
    EXPECT_TRUE(callsLight);
    // Without a light grid light() is 1: the apex rule holds for stages below 3, the stem's never.
    EXPECT_TRUE(holds(apex, {2.0f}));
    EXPECT_FALSE(holds(apex, {3.0f}));
    EXPECT_FALSE(holds(stem, {0.0f}));
}

// ---- malformed scripts ----

struct Malformed {
    const char* what;
    std::string text;
    int line;
    int col;
    const char* message;
};

// A script whose Grow block has `rules` from line 5.
std::string withRules(const std::string& rules) {
    return "EcoSystem 1.0 \"t\" {\n"
           "  Plant \"p\" {\n"
           "    Grow {\n"
           "      w = A(0);\n" +
           rules + "\n    }\n  }\n}\n";
}

// A script whose Stem block has `body` from line 4.
std::string withStem(const std::string& body) {
    return "EcoSystem 1.0 \"t\" {\n"
           "  Plant \"p\" {\n"
           "    Stem {\n" +
           body + "\n    }\n    Grow { w = A(0); }\n  }\n}\n";
}

TEST(EcoParser, MalformedScriptsReportLineAndColumn) {
    const std::vector<Malformed> cases = {
        {"unterminated string", "EcoSystem 1.0 \"MySys {\n  SoilPH = 7.0;\n}\n", 1, 15, "unterminated string"},
        {"missing EcoSystem", "Plant \"p\" { }\n", 1, 1, "starts with `EcoSystem"},
        {"unknown keyword", "EcoSystem 1.0 \"t\" {\n  SoilPh2 = 7.0;\n}\n", 2, 3, "unknown keyword 'SoilPh2'"},
        {"missing ';' after a property", "EcoSystem 1.0 \"t\" {\n  SoilPH = 7.0\n  RainRate = 0.9;\n}\n", 2, 15,
         "expected ';'"},
        {"bad number", "EcoSystem 1.0 \"t\" {\n  DayLight = 1.2.3;\n}\n", 2, 14, "bad number '1.2.3'"},
        {"number with a letter", "EcoSystem 1.0 \"t\" {\n  DayLight = 12h;\n}\n", 2, 14, "bad number '12h'"},
        {"number beyond a float", "EcoSystem 1.0 \"t\" {\n  DayLight = 1e39;\n}\n", 2, 14,
         "number '1e39' is beyond the largest a scene holds (3.40282e+38)"},
        {"rule condition without an expression", withRules("      S(0) : -> S(1);"), 5, 14, "expected"},
        {"rule condition without an expression", withRules("      S(0) : -> S(1);"), 5, 14, "expected"},
        {"missing '}' of the ecosystem", "EcoSystem 1.0 \"t\" {\n  SoilPH = 7.0;\n", 3, 1, "missing '}'"},
        {"missing '}' of a stage", withStem("      Stage 1 { GrowRate = 0.1;\n      Stage 2 { }"), 5, 7,
         "missing '}' closing Stem Stage 1"},
        {"unknown stage property", withStem("      Stage 1 { GrowRat = 0.1; }"), 4, 17,
         "unknown stage property 'GrowRat'"},
        {"property set twice", withStem("      Stage 1 { GrowRate = 0.1; GrowRate = 0.2; }"), 4, 33,
         "GrowRate is set twice"},
        {"stage defined twice", withStem("      Stage 1 { }\n      Stage 1 { }"), 5, 13, "Stage 1 is defined twice"},
        {"fractional stage", withStem("      Stage 1.5 { }"), 4, 13, "whole number"},
        {"stage past the largest", withStem("      Stage 2147483647 { }"), 4, 13, "from 0 to 1000000, found number 2147483647"},
        {"rand bounds reversed", withStem("      Stage 1 { ConeNoise = rand(0.5, 0.1); }"), 4, 29,
         "lower bound is above the upper"},
        {"colour with three numbers", withStem("      Stage 1 { Color = RGBA(1.0, 1.0, 1.0); }"), 4, 43,
         "expected ','"},
        {"plant without Grow", "EcoSystem 1.0 \"t\" {\n  Plant \"p\" {\n    Stem { }\n  }\n}\n", 4, 3,
         "ends without a Grow block"},
        {"text after the ecosystem", withRules("") + "Plant \"late\" { }\n", 9, 1, "after the end of the EcoSystem"},
        {"Grow without axiom", "EcoSystem 1.0 \"t\" {\n  Plant \"p\" {\n    Grow {\n      A(0) -> S(0);\n", 4, 7,
         "starts with its axiom"},
        {"unclosed bracket in a rule", withRules("      S(0) -> S(1)[rotr(0.5) S(2);"), 5, 19, "'[' is never closed"},
        {"stray closing bracket", withRules("      S(0) -> S(1) S(2)];"), 5, 24, "']' without a matching '['"},
        {"empty branch", withRules("      S(0) -> S(1)[]S(2);"), 5, 19, "branch needs at least one segment"},
        {"unknown segment letter", withRules("      S(0) -> S(1) X(2);"), 5, 20, "unknown segment type 'X'"},
        {"undefined variable", withRules("      L(i) -> L(j + 1);"), 5, 17, "undefined variable 'j'"},
        {"variable bound twice", withRules("      S(i) < S(i) -> S(0);"), 5, 16, "bound twice"},
        {"two predecessors", withRules("      S(0) S(1) -> S(2);"), 5, 12, "rewrites one segment"},
        {"missing ';' between rules", withRules("      S(0) -> S(1)\n      S(1) -> S(2);"), 6, 12,
         "missing ';' after the previous rule"},
        {"missing ';' before '}'", withRules("      S(0) -> S(1)"), 5, 19, "expected ';' at the end of the rule"},
        {"missing '}' of an organ",
         "EcoSystem 1.0 \"t\" {\n  Plant \"p\" {\n    Stem { Stage 0 { }\n    Grow { w = A(0); }\n  }\n}\n", 4, 5,
         "missing '}' closing the Stem block"},
        {"probability above 1", withRules("      S(0) -> prob(1.5) S(1) | S(2);"), 5, 20, "between 0 and 1"},
        {"prob in the middle", withRules("      S(0) -> S(1) prob(0.5) S(2);"), 5, 20, "only starts a successor"},
        {"step condition in a later successor", withRules("      L(i) -> L(0) | L(i + 1, i < 6);"), 5, 29,
         "belongs to the first successor"},
        {"step successor with company", withRules("      L(i) -> L(i + 1, i < 6) S(0);"), 5, 22, "stands alone"},
        {"empty successor", withRules("      S(0) -> ;"), 5, 15, "expected a segment"},
        {"fractional stage in a successor", withRules("      S(0) -> S(1.5);"), 5, 17, "whole number"},
        {"rand in the axiom", "EcoSystem 1.0 \"t\" { Plant \"p\" { Grow {\n  w = A(0) rotr(rand(0.0, 1.0));\n}}}\n",
         2, 17, "axiom takes plain numbers"},
        {"unknown function", withRules("      S(0) -> rotr(spin(1.0)) S(1);"), 5, 20, "unknown function 'spin'"},
        {"unexpected character", withRules("      S(0) -> S(1) @;"), 5, 20, "unexpected character '@'"},
        {"rotation in a predecessor", withRules("      rotr(1.0) -> S(1);"), 5, 7, "cannot be matched"},
    };
    EXPECT_GE(cases.size(), 15u);
    for (const Malformed& m : cases) {
        SCOPED_TRACE(m.what);
        try {
            ir::EcoScene scene = lang::parseEcoText(m.text, "bad.eco");
            ADD_FAILURE() << "parsed without error";
        } catch (const ir::InputError& e) {
            EXPECT_EQ(e.loc().file, "bad.eco");
            EXPECT_EQ(e.loc().line, m.line) << e.formatted();
            EXPECT_EQ(e.loc().col, m.col) << e.formatted();
            EXPECT_NE(std::string(e.what()).find(m.message), std::string::npos) << e.formatted();
        }
    }
}

TEST(EcoParser, AbsurdNestingIsAnErrorNotACrash) {
    std::string branches;
    for (int i = 0; i < 100000; ++i) branches += "[S(0)";
    try {
        lang::parseEcoText(withRules("      S(0) -> S(1)" + branches + ";"), "deep.eco");
        ADD_FAILURE() << "parsed without error";
    } catch (const ir::InputError& e) {
        EXPECT_EQ(e.loc().line, 5);
        EXPECT_NE(std::string(e.what()).find("nested more than"), std::string::npos);
    }
}

TEST(EcoParser, BinaryAndMissingFilesAreInputErrors) {
    EXPECT_THROW(lang::parseEcoText(std::string("EcoSystem 1.0 \"t\" {\0}", 21), "nul.eco"), ir::InputError);
    EXPECT_THROW(lang::parseEcoFile(kSeedScripts + "no-such-script.eco"), ir::InputError);
}

} // namespace
} // namespace simeco
