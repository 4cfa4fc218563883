#include "lang/expr_parser.h"

#include <cstdlib>

#include <fmt/format.h>

namespace simeco::lang {

namespace {

using ir::Expr;
using ir::Op;

class ExprParser {
public:
    ExprParser(TextCursor& cur, const ExprScope& scope, ExprOptions options)
        : cur_(cur), scope_(scope), options_(options) {}

    Expr parseTernary() {
        Expr c = parseOr();
        skip();
        if (cur_.peek() == '?') {
            ir::SourceLoc loc = cur_.loc();
            ++cur_.pos;
            Expr a = parseTernary();
            skip();
            if (!cur_.eat(":")) cur_.fail("expected ':' in conditional expression");
            Expr b = parseTernary();
            return node(Op::Select, loc, {std::move(c), std::move(a), std::move(b)});
        }
        return c;
    }

private:
    TextCursor& cur_;
    const ExprScope& scope_;
    ExprOptions options_;
    int parenDepth_ = 0;
    int fscanfDepth_ = 0; // inside fscanf's arguments, where `&name` names a destination

    void skip() {
        if (options_.newlines == NewlinePolicy::Always) cur_.skipBlanks(true);
        else cur_.skipLineBlanks();
    }

    static Expr node(Op op, ir::SourceLoc loc, std::vector<Expr> args) {
        Expr e;
        e.op = op;
        e.loc = std::move(loc);
        e.args = std::move(args);
        return e;
    }

    // Operators spelled with characters that also start arrows must not eat an arrow.
    bool atArrow() const { return cur_.startsWith("-->") || cur_.startsWith("->"); }

    Expr parseOr() {
        Expr v = parseAnd();
        for (;;) {
            skip();
            ir::SourceLoc loc = cur_.loc();
            if (!cur_.eat("||")) return v;
            v = node(Op::Or, loc, {std::move(v), parseAnd()});
        }
    }
    Expr parseAnd() {
        Expr v = parseEquality();
        for (;;) {
            skip();
            ir::SourceLoc loc = cur_.loc();
            if (!cur_.eat("&&")) return v;
            v = node(Op::And, loc, {std::move(v), parseEquality()});
        }
    }
    Expr parseEquality() {
        Expr v = parseRelational();
        for (;;) {
            skip();
            ir::SourceLoc loc = cur_.loc();
            Op op;
            if (cur_.eat("==")) op = Op::Eq;
            else if (cur_.eat("!=")) op = Op::Ne;
            else return v;
            v = node(op, loc, {std::move(v), parseRelational()});
        }
    }
    Expr parseRelational() {
        Expr v = parseAdditive();
        for (;;) {
            skip();
            ir::SourceLoc loc = cur_.loc();
            Op op;
            if (cur_.eat("<=")) op = Op::Le;
            else if (cur_.eat(">=")) op = Op::Ge;
            else if (cur_.peek() == '<' && cur_.peek(1) != '<') op = Op::Lt, ++cur_.pos;
            else if (cur_.peek() == '>' && cur_.peek(1) != '>') op = Op::Gt, ++cur_.pos;
            else return v;
            v = node(op, loc, {std::move(v), parseAdditive()});
        }
    }
    Expr parseAdditive() {
        Expr v = parseMultiplicative();
        for (;;) {
            skip();
            ir::SourceLoc loc = cur_.loc();
            Op op;
            if (cur_.peek() == '+') op = Op::Add;
            else if (cur_.peek() == '-' && !atArrow()) op = Op::Sub;
            else return v;
            ++cur_.pos;
            v = node(op, loc, {std::move(v), parseMultiplicative()});
        }
    }
    Expr parseMultiplicative() {
        Expr v = parsePower();
        for (;;) {
            skip();
            ir::SourceLoc loc = cur_.loc();
            Op op;
            char c = cur_.peek();
            if (c == '*') op = Op::Mul;
            else if (c == '/') op = Op::Div;
            else if (c == '%') op = Op::Mod;
            else return v;
            ++cur_.pos;
            v = node(op, loc, {std::move(v), parsePower()});
        }
    }
    // cpfg's `^` is power, groups to the left and binds looser than unary minus: -2^2 is 4.
    Expr parsePower() {
        Expr v = parseUnary();
        for (;;) {
            skip();
            ir::SourceLoc loc = cur_.loc();
            if (cur_.peek() != '^') return v;
            ++cur_.pos;
            v = node(Op::Pow, loc, {std::move(v), parseUnary()});
        }
    }
    Expr parseUnary() {
        skip();
        ir::SourceLoc loc = cur_.loc();
        char c = cur_.peek();
        if (c == '-' && !atArrow()) {
            ++cur_.pos;
            Expr operand = parseUnary();
            if (operand.isConst()) {
                operand.value = -operand.value;
                operand.loc = loc;
                return operand;
            }
            return node(Op::Neg, loc, {std::move(operand)});
        }
        if (c == '+') {
            ++cur_.pos;
            return parseUnary();
        }
        if (c == '!' && cur_.peek(1) != '=') {
            ++cur_.pos;
            return node(Op::Not, loc, {parseUnary()});
        }
        if (c == '&' && cur_.peek(1) != '&' && fscanfDepth_ > 0) {
            ++cur_.pos; // &name: fscanf's destination, the variable itself
            return parsePrimary();
        }
        return parsePrimary();
    }

