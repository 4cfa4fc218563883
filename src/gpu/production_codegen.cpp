#include "gpu/production_codegen.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "compute/shaders.h"
#include "compute/shared/derive_layout.h"

namespace simeco::gpu::codegen {

namespace {

constexpr unsigned kLoopLimit = 10'000'000u; // as the CPU reference's evaluator


// Emits straight-line GLSL for expressions and statements of one production.
class BodyEmitter {
public:
    BodyEmitter(const ir::Grammar& g, size_t species, std::vector<ErrorSite>& errors, std::string& out)
        : g_(g), species_(species), errors_(errors), out_(out) {}

    void line(const std::string& text) {
        out_.append(static_cast<size_t>(indent_) * 4, ' ');
        out_ += text;
        out_ += '\n';
    }
    void open(const std::string& text) {
        line(text);
        ++indent_;
    }
    void close(const std::string& text = "}") {
        --indent_;
        line(text);
    }
    void setIndent(int indent) { indent_ = indent; }

    uint32_t site(const ir::SourceLoc& loc, const std::string& message) {
        errors_.push_back({loc, message});
        return static_cast<uint32_t>(errors_.size() - 1);
    }

    std::string temp() { return fmt::format("t{}", temps_++); }

    // The name of a double holding e's value, after the statements that compute it.
    std::string expr(const ir::Expr& e) {
        using ir::Op;
        switch (e.op) {
        case Op::Const: return literal(e.value);
        case Op::Local: return fmt::format("v{}", e.slot);
        case Op::Global: return fmt::format("globals[globalBase + {}u]", e.slot);
        case Op::ArrayElem: return arrayElement(e);
        case Op::Neg: return define(fmt::format("-{}", expr(e.args[0])));
        case Op::Not: return define(fmt::format("({} == 0.0LF ? 1.0LF : 0.0LF)", expr(e.args[0])));
        case Op::Add:
        case Op::Sub:
        case Op::Mul: {
            std::string a = expr(e.args[0]);
            std::string b = expr(e.args[1]);
            const char* op = e.op == Op::Add ? "+" : e.op == Op::Sub ? "-" : "*";
            return define(fmt::format("{} {} {}", a, op, b));
        }
        case Op::Div: {
            std::string a = expr(e.args[0]);
            std::string b = expr(e.args[1]);
            line(fmt::format("if ({} == 0.0LF) reportError({}u);", b, site(e.loc, "division by zero")));
            return define(fmt::format("{} == 0.0LF ? 0.0LF : {} / {}", b, a, b));
        }
        case Op::Mod: {
            std::string a = expr(e.args[0]);
            std::string b = expr(e.args[1]);
            std::string ia = temp(), ib = temp();
            line(fmt::format("int {} = int({}), {} = int({});", ia, a, ib, b));
            line(fmt::format("if ({} == 0) {{ reportError({}u); {} = 1; }}", ib, site(e.loc, "remainder by zero"), ib));
            // OpSDiv truncates toward zero, so this is C's remainder for negative operands too.
            return define(fmt::format("double({} - ({} / {}) * {})", ia, ia, ib, ib));
        }
        case Op::Pow: {
            std::string a = expr(e.args[0]);
            std::string b = expr(e.args[1]);
            return define(fmt::format("powD({}, {})", a, b));
        }
        case Op::Lt:
        case Op::Le:
        case Op::Gt:
        case Op::Ge:
        case Op::Eq:
        case Op::Ne: {
            static const char* ops[] = {"<", "<=", ">", ">=", "==", "!="};
            std::string a = expr(e.args[0]);
            std::string b = expr(e.args[1]);
            return define(fmt::format("({} {} {}) ? 1.0LF : 0.0LF", a,
                                      ops[static_cast<int>(e.op) - static_cast<int>(Op::Lt)], b));
        }
        case Op::And:
        case Op::Or: {
            std::string result = temp();
            std::string a = expr(e.args[0]);
            line(fmt::format("double {} = 0.0LF;", result));
            open(fmt::format("if ({} {} 0.0LF) {{", a, e.op == Op::And ? "!=" : "=="));
            std::string b = expr(e.args[1]);
            line(fmt::format("{} = {} != 0.0LF ? 1.0LF : 0.0LF;", result, b));
            close(e.op == Op::And ? "}" : fmt::format("}} else {{ {} = 1.0LF; }}", result));
            return result;
        }
        case Op::Select: {
            std::string result = temp();
            std::string c = expr(e.args[0]);
            line(fmt::format("double {};", result));
            open(fmt::format("if ({} != 0.0LF) {{", c));
            line(fmt::format("{} = {};", result, expr(e.args[1])));
            close();
            open("else {");
            line(fmt::format("{} = {};", result, expr(e.args[2])));
            close();
            return result;
        }
        case Op::Call: return call(e);
        case Op::String: return "0.0LF";
        }
        return "0.0LF";
    }

    void statements(const std::vector<ir::Stmt>& stmts) {
        for (const ir::Stmt& s : stmts) statement(s);
    }

private:
    const ir::Grammar& g_;
    size_t species_;
    std::vector<ErrorSite>& errors_;
    std::string& out_;
    int indent_ = 1;
    int temps_ = 0;

    std::string define(const std::string& value) {
        std::string name = temp();
        line(fmt::format("double {} = {};", name, value));
        return name;
    }

    std::string draw() {
        std::string name = temp();
        line(fmt::format("double {} = double(randomUnit(pc.seed, plant, currentPass(), key, draw)); ++draw;", name));
        return name;
    }

    std::string arrayElement(const ir::Expr& e) {
        std::optional<std::string> index = arrayIndex(e.slot, e.args, e.loc);
        return index ? define("arrays[" + *index + "]") : "0.0LF";
    }

    // The index in `arrays` of an element, after the statements that check it; none for a wrong dimension.
    std::optional<std::string> arrayIndex(int slot, const std::vector<ir::Expr>& indices, const ir::SourceLoc& loc) {
        const ir::GlobalArray& a = g_.arrays[static_cast<size_t>(slot)];
        uint32_t offset = 0;
        for (int k = 0; k < slot; ++k) offset += static_cast<uint32_t>(g_.arrays[static_cast<size_t>(k)].init.size());
        if (indices.size() != a.dims.size()) {
            line(fmt::format("reportError({}u);", site(loc, fmt::format("array '{}' has {} dimension(s), {} index(es) given",
                                                                       a.name, a.dims.size(), indices.size()))));
            return std::nullopt;
        }
        std::string flat = temp();
        line(fmt::format("uint {} = 0u;", flat));
        for (size_t k = 0; k < indices.size(); ++k) {
            std::string v = expr(indices[k]);
            std::string index = temp();
            line(fmt::format("int {} = int(floor({}));", index, v));
            uint32_t where = site(loc, fmt::format("index out of range for array '{}' (dimension {} has {} elements)",
                                                   a.name, k + 1, a.dims[k]));
            line(fmt::format("if (!({} >= 0.0LF) || {} >= {}) {{ reportError({}u); {} = 0; }}", v, index, a.dims[k], where,
                             index));
            line(fmt::format("{} = {} * {}u + uint({});", flat, flat, a.dims[k], index));
        }
        return fmt::format("arrayBase + {}u + {}", offset, flat);
    }

