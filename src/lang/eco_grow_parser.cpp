// The Grow block (appendix B: Grow, Axiom, ProductionRule, Sentence and below).
//
// The BNF is read generously where its own examples go beyond it: rotations may stand anywhere in a
// sentence (the generator writes them after branches), arguments may be expressions, a rule may bind a
// variable in any segment, and `null` may be one alternative among others. It is kept strict where a
// looser reading would change meaning: segments are one of the letters A S L F T R, each successor and
// branch holds at least one segment, and a step condition belongs to the first successor only.
#include "lang/eco_grow_parser.h"

#include <cctype>
#include <cmath>
#include <optional>

#include <fmt/format.h>

namespace simeco::lang {

namespace {

using ir::Expr;
using ir::Op;

bool isRotation(const EcoToken& t) {
    if (t.kind != EcoTokenKind::Identifier) return false;
    for (const char* name : {"rotr", "rotu", "rotx", "roty", "rotz"})
        if (equalsIgnoreCase(t.text, name)) return true;
    return false;
}

// A single capital letter: the shape of a segment, known or not.
bool looksLikeSegment(const EcoToken& t) {
    return t.kind == EcoTokenKind::Identifier && t.text.size() == 1 &&
           std::isupper(static_cast<unsigned char>(t.text[0]));
}

bool isReservedWord(const std::string& name) {
    for (const char* word : {"prob", "null", "rand", "rotr", "rotu", "rotx", "roty", "rotz"})
        if (equalsIgnoreCase(name, word)) return true;
    return ir::findBuiltin(name) != nullptr;
}

// Builtins a script may call; the rest (printf, stop, func, srand) belong to cpfg's statements and tables.
const ir::BuiltinInfo* scriptBuiltin(const std::string& name) {
    const ir::BuiltinInfo* info = ir::findBuiltin(name);
    if (!info) return nullptr;
    switch (info->fn) {
    case ir::Builtin::Printf:
    case ir::Builtin::Stop:
    case ir::Builtin::Func:
    case ir::Builtin::Srand: return nullptr;
    default: return info;
    }
}

Expr node(Op op, std::vector<Expr> args, ir::SourceLoc loc) {
    Expr e;
    e.op = op;
    e.args = std::move(args);
    e.loc = std::move(loc);
    return e;
}

// Folds constant arithmetic, so that `-1.6` and `rand(0, 6.28)` carry plain numbers.
Expr arithmetic(Op op, Expr a, Expr b, ir::SourceLoc loc) {
    if (a.isConst() && b.isConst()) {
        switch (op) {
        case Op::Add: return Expr::constant(a.value + b.value, loc);
        case Op::Sub: return Expr::constant(a.value - b.value, loc);
        case Op::Mul: return Expr::constant(a.value * b.value, loc);
        default: break;
        }
    }
    return node(op, {std::move(a), std::move(b)}, std::move(loc));
}

Expr call(ir::Builtin fn, std::vector<Expr> args, ir::SourceLoc loc) {
    Expr e = node(Op::Call, std::move(args), std::move(loc));
    e.fn = fn;
    return e;
}

class GrowParser {
public:
    GrowParser(EcoTokenCursor& cur, std::vector<ir::EcoWarning>& warnings) : cur_(cur), warnings_(warnings) {}

    ir::EcoGrow block() {
        ir::EcoGrow grow;
        const EcoToken& open = cur_.expectPunct("{", "after Grow");
        grow.loc = cur_.loc(open);
        axiom(grow);
        while (!cur_.atPunct("}")) {
            if (cur_.atEnd())
                cur_.failAt(cur_.peek(), fmt::format("missing '}}' closing the Grow block opened at line {}",
                                                     grow.loc.line));
            grow.rules.push_back(rule());
        }
        cur_.next();
        return grow;
    }

private:
    void axiom(ir::EcoGrow& grow) {
        const EcoToken& w = cur_.peek();
        if (!(w.kind == EcoTokenKind::Identifier && equalsIgnoreCase(w.text, "w") && cur_.atPunct("=", 1)))
            cur_.failAt(w, fmt::format("a Grow block starts with its axiom, such as `w = A(0);`, found {}",
                                       EcoTokenCursor::describe(w)));
        grow.axiomLoc = cur_.loc(w);
        cur_.next();
        cur_.next();
        slotNames_.clear();
        std::vector<ir::EcoModule> modules;
        sentence(modules, nullptr, nullptr);
        for (const ir::EcoModule& m : modules)
            for (const Expr& arg : m.args)
                if (!arg.isConst())
                    throw ir::InputError(arg.loc, "the axiom takes plain numbers; rand() belongs in rules");
        grow.axiom = std::move(modules);
        cur_.expectPunct(";", "after the axiom");
    }