    Expr parsePrimary() {
        skip();
        ir::SourceLoc loc = cur_.loc();
        char c = cur_.peek();
        if (c == '(') {
            ++cur_.pos;
            ++parenDepth_;
            Expr inner = parseTernary();
            skip();
            if (!cur_.eat(")")) cur_.fail("expected ')'");
            --parenDepth_;
            return inner;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && std::isdigit(static_cast<unsigned char>(cur_.peek(1))))) {
            std::optional<double> value = parseNumber(cur_);
            if (!value) cur_.fail("bad number");
            return Expr::constant(*value, loc);
        }
        if (c == '"') {
            size_t start = ++cur_.pos;
            while (!cur_.atEnd() && cur_.peek() != '"' && cur_.peek() != '\n') ++cur_.pos;
            if (cur_.peek() != '"') cur_.failAt(start - 1, "unterminated string literal");
            Expr s;
            s.op = Op::String;
            s.loc = loc;
            for (size_t i = start; i < cur_.pos; ++i) {
                char ch = cur_.text()[i];
                if (ch == '\\' && i + 1 < cur_.pos) {
                    char e = cur_.text()[++i];
                    s.text.push_back(e == 'n' ? '\n' : e == 't' ? '\t' : e);
                } else {
                    s.text.push_back(ch);
                }
            }
            ++cur_.pos;
            return s;
        }
        if (isIdentStartChar(c)) {
            size_t start = cur_.pos;
            while (isIdentChar(cur_.peek())) ++cur_.pos;
            std::string name = cur_.text().substr(start, cur_.pos - start);
            size_t afterName = cur_.pos;
            skip();
            if (cur_.peek() == '(') return parseCall(name, loc, start);
            if (cur_.peek() == '[') {
                std::optional<int> slot = scope_.array(name);
                if (slot) return parseArrayElement(*slot, loc);
            }
            cur_.pos = afterName;
            if (std::optional<Expr> var = scope_.variable(name)) {
                var->loc = loc;
                return *var;
            }
            if (scope_.array(name)) cur_.failAt(start, fmt::format("array '{}' used without an index", name));
            cur_.failAt(start, fmt::format("undefined name '{}'", name));
        }
        if (cur_.atEnd() || c == '\n') cur_.fail("expected an expression");
        cur_.fail(fmt::format("unexpected '{}' in expression", c));
    }