    std::string call(const ir::Expr& e) {
        using ir::Builtin;
        std::vector<std::string> a;
        if (e.fn != Builtin::Ran) // ran draws after its argument is known, as the CPU does
            for (const ir::Expr& arg : e.args) a.push_back(expr(arg));
        switch (e.fn) {
        case Builtin::Sin: return define(fmt::format("sinD({} / kDegrees)", a[0]));
        case Builtin::Cos: return define(fmt::format("cosD({} / kDegrees)", a[0]));
        case Builtin::Tan: return define(fmt::format("sinD({0} / kDegrees) / cosD({0} / kDegrees)", a[0]));
        case Builtin::Asin: return define(fmt::format("asinD({}) * kDegrees", a[0]));
        case Builtin::Acos: return define(fmt::format("acosD({}) * kDegrees", a[0]));
        case Builtin::Atan: return define(fmt::format("atanD({}) * kDegrees", a[0]));
        case Builtin::Atan2: return define(fmt::format("atan2D({}, {}) * kDegrees", a[1], a[0]));
        case Builtin::Exp: return define(fmt::format("expD({})", a[0]));
        case Builtin::Log: return define(fmt::format("logD({})", a[0]));
        case Builtin::Sqrt: return define(fmt::format("sqrt({})", a[0]));
        case Builtin::Fabs: return define(fmt::format("abs({})", a[0]));
        case Builtin::Floor: return define(fmt::format("floor({})", a[0]));
        case Builtin::Ceil: return define(fmt::format("ceil({})", a[0]));
        case Builtin::Trunc: return define(fmt::format("floor({} + 0.5LF)", a[0]));
        case Builtin::Sign: return define(fmt::format("{0} > 0.0LF ? 1.0LF : ({0} < 0.0LF ? -1.0LF : 0.0LF)", a[0]));
        case Builtin::Pow: return define(fmt::format("powD({}, {})", a[0], a[1]));
        case Builtin::Min: return define(fmt::format("min({}, {})", a[0], a[1]));
        case Builtin::Max: return define(fmt::format("max({}, {})", a[0], a[1]));
        case Builtin::Ran: {
            std::string scale = expr(e.args[0]);
            std::string u = draw();
            return define(fmt::format("{} * {}", u, scale));
        }
        case Builtin::Nran: {
            std::string u1 = draw();
            std::string u2 = draw();
            return define(fmt::format("{} + {} * sqrt(-2.0LF * logD(1.0LF - {})) * cosD(2.0LF * kPi * {})", a[0], a[1],
                                      u1, u2));
        }
        case Builtin::Biran: {
            uint32_t where = site(e.loc, "biran(n, p) needs 0 <= n <= 1000000");
            line(fmt::format("if ({0} < 0.0LF || {0} > 1000000.0LF) reportError({1}u);", a[0], where));
            std::string count = temp();
            line(fmt::format("double {} = 0.0LF;", count));
            open(fmt::format("for (int k = 0; k < int(clamp({}, 0.0LF, 1000000.0LF)); ++k) {{", a[0]));
            line(fmt::format("if (double(randomUnit(pc.seed, plant, currentPass(), key, draw)) <= {}) {} += 1.0LF;", a[1], count));
            line("++draw;");
            close();
            return count;
        }
        case Builtin::Srand: return "0.0LF";
        case Builtin::Stop: // only in the sequential kernel (the parallel passes refuse it)
            line(a.empty() ? "requestStop(plant);" : fmt::format("if ({} != 0.0LF) requestStop(plant);", a[0]));
            return "0.0LF";
        case Builtin::Printf: return "0.0LF"; // arguments evaluated above (for their draws); nothing is printed
        case Builtin::Func: {
            uint32_t where = site(e.loc, fmt::format("func(id, x): no such function (the view file defines {})",
                                                     g_.functions.size()));
            return define(fmt::format("funcValue{}({}, {}, {}u)", species_, a[0], a[1], where));
        }
        case Builtin::CurveX:
        case Builtin::CurveY:
        case Builtin::CurveZ:
        case Builtin::CurveGal: {
            uint32_t where = site(e.loc, fmt::format("{}(id, ...): no such curve (the view file defines {})",
                                                     ir::builtinName(e.fn), g_.curves.size()));
            int axis = static_cast<int>(e.fn) - static_cast<int>(Builtin::CurveX); // 3 for curveGAL
            return define(fmt::format("curveValue{}({}, {}, {}, {}u)", species_, a[0], axis,
                                      e.fn == Builtin::CurveGal ? "0.0LF" : a[1], where));
        }
        default: return "0.0LF"; // excluded by gpuUnsupportedReason
        }
    }