    ir::EcoRule rule() {
        ir::EcoRule r;
        r.loc = cur_.loc(cur_.peek());
        slotNames_.clear();
        std::vector<ir::EcoPatternSegment> first = patternList("a rule");
        std::vector<ir::EcoPatternSegment> strict;
        if (cur_.atPunct("<")) {
            cur_.next();
            r.left = std::move(first);
            strict = patternList("after '<'");
        } else {
            strict = std::move(first);
        }
        if (strict.size() > 1)
            throw ir::InputError(strict[1].loc, "a rule rewrites one segment; mark contexts with '<' and '>'");
        r.predecessor = strict[0];
        if (cur_.acceptPunct(">")) r.right = patternList("after '>'");
        if (cur_.acceptPunct(":")) r.condition = expression(); // on the segments' stages and the environment
        cur_.expectPunct("->", "after the predecessor");
        r.slotNames = slotNames_;

        bool unconditionalSeen = false;
        do {
            const EcoToken& start = cur_.peek();
            ir::EcoAlternative alt = alternative(r.alternatives.empty());
            if (unconditionalSeen)
                warnings_.push_back({cur_.loc(start), "this alternative is never taken: the one before it has no "
                                                      "prob() and is always chosen"});
            if (!alt.probability) unconditionalSeen = true;
            r.alternatives.push_back(std::move(alt));
        } while (cur_.acceptPunct("|"));
        cur_.expectPunct(";", "at the end of the rule");
        return r;
    }

    // One or more segments, up to `<`, `>`, `:` or `->`.
    std::vector<ir::EcoPatternSegment> patternList(const char* where) {
        std::vector<ir::EcoPatternSegment> list;
        while (!cur_.atPunct("<") && !cur_.atPunct(">") && !cur_.atPunct(":") && !cur_.atPunct("->")) {
            const EcoToken& t = cur_.peek();
            if (t.kind == EcoTokenKind::Punct && (t.text == "[" || t.text == "]"))
                cur_.failAt(t, "brackets cannot appear in a predecessor or its contexts");
            if (isRotation(t)) cur_.failAt(t, fmt::format("'{}' cannot be matched: predecessors and contexts are "
                                                           "segments such as S(3)", t.text));
            if (list.empty() || t.kind == EcoTokenKind::Identifier) {
                list.push_back(patternSegment());
                continue;
            }
            cur_.failAt(t, fmt::format("expected '->' after the predecessor, found {}", EcoTokenCursor::describe(t)));
        }
        if (list.empty())
            cur_.failAt(cur_.peek(), fmt::format("expected a segment such as S(0) {}, found {}", where,
                                                 EcoTokenCursor::describe(cur_.peek())));
        return list;
    }

    char segmentLetter(const EcoToken& t) {
        if (t.kind != EcoTokenKind::Identifier)
            cur_.failAt(t, fmt::format("expected a segment such as S(0), found {}", EcoTokenCursor::describe(t)));
        if (!looksLikeSegment(t) || !ir::ecoOrganForLetter(t.text[0]))
            cur_.failAt(t, fmt::format("unknown segment type '{}' (segments are A, S, L, F, T and R)", t.text));
        return t.text[0];
    }

    ir::EcoPatternSegment patternSegment() {
        const EcoToken& letterToken = cur_.next();
        ir::EcoPatternSegment seg;
        seg.letter = segmentLetter(letterToken);
        seg.loc = cur_.loc(letterToken);
        cur_.expectPunct("(", fmt::format("after segment {}", seg.letter));
        const EcoToken& arg = cur_.next();
        if (arg.kind == EcoTokenKind::Number) {
            seg.stage = stageNumber(arg);
            // A literal's slot has no name in the script; letter, stage and position make one up.
            seg.slot = bindSlot(fmt::format("{}{}_{}", seg.letter, *seg.stage, slotNames_.size()));
        } else if (arg.kind == EcoTokenKind::Identifier && !isReservedWord(arg.text)) {
            for (const std::string& name : slotNames_)
                if (name == arg.text)
                    cur_.failAt(arg, fmt::format("variable '{}' is bound twice in this rule", arg.text));
            seg.slot = bindSlot(arg.text);
        } else {
            cur_.failAt(arg, fmt::format("expected a stage number or a variable in {}( ), found {}", seg.letter,
                                         EcoTokenCursor::describe(arg)));
        }
        cur_.expectPunct(")", "after the stage");
        return seg;
    }

