// Expression parsing: precedence and associativity as cpfg's grammar defines them.
#include <gtest/gtest.h>

#include "lang/expr_parser.h"

namespace {

class NoNames : public simeco::lang::ExprScope {
public:
    std::optional<simeco::ir::Expr> variable(const std::string& name) const override {
        if (name != "x") return std::nullopt;
        simeco::ir::Expr e;
        e.op = simeco::ir::Op::Local;
        return e;
    }
    std::optional<int> array(const std::string&) const override { return std::nullopt; }
};

simeco::ir::Expr parse(const std::string& text) {
    simeco::lang::PreprocessedText src = simeco::lang::preprocessText(text, "e", {});
    simeco::lang::TextCursor cur{&src, 0};
    NoNames scope;
    return simeco::lang::parseExpression(cur, scope);
}

TEST(Expressions, PowerBindsLooserThanUnaryMinusAndGroupsLeft) {
    simeco::ir::Expr e = parse("-x^2^3");
    ASSERT_EQ(e.op, simeco::ir::Op::Pow);
    EXPECT_EQ(e.args[0].op, simeco::ir::Op::Pow);
    EXPECT_EQ(e.args[0].args[0].op, simeco::ir::Op::Neg);
}

TEST(Expressions, ArithmeticComparisonLogicAndSelect) {
    simeco::ir::Expr e = parse("x + 1 * 2 < 3 && !x || x ? 1 : 2");
    ASSERT_EQ(e.op, simeco::ir::Op::Select);
    EXPECT_EQ(e.args[0].op, simeco::ir::Op::Or);
    EXPECT_EQ(e.args[0].args[0].op, simeco::ir::Op::And);
    EXPECT_EQ(e.args[0].args[0].args[0].op, simeco::ir::Op::Lt);
    EXPECT_EQ(e.args[0].args[0].args[0].args[0].op, simeco::ir::Op::Add);
}

TEST(Expressions, AnArrowIsNotAMinus) {
    simeco::lang::PreprocessedText src = simeco::lang::preprocessText("x --> y", "e", {});
    simeco::lang::TextCursor cur{&src, 0};
    NoNames scope;
    simeco::ir::Expr e = simeco::lang::parseExpression(cur, scope);
    EXPECT_EQ(e.op, simeco::ir::Op::Local);
    EXPECT_EQ(src.text().substr(cur.pos, 3), "-->");
}

TEST(Expressions, NumbersInCNotation) {
    EXPECT_FLOAT_EQ(parse("1.5e2").value, 150.0f);
    EXPECT_FLOAT_EQ(parse(".25").value, 0.25f);
    EXPECT_FLOAT_EQ(parse("3.").value, 3.0f);
}

TEST(Expressions, BuiltinsCheckTheirArgumentCount) {
    EXPECT_EQ(parse("sqrt(x)").fn, simeco::ir::Builtin::Sqrt);
    EXPECT_EQ(parse("atan(x, 1)").fn, simeco::ir::Builtin::Atan2);
    EXPECT_THROW(parse("sqrt(x, x)"), simeco::ir::InputError);
}

} // namespace