    void statement(const ir::Stmt& s) {
        switch (s.kind) {
        case ir::StmtKind::Assign: {
            // Globals and arrays are written only by the sequential kernel (the parallel passes refuse it).
            std::string v = expr(s.expr);
            if (s.target == ir::TargetKind::Local) {
                line(fmt::format("v{} = {};", s.slot, v));
            } else if (s.target == ir::TargetKind::Global) {
                line(fmt::format("globals[globalBase + {}u] = {};", s.slot, v));
            } else if (std::optional<std::string> index = arrayIndex(s.slot, s.indices, s.loc)) {
                line(fmt::format("arrays[{}] = {};", *index, v));
            }
            break;
        }
        case ir::StmtKind::Eval: expr(s.expr); break;
        case ir::StmtKind::If: {
            std::string c = expr(s.expr);
            open(fmt::format("if ({} != 0.0LF) {{", c));
            statements(s.body);
            close();
            if (!s.elseBody.empty()) {
                open("else {");
                statements(s.elseBody);
                close();
            }
            break;
        }
        case ir::StmtKind::While:
        case ir::StmtKind::DoWhile: {
            // A driver that ends the loop early (lavapipe) is caught at the end of the kernel (reportLoopsCut).
            uint32_t where = site(s.loc, fmt::format("loop still running after {} iterations", kLoopLimit));
            std::string guard = temp();
            line(fmt::format("uint {} = 0u;", guard));
            open("for (;;) {");
            if (s.kind == ir::StmtKind::DoWhile) statements(s.body);
            std::string c = expr(s.expr);
            line(fmt::format("if ({} == 0.0LF) break;", c));
            line(fmt::format("if (++{} > {}u) {{ reportError({}u); break; }}", guard, kLoopLimit, where));
            if (s.kind == ir::StmtKind::While) statements(s.body);
            close();
            break;
        }
        }
    }
};


} // namespace

// A double literal with every digit of the value.
std::string literal(double v) {
    if (std::isnan(v)) return "(0.0LF / 0.0LF)";
    if (std::isinf(v)) return v > 0 ? "(1.0LF / 0.0LF)" : "(-1.0LF / 0.0LF)";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", v);
    std::string s = buffer;
    if (s.find_first_of(".eE") == std::string::npos) s += ".0";
    return "(" + s + "LF)";
}


void Bindings::add(const char* access, const char* type, const char* name) {
    text_ += fmt::format("layout(set = 0, binding = {}, std430) {} buffer B{} {{ {} {}[]; }};\n", next_++, access, name,
                         type, name);
}

void Bindings::addInput(const char* type, const char* name) {
    if (!texelInputs_) {
        add("readonly", type, name);
        text_ += fmt::format("{0} {1}At(uint i) {{ return {1}[i]; }}\n", type, name);
        return;
    }
    std::string_view t = type;
    const char* sampler = t == "uint" ? "usamplerBuffer" : t == "int" ? "isamplerBuffer" : "samplerBuffer";
    text_ += fmt::format("layout(set = 0, binding = {}) uniform {} {};\n", next_++, sampler, name);
    text_ += fmt::format("{0} {1}At(uint i) {{ return texelFetch({1}, int(i)).x; }}\n", type, name);
}

void Bindings::addVectorInput(uint32_t width, const char* name) {
    std::string type = fmt::format("vec{}", width);
    if (!texelInputs_) {
        add("readonly", type.c_str(), name);
        text_ += fmt::format("{0} {1}At(uint i) {{ return {1}[i]; }}\n", type, name);
        return;
    }
    text_ += fmt::format("layout(set = 0, binding = {}) uniform samplerBuffer {};\n", next_++, name);
    text_ += fmt::format("{0} {1}At(uint i) {{ return texelFetch({1}, int(i)).{2}; }}\n", type, name,
                         width == 2 ? "xy" : "xyzw");
}

void Bindings::addShared(bool stateWritable) {
    const char* state = stateWritable ? "" : "readonly";
    addInput("uint", "symIn");
    addInput("float", "parIn");
    addInput("uint", "plantStart");
    add("readonly", "int", "depthTree");
    add("readonly", "uint", "levelInfo");
    addInput("uint", "bracketPartners");
    add(state, "double", "globals");
    add(state, "double", "arrays");
    add("readonly", "double", "funcTables"); // func() samples and contour curves (derive/contour_curve.glsl)
    add("readonly", "uint", "contextSkip");
    add("", "uint", "errors");
    add(state, "uint", "plantFrozen"); // the sequential kernel marks 2 when a production calls stop()
}

std::string functionName(size_t species, RuleKind kind, size_t index) {
    return fmt::format("s{}{}{}", species, kind == RuleKind::Step ? "step" : "decompose", index);
}

uint32_t skipWords(const ir::Grammar& g) { return static_cast<uint32_t>((g.alphabet.size() + 31) / 32 + 1); }

namespace {

// Whether the first walk of a pattern is one prefetchContexts() makes: a right pattern's from the module after a
// one-module predecessor, unless it starts with `=`; a left pattern's always. Ring L-systems walk without it:
// whether a walk may wrap depends on the pattern's earlier walks.
bool firstRightWalkPrefetched(const ir::Grammar& g, const ir::Production& p) {
    std::optional<ir::SymbolId> equals = g.alphabet.find("=");
    return !g.ring && p.strict.size() == 1 && !p.right.empty() && !(equals && p.right.front().sym == *equals);
}

bool firstLeftWalkPrefetched(const ir::Grammar& g, const ir::Production& p) { return !g.ring && !p.left.empty(); }

// A pattern module as the stream holds it: symbol | parameter count << kSymbolBits.
uint32_t moduleWord(const ir::PatternModule& m) {
    return m.sym | static_cast<uint32_t>(m.paramSlots.size()) << shared::kSymbolBits;
}

// Calls onExpr for every expression node and onStatement for every statement of a production's code: its
// statements, condition (unless `withCondition` is false) and successor parameters, nested blocks and
// subexpressions included.
template <typename OnExpr, typename OnStatement>
void walkProductionCode(const ir::Production& p, OnExpr&& onExpr, OnStatement&& onStatement, bool withCondition = true) {
    auto expr = [&](const ir::Expr& e, auto& self) -> void {
        onExpr(e);
        for (const ir::Expr& a : e.args) self(a, self);
    };
    auto statements = [&](const std::vector<ir::Stmt>& block, auto& self) -> void {
        for (const ir::Stmt& st : block) {
            onStatement(st);
            expr(st.expr, expr);
            for (const ir::Expr& index : st.indices) expr(index, expr);
            self(st.body, self);
            self(st.elseBody, self);
        }
    };
    statements(p.before, statements);
    statements(p.after, statements);
    if (withCondition && p.condition) expr(*p.condition, expr);
    for (const ir::Alternative& alt : p.alternatives)
        for (const ir::SuccessorModule& m : alt.modules)
            for (const ir::Expr& arg : m.args) expr(arg, expr);
}

// Whether a condition has no effect but its value: no draws, files or stop(). A writing pass, which applies the
// production its match pass chose, need not evaluate such a condition again.
bool conditionIsPure(const ir::Production& p) {
    if (!p.condition) return true;
    bool pure = true;
    auto expr = [&](const ir::Expr& e, auto& self) -> void {
        if (e.op == ir::Op::Call) {
            switch (e.fn) {
            case ir::Builtin::Ran: case ir::Builtin::Nran: case ir::Builtin::Bran: case ir::Builtin::Biran:
            case ir::Builtin::Fopen: case ir::Builtin::Fclose: case ir::Builtin::Fflush: case ir::Builtin::Fprintf:
            case ir::Builtin::Fscanf: case ir::Builtin::Printf: case ir::Builtin::Stop:
                pure = false;
                break;
            default: break;
            }
        }
        for (const ir::Expr& a : e.args) self(a, self);
    };
    expr(*p.condition, expr);
    return pure;
}

// Whether a writing pass walks `pattern`, a context of p: only for the parameters it binds, and only when the
// statements or the successor read them, or the condition, evaluated again for its effects, may.
bool writingWalks(const ir::Production& p, const std::vector<ir::PatternModule>& pattern) {
    std::set<int> bound;
    for (const ir::PatternModule& m : pattern) bound.insert(m.paramSlots.begin(), m.paramSlots.end());
    if (bound.empty()) return false;
    if (!conditionIsPure(p)) return true;
    bool read = false;
    walkProductionCode(
        p, [&](const ir::Expr& e) { read = read || (e.op == ir::Op::Local && bound.count(e.slot)); },
        [&](const ir::Stmt& st) { read = read || (st.target == ir::TargetKind::Local && bound.count(st.slot)); }, false);
    return read;
}

// For each module of a successor, the index of the bracket it pairs within the successor, or none: the
// successor gives these brackets their partners itself.
std::vector<std::optional<size_t>> pairedBrackets(const ir::Alternative& alt) {
    std::vector<std::optional<size_t>> partner(alt.modules.size());
    std::vector<size_t> open;
    for (size_t j = 0; j < alt.modules.size(); ++j) {
        if (alt.modules[j].sym == ir::kBranchOpen) open.push_back(j);
        if (alt.modules[j].sym == ir::kBranchClose && !open.empty()) {
            partner[j] = open.back();
            partner[open.back()] = j;
            open.pop_back();
        }
    }
    return partner;
}

// The parts of a production's code, in order: matching, then producing.
// `modal`: the function has a `mode` (FrameStyle::Fresh), and mode 2 writes what an earlier pass matched.
void emitMatch(BodyEmitter& body, const ir::Grammar& g, size_t species, const ir::Production& p, RuleKind kind,
               bool modal) {
    std::optional<ir::SymbolId> equals = g.alphabet.find("=");
    uint32_t skipRow = static_cast<uint32_t>(species) * skipWords(g);
    for (size_t k = 1; k < p.strict.size(); ++k) {
        // The further modules of a predecessor of several modules: adjacent, nothing skipped.
        const ir::PatternModule& m = p.strict[k];
        body.line(fmt::format("if (i + {0}u >= pEnd || symOf(i + {0}u) != {1}u || countOf(i + {0}u) != {2}u) return false;",
                              k, m.sym, m.paramSlots.size()));
        for (size_t a = 0; a < m.paramSlots.size(); ++a)
            body.line(fmt::format("v{} = paramOf(i + {}u, {}u);", m.paramSlots[a], k, a));
    }
    // Writing passes apply the production the match pass chose, so they walk contexts only for their parameters.
    auto walkOpening = [&](const std::vector<ir::PatternModule>& pattern) {
        return writingWalks(p, pattern) || !modal ? "{" : "if (mode < 2u) {";
    };
    // The parallel passes' kernels walk the first module of each pattern once before the productions
    // (contextPrefetchCode); the sequential kernel walks in each production.
    bool prefetched = modal;
    if (!p.right.empty()) {
        body.open(walkOpening(p.right));
        body.line(fmt::format("uint s = ctxRight + {}u;", p.strict.size() - 1));
        if (g.ring) body.line("bool wrapped = false;");
        bool first = true;
        for (const ir::PatternModule& m : p.right) {
            if (equals && m.sym == *equals) {
                body.line("s = endOfBranch(s, pBegin, pEnd);");
                first = false;
                continue;
            }
            bool enters = m.sym == ir::kBranchOpen;
            if (first && prefetched && firstRightWalkPrefetched(g, p)) {
                const char* found = enters ? "firstRightBranch" : "firstRight";
                body.line(fmt::format("if (!{0}Found || {0}Word != {1}u) return false;", found, moduleWord(m)));
                body.line(fmt::format("s = {};", found));
            } else {
                if (g.ring)
                    body.line(fmt::format("if (!rightWalk(s, {}, pBegin, pEnd, {}u, true, wrapped)) return false;",
                                          enters ? "true" : "false", skipRow));
                else
                    body.line(fmt::format("if (!rightAdvance(s, {}u, pEnd, {}u)) return false;", m.sym, skipRow));
                body.line(fmt::format("if (symInAt(s) != {}u) return false;", moduleWord(m)));
            }
            first = false;
            for (size_t k = 0; k < m.paramSlots.size(); ++k)
                body.line(fmt::format("v{} = paramOf(s, {}u);", m.paramSlots[k], k));
            body.line("++s;");
        }
        body.close();
    }
    if (!p.left.empty()) {
        body.open(walkOpening(p.left));
        body.line("int s = ctxLeft;");
        if (g.ring) body.line("bool wrapped = false;");
        for (auto it = p.left.rbegin(); it != p.left.rend(); ++it) {
            if (it == p.left.rbegin() && prefetched && firstLeftWalkPrefetched(g, p)) {
                body.line(fmt::format("if (!firstLeftFound || firstLeftWord != {}u) return false;", moduleWord(*it)));
                body.line("s = firstLeft;");
            } else {
                if (g.ring)
                    body.line(fmt::format("if (!leftWalk(s, pBegin, pEnd, {}u, true, wrapped)) return false;", skipRow));
                else
                    body.line(fmt::format("if (!leftAdvance(s, pBegin, {}u)) return false;", skipRow));
                body.line(fmt::format("if (symInAt(uint(s)) != {}u) return false;", moduleWord(*it)));
            }
            for (size_t k = 0; k < it->paramSlots.size(); ++k)
                body.line(fmt::format("v{} = paramOf(uint(s), {}u);", it->paramSlots[k], k));
            body.line("--s;");
        }
        body.close();
    }
    // A step's predecessor is in the string being rewritten, whose parallel kernels may have loaded its
    // parameters already (ownParam); a decomposition's is where the kernel keeps it.
    const char* strictParam = kind == RuleKind::Step ? (modal ? "ownParam" : "paramOf") : "strictParam";
    for (size_t k = 0; k < p.strict[0].paramSlots.size(); ++k)
        body.line(fmt::format("v{} = {}(i, {}u);", p.strict[0].paramSlots[k], strictParam, k));
    body.statements(p.before);
    if (p.condition) {
        // A writing pass skips a condition the match pass found true, unless evaluating it has effects.
        bool again = !modal || !conditionIsPure(p);
        body.open(again ? "{" : "if (mode < 2u) {");
        std::string c = body.expr(*p.condition);
        body.line(fmt::format("if ({} == 0.0LF) return false;", c));
        body.close();
    }
}

// The after-statements and the draw of an alternative; sets outCount.
void emitChoice(BodyEmitter& body, const ir::Production& p) {
    body.statements(p.after);
    size_t alternatives = p.alternatives.size();
    body.line(fmt::format("uint alt = {}u;", alternatives - 1));
    for (size_t k = 0; k + 1 < alternatives; ++k) {
        body.open("if (alt == " + std::to_string(alternatives - 1) + "u) {");
        body.line("double u = double(randomUnit(pc.seed, plant, currentPass(), key, draw)); ++draw;");
        body.line(fmt::format("if (u < {}) alt = {}u;", literal(static_cast<double>(p.alternatives[k].probability)), k));
        body.close();
    }
    for (size_t k = 0; k < alternatives; ++k)
        body.line(fmt::format("if (alt == {}u) outCount = {}u;", k, p.alternatives[k].modules.size()));
}

// The chosen alternative's modules, and the partners of the brackets it matches itself: written through
// emitModule/emitParam/emitPartners at outPos + j, or (`slots`) into the successor slots (successorSlots()).
void emitSuccessor(BodyEmitter& body, const ir::Production& p, bool slots) {
    for (size_t k = 0; k < p.alternatives.size(); ++k) {
        const ir::Alternative& alt = p.alternatives[k];
        if (alt.modules.empty()) continue;
        body.open(fmt::format("if (alt == {}u) {{", k));
        std::vector<std::optional<size_t>> partner = pairedBrackets(alt);
        for (size_t j = 0; j < alt.modules.size(); ++j) {
            const ir::SuccessorModule& m = alt.modules[j];
            std::vector<std::string> values;
            for (const ir::Expr& arg : m.args) values.push_back(body.expr(arg));
            if (slots) {
                body.line(fmt::format("slotWord{} = {}u;", j, m.sym | uint32_t(m.args.size()) << shared::kSymbolBits));
                for (size_t a = 0; a < values.size(); ++a)
                    body.line(fmt::format("slotParam{}_{} = float({});", j, a, values[a]));
            } else {
                body.line(fmt::format("emitModule(outPos + {}u, {}u, {}u, origin);", j, m.sym, m.args.size()));
                for (size_t a = 0; a < values.size(); ++a)
                    body.line(fmt::format("emitParam(outPos + {}u, {}u, {});", j, a, values[a]));
            }
            if (m.sym == ir::kBranchClose && partner[j]) // after the whole pair is written
                body.line(slots ? fmt::format("slotPartner{0} = {1}u; slotPartner{1} = {0}u;", *partner[j], j)
                                : fmt::format("emitPartners(outPos + {}u, outPos + {}u);", *partner[j], j));
        }
        body.close();
    }
}

std::string frameParameters(const ir::Production& p) {
    std::string s;
    for (int slot = 0; slot < p.frameSize; ++slot) s += fmt::format(", inout double v{}", slot);
    return s;
}

std::string frameArguments(const ir::Production& p) {
    std::string s;
    for (int slot = 0; slot < p.frameSize; ++slot) s += fmt::format(", v{}", slot);
    return s;
}

// `RESULT NAME(PARAMETERS, uint frame)`: loads the locals from frames[frame ...], calls the body function with
// them and stores them back, so that they carry over to the production's next application.
std::string frameWrapper(const ir::Production& p, const std::string& result, const std::string& name,
                         const std::string& parameters, const std::string& arguments) {
    std::string s = fmt::format("{} {}({}, uint frame) {{\n", result, name, parameters);
    for (int slot = 0; slot < p.frameSize; ++slot) s += fmt::format("    double v{0} = frames[frame + {0}u];\n", slot);
    s += fmt::format("    {}{}Body({}{});\n", result == "void" ? "" : result + " r = ", name, arguments, frameArguments(p));
    for (int slot = 0; slot < p.frameSize; ++slot) s += fmt::format("    frames[frame + {0}u] = v{0};\n", slot);
    if (result != "void") s += "    return r;\n";
    return s + "}\n\n";
}

} // namespace

void emitProduction(const ir::Grammar& g, size_t species, const ir::Production& p, RuleKind kind, size_t index,
                    FrameStyle style, std::vector<ErrorSite>& errors, std::string& out) {
    std::string name = functionName(species, kind, index);
    out += fmt::format("// {}:{}: production {}\n", p.loc.file, p.loc.line, index + 1);
    BodyEmitter body(g, species, errors, out);
    const char* bases = "uint globalBase = plant * pc.globalCount;\n    uint arrayBase = plant * pc.arrayStride;";
    const std::string testParameters =
        "uint i, uint plant, uint key, uint pBegin, uint pEnd, int ctxLeft, uint ctxRight, inout uint draw";
    if (style == FrameStyle::Fresh) {
        out += fmt::format("bool {}({}, uint mode, out uint outCount) {{\n", name, testParameters);
        body.line("outCount = 0u;");
        body.line(bases);
        for (int slot = 0; slot < p.frameSize; ++slot) body.line(fmt::format("double v{} = 0.0LF;", slot));
        emitMatch(body, g, species, p, kind, true);
        body.line("if (mode == 0u) return true;");
        emitChoice(body, p);
        body.line("if (mode == 1u) return true;");
        emitSuccessor(body, p, true);
        body.line("return true;");
        out += "}\n\n";
        return;
    }
    out += fmt::format("bool {}TestBody({}{}) {{\n", name, testParameters, frameParameters(p));
    body.line(bases);
    emitMatch(body, g, species, p, kind, false);
    body.line("return true;");
    out += "}\n\n";
    out += frameWrapper(p, "bool", name + "Test", testParameters, "i, plant, key, pBegin, pEnd, ctxLeft, ctxRight, draw");
    const std::string produceParameters = "uint plant, uint key, inout uint draw, out uint outCount";
    out += fmt::format("void {}ProduceBody({}{}) {{\n", name, produceParameters, frameParameters(p));
    body.line("outCount = 0u;");
    body.line(bases);
    body.line("const uint outPos = 0u, origin = 0u;");
    emitChoice(body, p);
    emitSuccessor(body, p, false);
    out += "}\n\n";
    out += frameWrapper(p, "void", name + "Produce", produceParameters, "plant, key, draw, outCount");
}

namespace {

// GLSL for the value (a double) and the truth of a condition part that reads only the predecessor's own
// parameters (ownParam(i, k)) and constants, through comparisons, negation and logic: std::nullopt for any other
// part. No sums or products, which a compiler may fuse differently here and in the production.
struct OwnParameterCode {
    const ir::PatternModule& predecessor;

