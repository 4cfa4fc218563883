// What the GPU strategies can derive exactly as the CPU reference does.
//
// The parallel passes rewrite every module at once, so anything that makes one module's rewriting depend on an
// earlier module's — productions writing globals or arrays, locals that carry their value over from the
// production's previous application (cpfg keeps one variable table per production), stop() — is left to the
// sequential kernel, which walks each plant in order. Neither does what a device cannot: file input and output
// in productions. printf() is accepted and prints nothing: the derived string is the same.
#include <set>

#include <fmt/format.h>

#include "codegen/derive_support.h"

namespace simeco::codegen {

namespace {

struct Checker {
    const ir::Grammar& g;
    bool parallel; // the parallel passes' limits too
    std::optional<std::string> reason;

    void fail(const ir::SourceLoc& loc, const std::string& what) {
        if (!reason) reason = fmt::format("{}:{}: {}", loc.file, loc.line, what);
    }

    // Reads in e of slots not yet assigned, and unsupported calls.
    void expr(const ir::Expr& e, const std::set<int>& assigned) {
        if (parallel && e.op == ir::Op::Local && !assigned.count(e.slot))
            fail(e.loc, "a local variable is read before it is assigned (cpfg carries its value over between "
                        "applications of the production)");
        if (e.op == ir::Op::Call) {
            switch (e.fn) {
            case ir::Builtin::Stop:
                if (parallel) fail(e.loc, "stop() in a production");
                break;
            case ir::Builtin::Bran:
            case ir::Builtin::Fopen:
            case ir::Builtin::Fclose:
            case ir::Builtin::Fflush:
            case ir::Builtin::Fprintf:
            case ir::Builtin::Fscanf: fail(e.loc, fmt::format("{}() in a production", ir::builtinName(e.fn))); break;
            case ir::Builtin::Func:
                for (const ir::FunctionCurve& f : g.functions)
                    if (f.samples <= 2) fail(e.loc, "func() of a function without precomputed samples");
                break;
            default: break;
            }
        }
        for (const ir::Expr& a : e.args) expr(a, assigned);
    }

    void statements(const std::vector<ir::Stmt>& stmts, std::set<int>& assigned) {
        for (const ir::Stmt& s : stmts) {
            switch (s.kind) {
            case ir::StmtKind::Assign:
                expr(s.expr, assigned);
                for (const ir::Expr& i : s.indices) expr(i, assigned);
                if (parallel && s.target != ir::TargetKind::Local)
                    fail(s.loc, "a production assigns a global variable or an array");
                else assigned.insert(s.slot);
                break;
            case ir::StmtKind::Eval: expr(s.expr, assigned); break;
            case ir::StmtKind::If: {
                expr(s.expr, assigned);
                std::set<int> a = assigned, b = assigned;
                statements(s.body, a);
                statements(s.elseBody, b);
                for (int slot : a)
                    if (b.count(slot)) assigned.insert(slot);
                break;
            }
            case ir::StmtKind::While: {
                expr(s.expr, assigned);
                std::set<int> inside = assigned;
                statements(s.body, inside);
                expr(s.expr, inside);
                break;
            }
            case ir::StmtKind::DoWhile:
                statements(s.body, assigned);
                expr(s.expr, assigned);
                break;
            }
        }
    }

    void production(const ir::Production& p, bool decomposition) {
        if (parallel && p.strict.size() > 8) fail(p.loc, "a predecessor of more than 8 modules");
        if (parallel && decomposition && p.strict[0].sym == ir::kCut)
            fail(p.loc, "a decomposition production for the cut '%'");
        std::set<int> assigned;
        for (const auto* patterns : {&p.left, &p.strict, &p.right})
            for (const ir::PatternModule& m : *patterns) assigned.insert(m.paramSlots.begin(), m.paramSlots.end());
        statements(p.before, assigned);
        if (p.condition) expr(*p.condition, assigned);
        statements(p.after, assigned);
        for (const ir::Alternative& alt : p.alternatives)
            for (const ir::SuccessorModule& m : alt.modules) {
                if (m.args.size() > 255) fail(m.loc, "more than 255 parameters");
                for (const ir::Expr& a : m.args) expr(a, assigned);
            }
    }
};

std::optional<std::string> unsupportedReason(const ir::Grammar& g, bool parallel) {
    Checker check{g, parallel, std::nullopt};
    if (g.alphabet.size() > (1u << 24)) check.fail(g.axiomLoc, "more than 2^24 symbols");
    for (const ir::Production& p : g.productions.productions) check.production(p, false);
    if (g.decomposition.maxDepth > 0)
        for (const ir::Production& p : g.decomposition.productions) check.production(p, true);
    return check.reason;
}

} // namespace

std::optional<std::string> gpuUnsupportedReason(const ir::Grammar& g) { return unsupportedReason(g, false); }

std::optional<std::string> gpuParallelUnsupportedReason(const ir::Grammar& g) { return unsupportedReason(g, true); }

} // namespace simeco::codegen