    int bindSlot(const std::string& name) {
        slotNames_.push_back(name);
        return static_cast<int>(slotNames_.size()) - 1;
    }

    int stageNumber(const EcoToken& t) {
        if (t.text.find_first_not_of("0123456789") != std::string::npos || t.number > ir::kMostStage)
            cur_.failAt(t, fmt::format("a stage is a whole number from 0 to {}, found {}", ir::kMostStage, t.text));
        return static_cast<int>(t.number);
    }

    ir::EcoAlternative alternative(bool first) {
        ir::EcoAlternative alt;
        alt.loc = cur_.loc(cur_.peek());
        if (cur_.atKeyword("prob")) {
            cur_.next();
            cur_.expectPunct("(", "after prob");
            Expr p = expression();
            if (!p.isConst()) throw ir::InputError(p.loc, "prob() takes a number");
            if (!(p.value >= 0.0f && p.value <= 1.0f))
                throw ir::InputError(p.loc, fmt::format("a probability is between 0 and 1, found {}", p.value));
            alt.probability = p.value;
            cur_.expectPunct(")", "after the probability");
        }
        if (cur_.atKeyword("null")) {
            cur_.next();
            alt.erase = true;
            if (!cur_.atPunct("|") && !cur_.atPunct(";"))
                cur_.failAt(cur_.peek(), "null stands alone: the segment dies and nothing replaces it");
            return alt;
        }
        const EcoToken* stepToken = nullptr;
        sentence(alt.modules, nullptr, &stepToken);
        if (stepToken) {
            if (!first)
                cur_.failAt(*stepToken, "a step condition belongs to the first successor of a rule");
            if (alt.modules.size() != 1)
                cur_.failAt(*stepToken, "a step successor stands alone, as in `L(i) -> L(i + 1, 1 < i < 6);`");
            alt.stepCondition = stepCondition_;
        }
        return alt;
    }

    // Segments, rotations and branches, up to `|` or `;` (or the `]` of `open`). `stepToken`: where a step
    // condition may be written (a successor's top level); null in the axiom and inside branches.
    void sentence(std::vector<ir::EcoModule>& out, const EcoToken* open, const EcoToken** stepToken) {
        int segments = 0;
        const EcoToken& start = cur_.peek();
        for (;;) {
            const EcoToken& t = cur_.peek();
            if (t.kind == EcoTokenKind::Punct) {
                if (t.text == "[") {
                    const EcoToken& bracket = cur_.next();
                    out.push_back({"[", {}, cur_.loc(bracket)});
                    NestingGuard guard(*this, bracket);
                    sentence(out, &bracket, nullptr);
                    out.push_back({"]", {}, cur_.loc(cur_.next())});
                    continue;
                }
                if (t.text == "]") {
                    if (!open) cur_.failAt(t, "']' without a matching '['");
                    if (segments == 0) cur_.failAt(*open, "a branch needs at least one segment");
                    return;
                }
                if (t.text == "|" || t.text == ";") {
                    if (open) cur_.failAt(*open, "'[' is never closed in this successor");
                    if (segments == 0)
                        cur_.failAt(start, "expected a segment such as S(0) in the successor (write null to "
                                           "let the segment die)");
                    return;
                }
                if (t.text == "->")
                    cur_.failAt(t, "unexpected '->' in a successor (missing ';' after the previous rule?)");
                if (t.text == "}") {
                    if (open) cur_.failAt(*open, "'[' is never closed in this successor");
                    cur_.failAfter(cur_.previous(), "expected ';' at the end of the rule, found '}'");
                }
            }
            if (t.kind == EcoTokenKind::End) {
                if (open) cur_.failAt(*open, "'[' is never closed in this successor");
                cur_.failAfter(cur_.previous(), "expected ';' at the end of the rule, found end of file");
            }
            if (isRotation(t)) {
                out.push_back(rotation());
                continue;
            }
            if (t.kind == EcoTokenKind::Identifier) {
                if (equalsIgnoreCase(t.text, "prob"))
                    cur_.failAt(t, "prob() only starts a successor, after '->' or '|'");
                if (equalsIgnoreCase(t.text, "null")) cur_.failAt(t, "null stands alone as a successor");
                out.push_back(segment(stepToken));
                ++segments;
                continue;
            }
            cur_.failAt(t, fmt::format("expected a segment, rotation or bracket, found {}",
                                       EcoTokenCursor::describe(t)));
        }
    }