    std::optional<std::string> value(const ir::Expr& e) const {
        using ir::Op;
        switch (e.op) {
        case Op::Const: return literal(e.value);
        case Op::Local: {
            const std::vector<int>& slots = predecessor.paramSlots;
            auto at = std::find(slots.begin(), slots.end(), e.slot);
            if (at == slots.end()) return std::nullopt;
            return fmt::format("ownParam(i, {}u)", at - slots.begin());
        }
        case Op::Neg: {
            std::optional<std::string> a = value(e.args[0]);
            return a ? std::optional(fmt::format("(-{})", *a)) : std::nullopt;
        }
        default: {
            std::optional<std::string> t = truth(e);
            return t ? std::optional(fmt::format("({} ? 1.0LF : 0.0LF)", *t)) : std::nullopt;
        }
        }
    }

    std::optional<std::string> truth(const ir::Expr& e) const {
        using ir::Op;
        switch (e.op) {
        case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne: {
            static const char* ops[] = {"<", "<=", ">", ">=", "==", "!="};
            std::optional<std::string> a = value(e.args[0]), b = value(e.args[1]);
            if (!a || !b) return std::nullopt;
            return fmt::format("({} {} {})", *a, ops[static_cast<int>(e.op) - static_cast<int>(Op::Lt)], *b);
        }
        case Op::And: case Op::Or: {
            std::optional<std::string> a = truth(e.args[0]), b = truth(e.args[1]);
            if (!a || !b) return std::nullopt;
            return fmt::format("({} {} {})", *a, e.op == Op::And ? "&&" : "||", *b);
        }
        case Op::Not: {
            std::optional<std::string> a = value(e.args[0]);
            return a ? std::optional(fmt::format("({} == 0.0LF)", *a)) : std::nullopt;
        }
        case Op::Const: case Op::Local: case Op::Neg: {
            std::optional<std::string> a = value(e);
            return a ? std::optional(fmt::format("({} != 0.0LF)", *a)) : std::nullopt;
        }
        default: return std::nullopt;
        }
    }
};

// Whether evaluating e can have no effect and raise no error: no calls, divisions or array elements.
bool harmless(const ir::Expr& e) {
    using ir::Op;
    switch (e.op) {
    case Op::Call: case Op::Div: case Op::Mod: case Op::Pow: case Op::ArrayElem: case Op::String: return false;
    default: return std::all_of(e.args.begin(), e.args.end(), harmless);
    }
}

// What a module must satisfy for step production p to apply, decided by its own parameters before any context is
// walked: the conjuncts of p's condition that OwnParameterCode can write, among those before the first one that is
// not harmless, as GLSL; "" for none. The CPU reference evaluates the condition after the contexts, from the left
// and stopping at the first false conjunct, so a module these reject draws nothing and raises no error there:
// skipping its walk changes nothing. Statements before the condition might, so p has none.
std::string ownParameterGuard(const ir::Production& p) {
    if (!p.condition || !p.before.empty() || p.strict.size() != 1) return "";
    std::vector<const ir::Expr*> conjuncts;
    auto flatten = [&](const ir::Expr& e, auto& self) -> void {
        if (e.op == ir::Op::And) {
            self(e.args[0], self);
            self(e.args[1], self);
        } else {
            conjuncts.push_back(&e);
        }
    };
    flatten(*p.condition, flatten);
    OwnParameterCode code{p.strict.front()};
    std::vector<std::string> guards;
    for (const ir::Expr* c : conjuncts) {
        if (std::optional<std::string> t = code.truth(*c))
            guards.push_back(*t);
        else if (!harmless(*c))
            break;
    }
    return fmt::format("{}", fmt::join(guards, " && "));
}

// Per species, the predecessors of the productions one prefetched walk serves, each with the guards
// (ownParameterGuard) of those productions; an empty guard lets every module of the symbol walk.
using WalkerSymbols = std::vector<std::map<ir::SymbolId, std::set<std::string>>>;

// A condition on `species`, `sym` and the module's own parameters that holds for the modules whose productions
// read a prefetched walk, so that the others do not walk: lavapipe runs a loop as long as its longest walk among
// the invocations that enter it. A species with many such symbols walks for all, where the comparisons would cost
// more than the walks they save.
std::string walkerCondition(const WalkerSymbols& walkers) {
    constexpr size_t kMostComparisons = 16;
    std::vector<std::string> terms;
    for (size_t sp = 0; sp < walkers.size(); ++sp) {
        if (walkers[sp].empty()) continue;
        std::vector<std::string> symbols;
        for (const auto& [sym, guards] : walkers[sp]) {
            if (guards.count(""))
                symbols.push_back(fmt::format("sym == {}u", sym));
            else
                symbols.push_back(fmt::format("(sym == {}u && ({}))", sym, fmt::join(guards, " || ")));
        }
        std::string bySymbol = walkers[sp].size() > kMostComparisons ? "true" : fmt::format("{}", fmt::join(symbols, " || "));
        terms.push_back(walkers.size() == 1 ? bySymbol : fmt::format("(species == {}u && ({}))", sp, bySymbol));
    }
    return fmt::format("{}", fmt::join(terms, " || "));
}

} // namespace

std::string contextPrefetchCode(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing) {
    WalkerSymbols right(species.size()), rightBranch(species.size()), left(species.size());
    bool anyWalk = false;
    for (size_t sp = 0; sp < species.size(); ++sp) {
        const ir::Grammar& g = species[sp];
        for (const ir::Production& p : (kind == RuleKind::Step ? g.productions : g.decomposition).productions) {
            // A decomposition kernel keeps its predecessor's parameters elsewhere (strictParam).
            std::string guard = kind == RuleKind::Step ? ownParameterGuard(p) : "";
            if (firstRightWalkPrefetched(g, p) && (!writing || writingWalks(p, p.right))) {
                bool enters = p.right.front().sym == ir::kBranchOpen;
                (enters ? rightBranch : right)[sp][p.strict.front().sym].insert(guard);
                anyWalk = true;
            }
            if (firstLeftWalkPrefetched(g, p) && (!writing || writingWalks(p, p.left))) {
                left[sp][p.strict.front().sym].insert(guard);
                anyWalk = true;
            }
        }
    }
    std::string code = "void prefetchContexts(uint i, uint species, uint sym, int ctxLeft, uint ctxRight, uint pBegin, uint pEnd) {\n";
    if (anyWalk) code += fmt::format("    uint skipRow = species * {}u;\n", skipWords(species.front()));
    // One walk: `name` is firstRight, firstRightBranch or firstLeft, `walk` the call that moves it.
    auto prefetch = [&](const WalkerSymbols& walkers, const std::string& name, const std::string& start, const std::string& walk) {
        std::string condition = walkerCondition(walkers);
        if (condition.empty()) return;
        code += fmt::format("    {0}Found = false;\n"
                            "    if ({1}) {{\n"
                            "        {0} = {2};\n"
                            "        {0}Found = {3};\n"
                            "        if ({0}Found) {0}Word = walkWord;\n"
                            "    }}\n",
                            name, condition, start, walk);
    };
    prefetch(right, "firstRight", "ctxRight", "walkRight(firstRight, false, pEnd, skipRow)");
    prefetch(rightBranch, "firstRightBranch", "ctxRight", "walkRight(firstRightBranch, true, pEnd, skipRow)");
    prefetch(left, "firstLeft", "ctxLeft", "walkLeft(firstLeft, pBegin, skipRow)");
    return code + "}\n\n";
}

bool mayLoopLong(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing) {
    // Well inside lavapipe's 65535 iterations, with room for the plant search and parameter copies.
    constexpr uint64_t kMostIterations = 8192;
    // The elementary functions of derive_lib.glsl and contour_curve.glsl loop at most this often per call.
    constexpr uint64_t kMostPerCall = 64;
    uint64_t iterations = 0;
    bool unbounded = false;
    auto countCalls = [&](const ir::Expr& e) {
        using ir::Builtin;
        if (e.op == ir::Op::Pow) iterations += kMostPerCall;
        if (e.op != ir::Op::Call) return;
        switch (e.fn) {
        case Builtin::Biran: unbounded = true; break;
        case Builtin::Exp: case Builtin::Log: case Builtin::Pow: case Builtin::Atan: case Builtin::Atan2:
        case Builtin::Asin: case Builtin::Acos: case Builtin::Nran: case Builtin::CurveX: case Builtin::CurveY:
        case Builtin::CurveZ:
            iterations += kMostPerCall;
            break;
        default: break;
        }
    };
    auto countLoops = [&](const ir::Stmt& st) {
        if (st.kind == ir::StmtKind::While || st.kind == ir::StmtKind::DoWhile) unbounded = true;
    };
    for (const ir::Grammar& g : species)
        for (const ir::Production& p : (kind == RuleKind::Step ? g.productions : g.decomposition).productions) {
            // Context walks pass any number of modules.
            if (writing ? writingWalks(p, p.left) || writingWalks(p, p.right) : !p.left.empty() || !p.right.empty())
                return true;
            walkProductionCode(p, countCalls, countLoops);
        }
    return unbounded || iterations > kMostIterations;
}

PlantInputs plantInputs(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing) {
    PlantInputs in;
    in.plant = species.size() > 1; // a plant's species is its index modulo their number
    auto scanExpr = [&](const ir::Expr& e) {
        if (e.op == ir::Op::Global || e.op == ir::Op::ArrayElem) in.plant = true;
        if (e.op != ir::Op::Call) return;
        switch (e.fn) {
        case ir::Builtin::Ran: case ir::Builtin::Nran: case ir::Builtin::Biran: in.random = true; break;
        case ir::Builtin::Stop: in.plant = true; break;
        default: break;
        }
    };
    auto scanStatement = [&](const ir::Stmt& st) {
        if (st.kind == ir::StmtKind::Assign && st.target != ir::TargetKind::Local) in.plant = true;
    };
    for (const ir::Grammar& g : species) {
        const ir::RuleSet& rules = kind == RuleKind::Step ? g.productions : g.decomposition;
        if (isStochastic(rules)) in.random = true;
        for (const ir::Production& p : rules.productions) {
            // A writing pass applies what the match chose: it walks only the contexts whose parameters it reads
            // (writingWalks), and the further modules of a predecessor are known to lie within the plant.
            bool walks = writing ? writingWalks(p, p.left) || writingWalks(p, p.right) : !p.left.empty() || !p.right.empty();
            if (walks || (!writing && p.strict.size() > 1)) in.bounds = true;
            if (p.alternatives.size() > 1) in.random = true;
            walkProductionCode(p, scanExpr, scanStatement);
        }
    }
    if (in.random) in.bounds = true; // a draw's key is the module's index in its plant
    if (in.bounds) in.plant = true;
    return in;
}

bool successorsKeepBracketsBalanced(const std::vector<ir::Grammar>& species) {
    auto isBracket = [](ir::SymbolId s) { return s == ir::kBranchOpen || s == ir::kBranchClose; };
    for (const ir::Grammar& g : species) {
        std::optional<ir::SymbolId> equals = g.alphabet.find("=");
        for (const ir::Production& p : g.productions.productions) {
            if (std::any_of(p.strict.begin(), p.strict.end(), [&](const ir::PatternModule& m) { return isBracket(m.sym); }))
                return false;
            if (equals && std::any_of(p.right.begin(), p.right.end(),
                                      [&](const ir::PatternModule& m) { return m.sym == *equals; }))
                return false;
            for (const ir::Alternative& alt : p.alternatives) {
                int depth = 0;
                for (const ir::SuccessorModule& m : alt.modules) {
                    depth += m.sym == ir::kBranchOpen ? 1 : m.sym == ir::kBranchClose ? -1 : 0;
                    if (depth < 0) return false;
                }
                if (depth != 0) return false;
            }
        }
    }
    return true;
}

SuccessorSlots successorSlots(const std::vector<ir::Grammar>& species, RuleKind kind, uint32_t copiedParams) {
    SuccessorSlots slots;
    slots.params.assign(1, copiedParams);
    slots.pairs.assign(1, false);
    for (const ir::Grammar& g : species)
        for (const ir::Production& p : (kind == RuleKind::Step ? g.productions : g.decomposition).productions)
            for (const ir::Alternative& alt : p.alternatives) {
                if (alt.modules.size() > slots.params.size()) {
                    slots.params.resize(alt.modules.size(), 0);
                    slots.pairs.resize(alt.modules.size(), false);
                }
                std::vector<std::optional<size_t>> partner = pairedBrackets(alt);
                for (size_t j = 0; j < alt.modules.size(); ++j) {
                    slots.params[j] = std::max(slots.params[j], static_cast<uint32_t>(alt.modules[j].args.size()));
                    if (partner[j]) slots.pairs[j] = true;
                }
            }
    return slots;
}

std::string slotDeclarations(const SuccessorSlots& slots) {
    std::string s;
    for (size_t j = 0; j < slots.params.size(); ++j) {
        s += fmt::format("uint slotWord{};", j);
        for (uint32_t a = 0; a < slots.params[j]; ++a) s += fmt::format(" float slotParam{}_{};", j, a);
        if (slots.pairs[j]) s += fmt::format(" uint slotPartner{};", j);
        s += "\n";
    }
    return s + "\n";
}

namespace {

// The stores of one slot at pos + `at` (a number or, in the loop over slots, j), its word in `word`.
std::string slotStores(const std::string& at, const std::string& word, const std::vector<std::string>& params,
                       const std::string& partner, bool provenance, uint32_t paramVector) {
    std::string s = fmt::format("        symOut[pos + {}] = {};\n", at, word);
    if (paramVector == 1) {
        for (size_t a = 0; a < params.size(); ++a)
            s += fmt::format("        if (({} >> kSymbolBits) > {}u) parOut[(pos + {}) * pc.stride + {}u] = {};\n", word, a,
                             at, a, params[a]);
    } else if (!params.empty()) {
        std::vector<std::string> components = params;
        components.resize(paramVector, "0.0");
        s += fmt::format("        if (({} >> kSymbolBits) > 0u) parOut[pos + {}] = vec{}({});\n", word, at, paramVector,
                         fmt::join(components, ", "));
    }
    if (provenance) s += fmt::format("        originOut[pos + {0}] = origin;\n        liveOut[pos + {0}] = 1u;\n", at);
    if (!partner.empty())
        s += fmt::format("        if ({0} != kNoModule) partnersOut[pos + {1}] = pos + {0};\n", partner, at);
    return s;
}

} // namespace

uint32_t parameterVectorWidth(uint32_t stride) { return stride == 2 || stride == 4 ? stride : 1; }

std::string slotStoreCode(const SuccessorSlots& slots, bool provenance, bool partners, uint32_t paramVector) {
    // Up to this many slots are stored one by one; more go through a loop (below).
    constexpr size_t kMostSlotsStoredOneByOne = 16;
    size_t count = slots.params.size();
    bool loop = count > kMostSlotsStoredOneByOne;
    std::string accessors, s = "void storeSlots(uint pos, uint n, uint origin) {\n";
    for (size_t j = 0; j < (loop ? 1 : count); ++j) {
        std::vector<std::string> params;
        for (uint32_t a = 0; a < slots.params[j]; ++a) params.push_back(fmt::format("slotParam{}_{}", j, a));
        std::string partner = partners && slots.pairs[j] ? fmt::format("slotPartner{}", j) : "";
        s += fmt::format("    if ({}u < n) {{\n", j) +
             slotStores(fmt::format("{}u", j), fmt::format("slotWord{}", j), params, partner, provenance, paramVector) +
             "    }\n";
    }
    if (loop) {
        // The slots after the first in a loop as long as the subgroup's longest successor: every store in the
        // kernel's code costs a loop over the subgroup on lavapipe, taken or not, and most subgroups copy all
        // their modules, so the loop ends after one pass where the stores one by one would be many.
        uint32_t mostParams = *std::max_element(slots.params.begin() + 1, slots.params.end());
        bool anyPairs = partners && std::find(slots.pairs.begin() + 1, slots.pairs.end(), true) != slots.pairs.end();
        accessors += "uint slotWordAt(uint j) {\n    uint w = 0u;\n";
        for (size_t j = 1; j < count; ++j) accessors += fmt::format("    if (j == {0}u) w = slotWord{0};\n", j);
        accessors += "    return w;\n}\n";
        std::vector<std::string> params;
        for (uint32_t a = 0; a < mostParams; ++a) {
            accessors += fmt::format("float slotParamAt{}(uint j) {{\n    float v = 0.0;\n", a);
            for (size_t j = 1; j < count; ++j)
                if (slots.params[j] > a) accessors += fmt::format("    if (j == {0}u) v = slotParam{0}_{1};\n", j, a);
            accessors += "    return v;\n}\n";
            params.push_back(fmt::format("slotParamAt{}(j)", a));
        }
        if (anyPairs) {
            accessors += "uint slotPartnerAt(uint j) {\n    uint p = kNoModule;\n";
            for (size_t j = 1; j < count; ++j)
                if (slots.pairs[j]) accessors += fmt::format("    if (j == {0}u) p = slotPartner{0};\n", j);
            accessors += "    return p;\n}\n";
        }
        s += "    uint most = subgroupMax(n);\n"
             "    for (uint j = 1u; j < most; ++j) {\n"
             "        if (j >= n) continue;\n"
             "        uint word = slotWordAt(j);\n";
        if (anyPairs) s += "        uint partner = slotPartnerAt(j);\n";
        s += slotStores("j", "word", params, anyPairs ? "partner" : "", provenance, paramVector);
        s += "    }\n";
    }
    return accessors + s + "}\n\n";
}

std::string resetSlotPartners(const SuccessorSlots& slots) {
    std::string s;
    for (size_t j = 0; j < slots.pairs.size(); ++j)
        if (slots.pairs[j]) s += fmt::format("    slotPartner{} = kNoModule;\n", j);
    return s;
}

std::vector<uint32_t> contextSkipBits(const std::vector<ir::Grammar>& species) {
    size_t symbols = species.front().alphabet.size();
    size_t rowWords = skipWords(species.front());
    std::vector<uint32_t> bits(rowWords * species.size(), 0);
    for (size_t sp = 0; sp < species.size(); ++sp)
        for (size_t s = 0; s < symbols; ++s)
            if (species[sp].skippedInContext(static_cast<ir::SymbolId>(s)))
                bits[sp * rowWords + s / 32] |= 1u << (s % 32);
    return bits;
}

std::string contextSkipCode(const std::vector<uint32_t>& bits) {
    // Few words become constants, so a walk tests a symbol without a load; many stay in the contextSkip buffer.
    constexpr size_t kMostConstantWords = 16;
    if (bits.size() > kMostConstantWords) return "uint contextSkipWord(uint word) { return contextSkip[word]; }\n";
    std::string code = "uint contextSkipWord(uint word) {\n    uint bits = 0u;\n";
    for (size_t w = 0; w < bits.size(); ++w)
        if (bits[w] != 0) code += fmt::format("    bits = word == {}u ? 0x{:08x}u : bits;\n", w, bits[w]);
    return code + "    return bits;\n}\n";
}

std::string functionTableCode(const ir::Grammar& g, size_t species, std::vector<double>& tables) {
    std::string code = fmt::format("double funcValue{}(double idValue, double x, uint errorSite) {{\n"
                                   "    int id = int(idValue);\n", species);
    code += "    uint offset = 0u; int samples = 0;\n";
    for (size_t f = 0; f < g.functions.size(); ++f) {
        code += fmt::format("    if (id == {}) {{ offset = {}u; samples = {}; }}\n", f + 1, tables.size(),
                            g.functions[f].samples);
        tables.insert(tables.end(), g.functions[f].table.begin(), g.functions[f].table.end());
    }
    code += "    if (samples == 0) { reportError(errorSite); return 0.0LF; }\n"
            "    if (x < 0.0LF) x = 0.0LF;\n"
            "    if (x > 1.0LF) x = 1.0LF;\n"
            "    double index = x * double(samples - 1);\n"
            "    int i = int(floor(index));\n"
            "    double w2 = index - double(i), w1 = 1.0LF - w2;\n"
            "    if (i >= samples - 1) return funcTables[offset + uint(samples - 1)];\n"
            "    return w1 * funcTables[offset + uint(i)] + w2 * funcTables[offset + uint(i + 1)];\n"
            "}\n\n";
    return code;
}


std::string perSpecies(size_t count, const std::function<std::string(size_t)>& body) {
    std::string code = "    switch (species) {\n";
    for (size_t sp = 0; sp < count; ++sp) code += fmt::format("    case {}u: {{\n{}        break;\n    }}\n", sp, body(sp));
    return code + "    }\n";
}

bool isStochastic(const ir::RuleSet& rules) {
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [](const ir::Production& p) { return p.weight >= 0; });
}

