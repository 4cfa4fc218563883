#include "codegen/production_analysis.h"

#include <set>

namespace simeco::codegen {

bool firstRightWalkPrefetched(const ir::Grammar& g, const ir::Production& p) {
    std::optional<ir::SymbolId> equals = g.alphabet.find("=");
    return !g.ring && p.strict.size() == 1 && !p.right.empty() && !(equals && p.right.front().sym == *equals);
}

bool firstLeftWalkPrefetched(const ir::Grammar& g, const ir::Production& p) { return !g.ring && !p.left.empty(); }

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

} // namespace simeco::codegen