    Expr parseCall(const std::string& name, const ir::SourceLoc& loc, size_t nameOffset) {
        const ir::BuiltinInfo* info = ir::findBuiltin(name);
        if (!info) cur_.failAt(nameOffset, fmt::format("unknown function '{}'", name));
        ++cur_.pos; // (
        ++parenDepth_;
        bool isFscanf = info->fn == ir::Builtin::Fscanf;
        fscanfDepth_ += isFscanf;
        std::vector<Expr> args;
        skip();
        if (cur_.peek() != ')') {
            for (;;) {
                args.push_back(parseTernary());
                skip();
                if (cur_.eat(",")) continue;
                break;
            }
        }
        if (!cur_.eat(")")) cur_.fail(fmt::format("expected ')' to close the call of '{}'", name));
        --parenDepth_;
        fscanfDepth_ -= isFscanf;
        ir::Builtin fn = info->fn;
        if (fn == ir::Builtin::Atan && args.size() == 2) fn = ir::Builtin::Atan2; // cpfg's atan(x, y)
        else if (static_cast<int>(args.size()) < info->minArgs || static_cast<int>(args.size()) > info->maxArgs) {
            std::string expected = info->minArgs == info->maxArgs ? std::to_string(info->minArgs)
                                                                  : fmt::format("{} to {}", info->minArgs, info->maxArgs);
            cur_.failAt(nameOffset,
                        fmt::format("'{}' takes {} argument(s), {} given", name, expected, args.size()));
        }
        for (size_t i = 0; i < args.size(); ++i) {
            bool stringAllowed = (fn == ir::Builtin::Printf && i == 0) || (fn == ir::Builtin::Fopen && i < 2) ||
                                 ((fn == ir::Builtin::Fprintf || fn == ir::Builtin::Fscanf) && i == 1);
            if ((args[i].op == Op::String) != stringAllowed)
                throw ir::InputError(args[i].loc, stringAllowed ? fmt::format("'{}' expects a string here", name)
                                                                : "a string is not allowed here");
            if (fn == ir::Builtin::Fscanf && i >= 2 && args[i].op != Op::Local && args[i].op != Op::Global)
                throw ir::InputError(args[i].loc, "fscanf stores into variables: write &name");
        }
        Expr e = node(Op::Call, loc, std::move(args));
        e.fn = fn;
        return e;
    }

    // a[i], a[i][j] and a[i,j] all index a (row-major) array.
    Expr parseArrayElement(int slot, const ir::SourceLoc& loc) {
        Expr e = node(Op::ArrayElem, loc, {});
        e.slot = slot;
        while (cur_.peek() == '[') {
            ++cur_.pos;
            ++parenDepth_;
            for (;;) {
                e.args.push_back(parseTernary());
                skip();
                if (cur_.eat(",")) continue;
                break;
            }
            if (!cur_.eat("]")) cur_.fail("expected ']' after array index");
            --parenDepth_;
            size_t save = cur_.pos;
            skip();
            if (cur_.peek() != '[') cur_.pos = save;
        }
        return e;
    }
};

} // namespace

std::optional<double> parseNumber(TextCursor& cur) {
    const std::string& text = cur.text();
    size_t i = cur.pos;
    while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    if (i < text.size() && text[i] == '.') {
        ++i;
        while (i < text.size() && std::isdigit(static_cast<unsigned char>(text[i]))) ++i;
    }
    if (i == cur.pos || (i == cur.pos + 1 && text[cur.pos] == '.')) return std::nullopt;
    if (i < text.size() && (text[i] == 'e' || text[i] == 'E')) {
        size_t j = i + 1;
        if (j < text.size() && (text[j] == '+' || text[j] == '-')) ++j;
        if (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) {
            while (j < text.size() && std::isdigit(static_cast<unsigned char>(text[j]))) ++j;
            i = j;
        }
    }
    std::string literal = text.substr(cur.pos, i - cur.pos);
    cur.pos = i;
    return std::strtod(literal.c_str(), nullptr);
}

ir::Expr parseExpression(TextCursor& cur, const ExprScope& scope, ExprOptions options) {
    ExprParser parser(cur, scope, options);
    return parser.parseTernary();
}

} // namespace simeco::lang