GeneratedKernels speciesTraits(const std::vector<ir::Grammar>& species) {
    GeneratedKernels k;
    for (const ir::Grammar& g : species) {
        if (!g.decomposition.productions.empty() && g.decomposition.maxDepth > 0) {
            k.hasDecomposition = true;
            k.maxDecompositionDepth = std::max(k.maxDecompositionDepth, g.decomposition.maxDepth);
        }
        for (const ir::RuleSet* rules : {&g.productions, &g.decomposition})
            for (const ir::Production& p : rules->productions) {
                if (!p.left.empty() || !p.right.empty()) k.needsBrackets = true;
                for (const ir::Alternative& alt : p.alternatives)
                    for (const ir::SuccessorModule& m : alt.modules)
                        if (m.sym == ir::kCut) k.mayCut = true;
            }
        for (const ir::SuccessorModule& m : g.axiom)
            if (m.sym == ir::kCut) k.mayCut = true;
        for (const ir::Production& p : g.productions.productions)
            k.longestPredecessor = std::max<uint32_t>(k.longestPredecessor, static_cast<uint32_t>(p.strict.size()));
    }
    if (k.mayCut) k.needsBrackets = true;
    return k;
}

std::string deriveLibrary(const std::vector<ir::Grammar>& species) {
    return contextSkipCode(contextSkipBits(species)) + std::string(shaders::glslSource("derive/depth_tree.glsl")) +
           std::string(shaders::glslSource("derive/derive_lib.glsl")) +
           std::string(shaders::glslSource("derive/contour_curve.glsl"));
}

std::string kernelPrelude(size_t speciesCount) {
    std::string s = "#version 460\n"
                    "#extension GL_EXT_shader_explicit_arithmetic_types_float64 : require\n"
                    "#extension GL_KHR_shader_subgroup_basic : require\n"
                    "#extension GL_KHR_shader_subgroup_arithmetic : require\n";
    s += std::string(shaders::glslSource("shared/derive_layout.h"));
    s += std::string(shaders::glslSource("shared/random.h"));
    s += "layout(local_size_x = kDeriveWorkgroupSize) in;\n"
         "layout(push_constant) uniform Push { DerivePush pc; };\n";
    s += fmt::format("const uint kSpeciesCount = {}u; // plant p is of species p % kSpeciesCount\n", speciesCount);
    return s;
}

} // namespace simeco::gpu::codegen
