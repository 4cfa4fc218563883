#include "gpu/derive_codegen.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include <fmt/format.h>

#include "compute/shaders.h"

namespace simeco::gpu {

namespace {

constexpr unsigned kLoopLimit = 10'000'000u; // as the CPU reference's evaluator

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

enum class RuleKind { Step, Decomposition };

// Emits straight-line GLSL for expressions and statements of one production.
class BodyEmitter {
public:
    BodyEmitter(const ir::Grammar& g, std::vector<ErrorSite>& errors, std::string& out)
        : g_(g), errors_(errors), out_(out) {}

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
        line(fmt::format("double {} = double(randomUnit(pc.seed, plant, pc.pass, key, draw)); ++draw;", name));
        return name;
    }

    std::string arrayElement(const ir::Expr& e) {
        const ir::GlobalArray& a = g_.arrays[static_cast<size_t>(e.slot)];
        uint32_t offset = 0;
        for (int k = 0; k < e.slot; ++k) offset += static_cast<uint32_t>(g_.arrays[static_cast<size_t>(k)].init.size());
        if (e.args.size() != a.dims.size()) {
            line(fmt::format("reportError({}u);", site(e.loc, fmt::format("array '{}' has {} dimension(s), {} index(es) given",
                                                                         a.name, a.dims.size(), e.args.size()))));
            return "0.0LF";
        }
        std::string flat = temp();
        line(fmt::format("uint {} = 0u;", flat));
        for (size_t k = 0; k < e.args.size(); ++k) {
            std::string v = expr(e.args[k]);
            std::string index = temp();
            line(fmt::format("int {} = int(floor({}));", index, v));
            uint32_t where = site(e.loc, fmt::format("index out of range for array '{}' (dimension {} has {} elements)",
                                                     a.name, k + 1, a.dims[k]));
            line(fmt::format("if (!({} >= 0.0LF) || {} >= {}) {{ reportError({}u); {} = 0; }}", v, index, a.dims[k], where,
                             index));
            line(fmt::format("{} = {} * {}u + uint({});", flat, flat, a.dims[k], index));
        }
        return define(fmt::format("arrays[arrayBase + {}u + {}]", offset, flat));
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
            line(fmt::format("if (double(randomUnit(pc.seed, plant, pc.pass, key, draw)) <= {}) {} += 1.0LF;", a[1], count));
            line("++draw;");
            close();
            return count;
        }
        case Builtin::Srand: return "0.0LF";
        case Builtin::Printf: return "0.0LF"; // arguments evaluated above (for their draws); nothing is printed
        case Builtin::Func: {
            uint32_t where = site(e.loc, fmt::format("func(id, x): no such function (the view file defines {})",
                                                     g_.functions.size()));
            return define(fmt::format("funcValue({}, {}, {}u)", a[0], a[1], where));
        }
        default: return "0.0LF"; // excluded by gpuUnsupportedReason
        }
    }

    void statement(const ir::Stmt& s) {
        switch (s.kind) {
        case ir::StmtKind::Assign: {
            std::string v = expr(s.expr);
            line(fmt::format("v{} = {};", s.slot, v)); // only locals: global writes are not supported here
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

std::string functionName(RuleKind kind, size_t index) {
    return fmt::format("{}{}", kind == RuleKind::Step ? "step" : "decompose", index);
}

// One production as a GLSL function. mode 0: applicable?; 1: also run the after-statements, choose the
// alternative and set outCount; 2: also write the successor at outPos.
void emitProduction(const ir::Grammar& g, const ir::Production& p, RuleKind kind, size_t index,
                    std::vector<ErrorSite>& errors, std::string& out) {
    std::optional<ir::SymbolId> equals = g.alphabet.find("=");
    out += fmt::format("// {}:{}: production {}\n", p.loc.file, p.loc.line, index + 1);
    out += fmt::format("bool {}(uint i, uint plant, uint key, uint pBegin, uint pEnd, int ctxLeft, uint ctxRight, "
                       "inout uint draw, uint mode, uint outPos, uint origin, out uint outCount) {{\n",
                       functionName(kind, index));
    BodyEmitter body(g, errors, out);
    body.line("outCount = 0u;");
    body.line("uint globalBase = plant * pc.globalCount;");
    body.line("uint arrayBase = plant * pc.arrayStride;");
    for (int slot = 0; slot < p.frameSize; ++slot) body.line(fmt::format("double v{} = 0.0LF;", slot));
    for (size_t k = 1; k < p.strict.size(); ++k) {
        // The further modules of a predecessor of several modules: adjacent, nothing skipped.
        const ir::PatternModule& m = p.strict[k];
        body.line(fmt::format("if (i + {0}u >= pEnd || symOf(i + {0}u) != {1}u || countOf(i + {0}u) != {2}u) return false;",
                              k, m.sym, m.paramSlots.size()));
        for (size_t a = 0; a < m.paramSlots.size(); ++a)
            body.line(fmt::format("v{} = paramOf(i + {}u, {}u);", m.paramSlots[a], k, a));
    }
    if (!p.right.empty()) {
        body.open("{");
        body.line(fmt::format("uint s = ctxRight + {}u;", p.strict.size() - 1));
        for (const ir::PatternModule& m : p.right) {
            if (equals && m.sym == *equals) {
                body.line("s = endOfBranch(s, pBegin, pEnd);");
                continue;
            }
            body.line(fmt::format("if (!rightAdvance(s, {}u, pEnd)) return false;", m.sym));
            body.line(fmt::format("if (symOf(s) != {}u || countOf(s) != {}u) return false;", m.sym, m.paramSlots.size()));
            for (size_t k = 0; k < m.paramSlots.size(); ++k)
                body.line(fmt::format("v{} = paramOf(s, {}u);", m.paramSlots[k], k));
            body.line("++s;");
        }
        body.close();
    }
    if (!p.left.empty()) {
        body.open("{");
        body.line("int s = ctxLeft;");
        for (auto it = p.left.rbegin(); it != p.left.rend(); ++it) {
            body.line("if (!leftAdvance(s, pBegin)) return false;");
            body.line(fmt::format("if (symOf(uint(s)) != {}u || countOf(uint(s)) != {}u) return false;", it->sym,
                                  it->paramSlots.size()));
            for (size_t k = 0; k < it->paramSlots.size(); ++k)
                body.line(fmt::format("v{} = paramOf(uint(s), {}u);", it->paramSlots[k], k));
            body.line("--s;");
        }
        body.close();
    }
    for (size_t k = 0; k < p.strict[0].paramSlots.size(); ++k)
        body.line(fmt::format("v{} = strictParam(i, {}u);", p.strict[0].paramSlots[k], k));
    body.statements(p.before);
    if (p.condition) {
        std::string c = body.expr(*p.condition);
        body.line(fmt::format("if ({} == 0.0LF) return false;", c));
    }
    body.line("if (mode == 0u) return true;");
    body.statements(p.after);
    size_t alternatives = p.alternatives.size();
    body.line(fmt::format("uint alt = {}u;", alternatives - 1));
    for (size_t k = 0; k + 1 < alternatives; ++k) {
        body.open("if (alt == " + std::to_string(alternatives - 1) + "u) {");
        body.line(fmt::format("double u = double(randomUnit(pc.seed, plant, pc.pass, key, draw)); ++draw;"));
        body.line(fmt::format("if (u < {}) alt = {}u;", literal(static_cast<double>(p.alternatives[k].probability)), k));
        body.close();
    }
    for (size_t k = 0; k < alternatives; ++k)
        body.line(fmt::format("if (alt == {}u) outCount = {}u;", k, p.alternatives[k].modules.size()));
    body.line("if (mode == 1u) return true;");
    for (size_t k = 0; k < alternatives; ++k) {
        const ir::Alternative& alt = p.alternatives[k];
        if (alt.modules.empty()) continue;
        body.open(fmt::format("if (alt == {}u) {{", k));
        for (size_t j = 0; j < alt.modules.size(); ++j) {
            const ir::SuccessorModule& m = alt.modules[j];
            std::vector<std::string> values;
            for (const ir::Expr& arg : m.args) values.push_back(body.expr(arg));
            body.line(fmt::format("emitModule(outPos + {}u, {}u, {}u, origin);", j, m.sym, m.args.size()));
            for (size_t a = 0; a < values.size(); ++a)
                body.line(fmt::format("emitParam(outPos + {}u, {}u, {});", j, a, values[a]));
        }
        body.close();
    }
    body.line("return true;");
    out += "}\n\n";
}

// The buffers of each kernel. Contexts always read the string being rewritten (symIn, parIn).
std::string declarations(bool decomposition, bool write) {
    std::string d;
    int b = 0;
    auto buffer = [&](const char* access, const char* type, const char* name) {
        d += fmt::format("layout(set = 0, binding = {}, std430) {} buffer B{} {{ {} {}[]; }};\n", b++, access, name, type, name);
    };
    buffer("readonly", "uint", "symIn");
    buffer("readonly", "float", "parIn");
    buffer("readonly", "uint", "plantStart");
    buffer("readonly", "int", "depthTree");
    buffer("readonly", "uint", "levelInfo");
    buffer("readonly", "double", "globals");
    buffer("readonly", "double", "arrays");
    buffer("readonly", "double", "funcTables");
    buffer("readonly", "uint", "contextSkip");
    buffer("", "uint", "errors");
    if (decomposition) {
        buffer("readonly", "uint", "symX");
        buffer("readonly", "float", "parX");
        buffer("readonly", "uint", "plantStartX");
        buffer("readonly", "uint", "liveX");
        buffer("readonly", "uint", "originX");
        buffer("readonly", "uint", "examined");
    }
    if (!write) {
        buffer("writeonly", "uint", "counts");
        buffer("writeonly", "uint", "choices");
        buffer("writeonly", "uint", "drawStarts");
        if (!decomposition) buffer("", "uint", "cutDelta");
    } else {
        buffer("readonly", "uint", "offsets");
        buffer("readonly", "uint", "choices");
        buffer("readonly", "uint", "drawStarts");
        buffer("writeonly", "uint", "symOut");
        buffer("writeonly", "float", "parOut");
        buffer("writeonly", "uint", "originOut");
        buffer("writeonly", "uint", "liveOut");
    }
    return d;
}

std::string functionTableCode(const ir::Grammar& g, std::vector<double>& tables) {
    std::string code = "double funcValue(double idValue, double x, uint errorSite) {\n"
                       "    int id = int(idValue);\n";
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

// The selection among one symbol's productions, as the CPU reference does it: the first applicable in file
// order, or a weighted draw among all applicable ones in stochastic L-systems. Leaves `chosen` (index + 1,
// 0 for none), `start` (draw counter at the chosen production's start) and `produced`.
std::string selection(const ir::RuleSet& rules, RuleKind kind, bool stochastic) {
    std::string code;
    std::map<ir::SymbolId, std::vector<size_t>> bySymbol;
    for (size_t i = 0; i < rules.productions.size(); ++i)
        if (kind == RuleKind::Step || rules.productions[i].strict.size() == 1) // as the CPU's decomposition
            bySymbol[rules.productions[i].strict[0].sym].push_back(i);
    code += "    switch (sym) {\n";
    for (const auto& [sym, list] : bySymbol) {
        code += fmt::format("    case {}u: {{\n", sym);
        if (!stochastic) {
            code += "        do {\n";
            for (size_t pi : list) {
                const ir::Production& p = rules.productions[pi];
                code += fmt::format("            start = draw;\n"
                                    "            if (count == {}u && {}(i, plant, key, pBegin, pEnd, ctxLeft, ctxRight, draw, "
                                    "1u, 0u, 0u, produced)) {{ chosen = {}u; length = {}u; break; }}\n",
                                    p.strict[0].paramSlots.size(), functionName(kind, pi), pi + 1, p.strict.size());
            }
            code += "        } while (false);\n";
        } else {
            code += "        double total = 0.0LF;\n        uint ignored;\n";
            for (size_t pi : list) {
                const ir::Production& p = rules.productions[pi];
                code += fmt::format("        uint start{0} = draw;\n"
                                    "        bool applicable{0} = count == {1}u && {2}(i, plant, key, pBegin, pEnd, ctxLeft, "
                                    "ctxRight, draw, 0u, 0u, 0u, ignored);\n"
                                    "        if (applicable{0}) total += {3};\n",
                                    pi, p.strict[0].paramSlots.size(), functionName(kind, pi),
                                    literal(static_cast<double>(std::max(p.weight, 0.0f))));
            }
            // Walk the applicable ones subtracting weights from r = total * u: the first to bring r to zero or
            // below wins, else the last applicable one.
            code += "        bool any = false;\n";
            for (size_t pi : list) code += fmt::format("        any = any || applicable{};\n", pi);
            code += "        if (any) {\n"
                    "            double left = total * double(randomUnit(pc.seed, plant, pc.pass, key, 0u));\n"
                    "            bool done = false;\n";
            for (size_t pi : list) {
                const ir::Production& p = rules.productions[pi];
                code += fmt::format("            if (!done && applicable{0}) {{ chosen = {1}u; start = start{0}; "
                                    "length = {3}u; left -= {2}; done = left <= 0.0LF; }}\n",
                                    pi, pi + 1, literal(static_cast<double>(std::max(p.weight, 0.0f))), p.strict.size());
            }
            code += "            draw = start;\n            switch (chosen) {\n";
            for (size_t pi : list)
                code += fmt::format("            case {}u: {}(i, plant, key, pBegin, pEnd, ctxLeft, ctxRight, draw, 1u, 0u, "
                                    "0u, produced); break;\n",
                                    pi + 1, functionName(kind, pi));
            code += "            }\n        }\n";
        }
        code += "        break;\n    }\n";
    }
    code += "    }\n";
    return code;
}

std::string writeDispatch(const ir::RuleSet& rules, RuleKind kind) {
    std::string code = "    uint produced;\n    switch (choice) {\n";
    for (size_t pi = 0; pi < rules.productions.size(); ++pi)
        code += fmt::format("    case {}u: {}(i, plant, key, pBegin, pEnd, ctxLeft, ctxRight, draw, 2u, pos, origin, "
                            "produced); break;\n",
                            pi + 1, functionName(kind, pi));
    code += "    }\n";
    return code;
}

// How a kernel writes successor modules: nowhere (match passes), or into symOut/parOut, with the position each
// module came from and its liveness when decomposition follows.
std::string emitters(bool writes, bool provenance) {
    if (!writes)
        return "void emitModule(uint pos, uint sym, uint count, uint origin) {}\n"
               "void emitParam(uint pos, uint k, double value) {}\n\n";
    std::string s = "void emitModule(uint pos, uint sym, uint count, uint origin) {\n"
                    "    symOut[pos] = sym | (count << kSymbolBits);\n";
    if (provenance) // where each module came from, for decomposition's contexts
        s += "    originOut[pos] = origin;\n"
             "    liveOut[pos] = 1u;\n";
    return s + "}\n"
               "void emitParam(uint pos, uint k, double value) { parOut[pos * pc.stride + k] = float(value); }\n\n";
}

// The end of a match kernel: what it found for module i.
std::string recordChoice() {
    return "    if (chosen == 0u) produced = 1u;\n"
           "    counts[i] = produced;\n"
           "    choices[i] = chosen | ((length - 1u) << 24u); // the predecessor's length for the greedy walk\n"
           "    drawStarts[i] = start;\n"
           "}\n";
}

} // namespace

GeneratedKernels generateDeriveKernels(const ir::Grammar& g) {
    GeneratedKernels k;
    k.hasDecomposition = !g.decomposition.productions.empty() && g.decomposition.maxDepth > 0;
    for (const ir::RuleSet* rules : {&g.productions, &g.decomposition})
        for (const ir::Production& p : rules->productions) {
            if (!p.left.empty() || !p.right.empty()) k.needsBrackets = true;
            for (const ir::Alternative& alt : p.alternatives)
                for (const ir::SuccessorModule& m : alt.modules)
                    if (m.sym == ir::kCut) k.mayCut = true;
        }
    for (const ir::SuccessorModule& m : g.axiom)
        if (m.sym == ir::kCut) k.mayCut = true;
    if (k.mayCut) k.needsBrackets = true;
    for (const ir::Production& p : g.productions.productions)
        k.longestPredecessor = std::max<uint32_t>(k.longestPredecessor, static_cast<uint32_t>(p.strict.size()));
    bool stochastic = false;
    for (const ir::Production& p : g.productions.productions) stochastic = stochastic || p.weight >= 0;
    bool decompositionStochastic = false;
    for (const ir::Production& p : g.decomposition.productions)
        decompositionStochastic = decompositionStochastic || p.weight >= 0;

    std::string prelude = "#version 460\n"
                          "#extension GL_EXT_shader_explicit_arithmetic_types_float64 : require\n";
    prelude += std::string(shaders::glslSource("shared/derive_layout.h"));
    prelude += std::string(shaders::glslSource("shared/random.h"));
    prelude += "layout(local_size_x = kDeriveWorkgroupSize) in;\n"
               "layout(push_constant) uniform Push { DerivePush pc; };\n";
    std::string library(shaders::glslSource("derive/derive_lib.glsl"));
    std::string functions = functionTableCode(g, k.functionTables);
    std::vector<ErrorSite>& errors = k.errors;

    std::string stepFunctions, decompositionFunctions;
    for (size_t i = 0; i < g.productions.productions.size(); ++i)
        emitProduction(g, g.productions.productions[i], RuleKind::Step, i, errors, stepFunctions);
    for (size_t i = 0; i < g.decomposition.productions.size(); ++i)
        emitProduction(g, g.decomposition.productions[i], RuleKind::Decomposition, i, errors, decompositionFunctions);

    const std::string globalIndex =
        "    uint i = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + "
        "gl_LocalInvocationID.x;\n    if (i >= pc.count) return;\n";
    auto findPlant = [](const char* table, const char* name) {
        return fmt::format("uint {}(uint i) {{\n"
                           "    uint low = 0u, high = pc.plants - 1u;\n"
                           "    while (low < high) {{\n"
                           "        uint mid = (low + high + 1u) / 2u;\n"
                           "        if ({}[mid] <= i) low = mid; else high = mid - 1u;\n"
                           "    }}\n"
                           "    return low;\n}}\n\n",
                           name, table);
    };

    // ---- derivation step: match ----
    {
        std::string s = prelude + declarations(false, false) + library + functions;
        s += "double strictParam(uint i, uint k) { return paramOf(i, k); }\n" + emitters(false, false);
        s += findPlant("plantStart", "plantOf");
        s += stepFunctions;
        s += "void main() {\n" + globalIndex;
        s += "    uint plant = plantOf(i);\n"
             "    uint pBegin = plantStart[plant], pEnd = plantStart[plant + 1u];\n"
             "    uint sym = symOf(i), count = countOf(i);\n"
             "    uint key = i - pBegin;\n"
             "    int ctxLeft = int(i) - 1;\n"
             "    uint ctxRight = i + 1u;\n"
             "    uint draw = 1u, chosen = 0u, start = 0u, produced = 1u, length = 1u;\n";
        s += selection(g.productions, RuleKind::Step, stochastic);
        if (k.mayCut) {
            s += "    if (chosen == 0u && sym == 2u && count == 0u) {\n"
                 "        // A cut: this module and the rest of its branch leave the string.\n"
                 "        atomicAdd(cutDelta[i], 1u);\n"
                 "        atomicAdd(cutDelta[endOfBranch(i + 1u, pBegin, pEnd)], 0xFFFFFFFFu);\n"
                 "    }\n";
        }
        s += recordChoice();
        k.match = std::move(s);
    }
    // ---- derivation step: write ----
    {
        std::string s = prelude + declarations(false, true) + library + functions;
        s += "double strictParam(uint i, uint k) { return paramOf(i, k); }\n" + emitters(true, k.hasDecomposition);
        s += findPlant("plantStart", "plantOf");
        s += stepFunctions;
        s += "void main() {\n" + globalIndex;
        s += "    uint choice = choices[i];\n"
             "    if (choice == kChoiceDropped) return;\n"
             "    choice &= kSymbolMask;\n"
             "    uint pos = offsets[i];\n"
             "    uint origin = i;\n"
             "    if (choice == kChoiceCopy) {\n"
             "        uint count = countOf(i);\n"
             "        emitModule(pos, symOf(i), count, origin);\n"
             "        for (uint k = 0u; k < count; ++k) parOut[pos * pc.stride + k] = parIn[i * pc.stride + k];\n"
             "        return;\n"
             "    }\n"
             "    uint plant = plantOf(i);\n"
             "    uint pBegin = plantStart[plant], pEnd = plantStart[plant + 1u];\n"
             "    uint key = i - pBegin;\n"
             "    int ctxLeft = int(i) - 1;\n"
             "    uint ctxRight = i + 1u;\n"
             "    uint draw = drawStarts[i];\n";
        s += writeDispatch(g.productions, RuleKind::Step);
        s += "}\n";
        k.write = std::move(s);
    }
    if (k.hasDecomposition) {
        const std::string decompositionSetup =
            "    uint plant = plantOfX(i);\n"
            "    uint pBegin = plantStart[plant], pEnd = plantStart[plant + 1u];\n"
            "    uint origin = originX[i];\n"
            "    uint key = examined[i] - examined[plantStartX[plant]];\n"
            "    int ctxLeft = int(origin) - 1;\n"
            "    uint ctxRight = origin + 1u;\n";
        // ---- decomposition: match ----
        {
            std::string s = prelude + declarations(true, false) + library + functions;
            s += "double strictParam(uint i, uint k) { return double(parX[i * pc.stride + k]); }\n" +
                 emitters(false, false);
            s += findPlant("plantStartX", "plantOfX");
            s += decompositionFunctions;
            s += "void main() {\n" + globalIndex;
            s += "    if (liveX[i] == 0u) { counts[i] = 1u; choices[i] = kChoiceCopy; drawStarts[i] = 0u; return; }\n";
            s += decompositionSetup;
            s += "    uint sym = symX[i] & kSymbolMask, count = symX[i] >> kSymbolBits;\n"
                 "    uint draw = 1u, chosen = 0u, start = 0u, produced = 1u, length = 1u;\n";
            s += selection(g.decomposition, RuleKind::Decomposition, decompositionStochastic);
            s += recordChoice();
            k.decompositionMatch = std::move(s);
        }
        // ---- decomposition: write ----
        {
            std::string s = prelude + declarations(true, true) + library + functions;
            s += "double strictParam(uint i, uint k) { return double(parX[i * pc.stride + k]); }\n" +
                 emitters(true, true);
            s += findPlant("plantStartX", "plantOfX");
            s += decompositionFunctions;
            s += "void main() {\n" + globalIndex;
            s += "    uint choice = choices[i];\n"
                 "    uint pos = offsets[i];\n"
                 "    if (choice == kChoiceCopy) {\n"
                 "        uint count = symX[i] >> kSymbolBits;\n"
                 "        symOut[pos] = symX[i];\n"
                 "        originOut[pos] = originX[i];\n"
                 "        liveOut[pos] = 0u; // not decomposed at this depth: final\n"
                 "        for (uint k = 0u; k < count; ++k) parOut[pos * pc.stride + k] = parX[i * pc.stride + k];\n"
                 "        return;\n"
                 "    }\n";
            s += decompositionSetup;
            s += "    uint draw = drawStarts[i];\n";
            s += writeDispatch(g.decomposition, RuleKind::Decomposition);
            s += "}\n";
            k.decompositionWrite = std::move(s);
        }
    }
    return k;
}

} // namespace simeco::gpu