    ir::EcoModule rotation() {
        const EcoToken& name = cur_.next();
        ir::EcoModule m;
        m.name = name.text;
        for (char& c : m.name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        m.loc = cur_.loc(name);
        cur_.expectPunct("(", fmt::format("after {}", m.name));
        m.args.push_back(expression());
        cur_.expectPunct(")", fmt::format("after the angle of {} (it takes one angle in radians)", m.name));
        return m;
    }

    ir::EcoModule segment(const EcoToken** stepToken) {
        const EcoToken& letterToken = cur_.next();
        ir::EcoModule m;
        m.name = std::string(1, segmentLetter(letterToken));
        m.loc = cur_.loc(letterToken);
        cur_.expectPunct("(", fmt::format("after segment {}", m.name));
        Expr stage = expression();
        if (stage.isConst() && !(stage.value >= 0.0f && std::floor(stage.value) == stage.value))
            throw ir::InputError(stage.loc, fmt::format("a stage is a whole number from 0, found {}", stage.value));
        m.args.push_back(std::move(stage));
        if (cur_.atPunct(",")) {
            const EcoToken& comma = cur_.next();
            if (!stepToken)
                cur_.failAt(comma, "a step condition belongs to a step successor, as in `L(i) -> L(i + 1, i < 6);`");
            if (*stepToken) cur_.failAt(comma, "a successor has at most one step condition");
            *stepToken = &comma;
            stepCondition_ = expression();
        }
        cur_.expectPunct(")", fmt::format("after the stage of {}", m.name));
        return m;
    }

    // Expressions: || && , chained comparisons (`1 < i < 6` is `1 < i && i < 6`), + -, * / %, unary - !.
    Expr expression() { return orExpr(); }

    Expr orExpr() {
        Expr e = andExpr();
        while (cur_.atPunct("||")) {
            ir::SourceLoc loc = cur_.loc(cur_.next());
            e = node(Op::Or, {std::move(e), andExpr()}, loc);
        }
        return e;
    }

    Expr andExpr() {
        Expr e = comparison();
        while (cur_.atPunct("&&")) {
            ir::SourceLoc loc = cur_.loc(cur_.next());
            e = node(Op::And, {std::move(e), comparison()}, loc);
        }
        return e;
    }

    std::optional<Op> comparisonOp() const {
        const EcoToken& t = cur_.peek();
        if (t.kind != EcoTokenKind::Punct) return std::nullopt;
        if (t.text == "<") return Op::Lt;
        if (t.text == "<=") return Op::Le;
        if (t.text == ">") return Op::Gt;
        if (t.text == ">=") return Op::Ge;
        if (t.text == "==") return Op::Eq;
        if (t.text == "!=") return Op::Ne;
        return std::nullopt;
    }

    Expr comparison() {
        Expr left = additive();
        std::optional<Expr> chain;
        while (std::optional<Op> op = comparisonOp()) {
            ir::SourceLoc loc = cur_.loc(cur_.next());
            Expr right = additive();
            Expr test = node(*op, {left, right}, loc);
            chain = chain ? node(Op::And, {std::move(*chain), std::move(test)}, loc) : std::move(test);
            left = std::move(right);
        }
        return chain ? std::move(*chain) : std::move(left);
    }

    Expr additive() {
        Expr e = multiplicative();
        while (cur_.atPunct("+") || cur_.atPunct("-")) {
            const EcoToken& op = cur_.next();
            e = arithmetic(op.text == "+" ? Op::Add : Op::Sub, std::move(e), multiplicative(), cur_.loc(op));
        }
        return e;
    }

    Expr multiplicative() {
        Expr e = unary();
        while (cur_.atPunct("*") || cur_.atPunct("/") || cur_.atPunct("%")) {
            const EcoToken& op = cur_.next();
            Op kind = op.text == "*" ? Op::Mul : op.text == "/" ? Op::Div : Op::Mod;
            e = arithmetic(kind, std::move(e), unary(), cur_.loc(op));
        }
        return e;
    }

    Expr unary() {
        NestingGuard guard(*this, cur_.peek());
        if (cur_.atPunct("-")) {
            ir::SourceLoc loc = cur_.loc(cur_.next());
            Expr operand = unary();
            if (operand.isConst()) return Expr::constant(-operand.value, loc);
            return node(Op::Neg, {std::move(operand)}, loc);
        }
        if (cur_.atPunct("+")) {
            cur_.next();
            return unary();
        }
        if (cur_.atPunct("!")) {
            ir::SourceLoc loc = cur_.loc(cur_.next());
            return node(Op::Not, {unary()}, loc);
        }
        return primary();
    }

    Expr primary() {
        const EcoToken& t = cur_.next();
        ir::SourceLoc loc = cur_.loc(t);
        if (t.kind == EcoTokenKind::Number) return Expr::constant(static_cast<float>(t.number), loc);
        if (t.kind == EcoTokenKind::Punct && t.text == "(") {
            Expr e = expression();
            cur_.expectPunct(")", "closing the parenthesis");
            return e;
        }
        if (t.kind != EcoTokenKind::Identifier)
            cur_.failAt(t, fmt::format("expected a number or a variable, found {}", EcoTokenCursor::describe(t)));
        for (size_t slot = 0; slot < slotNames_.size(); ++slot) {
            if (slotNames_[slot] == t.text) {
                Expr e = node(Op::Local, {}, loc);
                e.slot = static_cast<int>(slot);
                return e;
            }
        }
        if (!cur_.atPunct("(")) {
            if (slotNames_.empty())
                cur_.failAt(t, fmt::format("undefined variable '{}' (this rule binds no variables)", t.text));
            cur_.failAt(t, fmt::format("undefined variable '{}'", t.text));
        }
        if (equalsIgnoreCase(t.text, "rand")) return randomRange(loc);
        const ir::BuiltinInfo* info = scriptBuiltin(t.text);
        if (!info) cur_.failAt(t, fmt::format("unknown function '{}'", t.text));
        cur_.next();
        std::vector<Expr> args;
        if (!cur_.atPunct(")")) {
            do args.push_back(expression());
            while (cur_.acceptPunct(","));
        }
        cur_.expectPunct(")", fmt::format("after the arguments of {}", info->name));
        if (static_cast<int>(args.size()) < info->minArgs || static_cast<int>(args.size()) > info->maxArgs)
            cur_.failAt(t, fmt::format("{}() takes {} argument(s), found {}", info->name, info->minArgs, args.size()));
        return call(info->fn, std::move(args), loc);
    }

    // rand(a, b): uniform on [a, b), drawn each time the rule applies, lowered to a + ran(b - a).
    Expr randomRange(const ir::SourceLoc& loc) {
        cur_.expectPunct("(", "after rand");
        Expr lo = expression();
        cur_.expectPunct(",", "between the bounds of rand(a, b)");
        Expr hi = expression();
        cur_.expectPunct(")", "after rand(a, b)");
        if (lo.isConst() && hi.isConst() && lo.value > hi.value)
            throw ir::InputError(loc, fmt::format("rand({}, {}): the lower bound is above the upper", lo.value,
                                                  hi.value));
        Expr width = arithmetic(Op::Sub, hi, lo, loc);
        return arithmetic(Op::Add, std::move(lo), call(ir::Builtin::Ran, {std::move(width)}, loc), loc);
    }

    // Branches and parentheses are parsed recursively; a bound on their depth keeps absurd input from
    // exhausting the stack.
    static constexpr int kMaxNesting = 500;
    struct NestingGuard {
        NestingGuard(GrowParser& parser, const EcoToken& at) : depth(parser.nesting_) {
            if (++depth > kMaxNesting)
                parser.cur_.failAt(at, fmt::format("nested more than {} levels deep", kMaxNesting));
        }
        ~NestingGuard() { --depth; }
        int& depth;
    };

    EcoTokenCursor& cur_;
    std::vector<ir::EcoWarning>& warnings_;
    int nesting_ = 0;
    std::vector<std::string> slotNames_;
    Expr stepCondition_;
};

} // namespace

ir::EcoGrow parseEcoGrowBlock(EcoTokenCursor& cur, std::vector<ir::EcoWarning>& warnings) {
    return GrowParser(cur, warnings).block();
}

} // namespace simeco::lang
