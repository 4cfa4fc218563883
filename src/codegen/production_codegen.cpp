#include "codegen/production_codegen.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <string_view>

#include <fmt/format.h>

#include "codegen/hoisted_constants.h"
#include "codegen/production_analysis.h"
#include "compute/shared/derive_layout.h"

namespace simeco::codegen {

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
        case Op::Const:
            return isHoisted(e) ? define(fmt::format("hoisted(plant, {}u)", hoistedIndex(e))) : literal(e.value);
        case Op::Local: return fmt::format("v{}", e.slot);
        case Op::Global: return fmt::format("globals[globalBase + {}u]", e.slot);
        case Op::ArrayElem: return arrayElement(e);
        case Op::Neg: return define(fmt::format("-{}", expr(e.args[0])));
        case Op::Not: return define(fmt::format("({} == 0.0LF ? 1.0LF : 0.0LF)", expr(e.args[0])));
        case Op::Add:
        case Op::Sub: {
            std::string a = expr(e.args[0]);
            std::string b = expr(e.args[1]);
            return define(fmt::format("{} {} {}", a, e.op == Op::Add ? "+" : "-", b));
        }
        case Op::Mul: {
            std::string a = factor(e.args[0]);
            std::string b = factor(e.args[1]);
            return define(fmt::format("{} * {}", a, b));
        }
        case Op::Div: {
            std::string a = factor(e.args[0]);
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

    // An operand of a product, or a quotient's dividend: a literal zero there is read through opaqueZero()
    // (derive_lib.glsl), which the driver cannot fold into the product.
    std::string factor(const ir::Expr& e) {
        if (e.op != ir::Op::Const || isHoisted(e) || e.value != 0.0) return expr(e);
        return define(std::signbit(e.value) ? "-opaqueZero()" : "opaqueZero()");
    }

    std::string define(const std::string& value) {
        std::string name = temp();
        line(fmt::format("double {} = {};", name, value));
        return name;
    }

    std::string draw() {
        std::string name = temp();
        line(fmt::format("double {} = double(randomUnit(pc.seed, pc.firstPlant + plant, currentPass(), key, draw)); "
                         "++draw;",
                         name));
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
            line(fmt::format("if (double(randomUnit(pc.seed, pc.firstPlant + plant, currentPass(), key, draw)) <= {}) "
                             "{} += 1.0LF;",
                             a[1], count));
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
        case Builtin::Light: return define("moduleLight()");
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
    add("readonly", "uint", "speciesTable"); // context filter rows, species classes (kernel_traits.h)
    add("", "uint", "errors");
    add(state, "uint", "plantFrozen"); // the sequential kernel marks 2 when a production calls stop()
}

std::string functionName(size_t species, RuleKind kind, size_t index) {
    return fmt::format("s{}{}{}", species, kind == RuleKind::Step ? "step" : "decompose", index);
}

uint32_t skipWords(const ir::Grammar& g) { return static_cast<uint32_t>((g.alphabet.size() + 31) / 32 + 1); }

namespace {

// A pattern module as the stream holds it: symbol | parameter count << kSymbolBits.
uint32_t moduleWord(const ir::PatternModule& m) {
    return m.sym | static_cast<uint32_t>(m.paramSlots.size()) << shared::kSymbolBits;
}

// GLSL that is true where `word`, a module's word, is not pattern module m's: of another name, or another count
// of parameters. Matching by name, any symbol of m's name will do (a file of several L-systems gives each its
// own, ir::Alphabet).
std::string wordDiffers(const ir::Grammar& g, const std::string& word, const ir::PatternModule& m) {
    const uint32_t count = static_cast<uint32_t>(m.paramSlots.size()) << shared::kSymbolBits;
    std::vector<std::string> same;
    for (ir::SymbolId s = 0; s < g.alphabet.size(); ++s)
        if (g.alphabet.canonical(s) == g.alphabet.canonical(m.sym))
            same.push_back(fmt::format("{} == {}u", word, s | count));
    if (same.size() == 1) return fmt::format("{} != {}u", word, moduleWord(m));
    return fmt::format("!({})", fmt::join(same, " || "));
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
        body.line(fmt::format("if (i + {}u >= pEnd || {}) return false;", k,
                              wordDiffers(g, fmt::format("symInAt(i + {}u)", k), m)));
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
                body.line(fmt::format("if (!{}Found || {}) return false;", found,
                                      wordDiffers(g, std::string(found) + "Word", m)));
                body.line(fmt::format("s = {};", found));
            } else {
                if (g.ring)
                    body.line(fmt::format("if (!rightWalk(s, {}, pBegin, pEnd, {}u, true, wrapped)) return false;",
                                          enters ? "true" : "false", skipRow));
                else
                    body.line(fmt::format("if (!rightAdvance(s, {}u, pEnd, {}u)) return false;", m.sym, skipRow));
                body.line(fmt::format("if ({}) return false;", wordDiffers(g, "symInAt(s)", m)));
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
                body.line(
                    fmt::format("if (!firstLeftFound || {}) return false;", wordDiffers(g, "firstLeftWord", *it)));
                body.line("s = firstLeft;");
            } else {
                if (g.ring)
                    body.line(fmt::format("if (!leftWalk(s, pBegin, pEnd, {}u, true, wrapped)) return false;", skipRow));
                else
                    body.line(fmt::format("if (!leftAdvance(s, pBegin, {}u)) return false;", skipRow));
                body.line(fmt::format("if ({}) return false;", wordDiffers(g, "symInAt(uint(s))", *it)));
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

// The after-statements and the draw of an alternative; sets outCount. A `modal` function leaves the alternative
// in chosenAlternative and, in mode 3, applies givenAlternative instead of drawing (derive_lib.glsl).
void emitChoice(BodyEmitter& body, const ir::Production& p, bool modal) {
    body.statements(p.after);
    size_t alternatives = p.alternatives.size();
    body.line(fmt::format("uint alt = {}u;", alternatives - 1));
    bool mayBeGiven = modal && alternatives > 1;
    if (mayBeGiven) {
        body.line("bool drawsAlternative = mode != 3u;");
        body.line("if (!drawsAlternative) alt = givenAlternative;");
    }
    for (size_t k = 0; k + 1 < alternatives; ++k) {
        body.open(fmt::format("if ({}alt == {}u) {{", mayBeGiven ? "drawsAlternative && " : "", alternatives - 1));
        body.line("double u = double(randomUnit(pc.seed, pc.firstPlant + plant, currentPass(), key, draw)); ++draw;");
        body.line(fmt::format("if (u < {}) alt = {}u;", literal(static_cast<double>(p.alternatives[k].probability)), k));
        body.close();
    }
    if (modal) body.line("chosenAlternative = alt;");
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

// The slots that matching binds: the parameters of the predecessor and its contexts. The rest are the locals.
std::vector<bool> parameterSlots(const ir::Production& p) {
    std::vector<bool> bound(static_cast<size_t>(p.frameSize), false);
    for (const auto* patterns : {&p.left, &p.strict, &p.right})
        for (const ir::PatternModule& m : *patterns)
            for (int slot : m.paramSlots) bound[static_cast<size_t>(slot)] = true;
    return bound;
}

// `bool NAMETest(PARAMETERS, uint frame)` and `void NAMEProduce(PARAMETERS, uint frame)` around the body functions.
// The locals live in frames[frame ...], loaded before and stored after each call, so that they carry over to the
// production's next application. The parameters, bound afresh by every test, pass from the test to the production
// in private variables (NAMEParameterK): storing them too made every test and production store its whole frame, and
// those stores of doubles took lavapipe's compiler most of its time on grammars with many parameters.
std::string frameWrappers(const ir::Production& p, const std::string& name, const std::string& testParameters,
                          const std::string& produceParameters) {
    const std::vector<bool> bound = parameterSlots(p);
    std::string handOff, unbound, keepParameters, takeParameters, loadLocals, storeLocals;
    for (int slot = 0; slot < p.frameSize; ++slot) {
        if (bound[static_cast<size_t>(slot)]) {
            handOff += fmt::format("double {}Parameter{};\n", name, slot);
            unbound += fmt::format("    double v{} = 0.0LF;\n", slot);
            keepParameters += fmt::format("    {}Parameter{} = v{};\n", name, slot, slot);
            takeParameters += fmt::format("    double v{} = {}Parameter{};\n", slot, name, slot);
        } else {
            loadLocals += fmt::format("    double v{0} = frames[frame + {0}u];\n", slot);
            storeLocals += fmt::format("    frames[frame + {0}u] = v{0};\n", slot);
        }
    }
    return handOff +
           fmt::format("bool {0}Test({1}, uint frame) {{\n{2}{3}"
                       "    bool r = {0}TestBody(i, plant, key, pBegin, pEnd, ctxLeft, ctxRight, draw{4});\n"
                       "{5}{6}    return r;\n}}\n\n",
                       name, testParameters, unbound, loadLocals, frameArguments(p), keepParameters, storeLocals) +
           fmt::format("void {0}Produce({1}, uint frame) {{\n{2}{3}"
                       "    {0}ProduceBody(plant, key, draw, outCount{4});\n"
                       "{5}}}\n\n",
                       name, produceParameters, takeParameters, loadLocals, frameArguments(p), storeLocals);
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
        emitChoice(body, p, true);
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
    const std::string produceParameters = "uint plant, uint key, inout uint draw, out uint outCount";
    out += fmt::format("void {}ProduceBody({}{}) {{\n", name, produceParameters, frameParameters(p));
    body.line("outCount = 0u;");
    body.line(bases);
    body.line("const uint outPos = 0u, origin = 0u;");
    emitChoice(body, p, false);
    emitSuccessor(body, p, false);
    out += "}\n\n";
    out += frameWrappers(p, name, testParameters, produceParameters);
}

} // namespace simeco::codegen
