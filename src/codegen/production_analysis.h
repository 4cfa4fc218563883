// What the kernel generators ask of a production: which of its context walks a pass makes ahead of the
// productions, what its code reads, and which brackets its successors pair. Private to src/gpu/.
#pragma once

#include <cstddef>
#include <optional>
#include <vector>

#include "ir/grammar.h"

namespace simeco::codegen {

// Whether the first walk of a pattern is one prefetchContexts() makes: a right pattern's from the module after a
// one-module predecessor, unless it starts with `=`; a left pattern's always. Ring L-systems walk without it:
// whether a walk may wrap depends on the pattern's earlier walks.
bool firstRightWalkPrefetched(const ir::Grammar& g, const ir::Production& p);
bool firstLeftWalkPrefetched(const ir::Grammar& g, const ir::Production& p);

// Calls onExpr for every expression node and onStatement for every statement of a production's code: its
// statements, condition (unless `withCondition` is false) and successor parameters, nested blocks and
// subexpressions included, always in this order. `Production` is ir::Production, const or not (the callbacks then
// take the nodes to change).
template <typename Production, typename OnExpr, typename OnStatement>
void walkProductionCode(Production& p, OnExpr&& onExpr, OnStatement&& onStatement, bool withCondition = true) {
    auto expr = [&](auto& e, auto& self) -> void {
        onExpr(e);
        for (auto& a : e.args) self(a, self);
    };
    auto statements = [&](auto& block, auto& self) -> void {
        for (auto& st : block) {
            onStatement(st);
            expr(st.expr, expr);
            for (auto& index : st.indices) expr(index, expr);
            self(st.body, self);
            self(st.elseBody, self);
        }
    };
    statements(p.before, statements);
    statements(p.after, statements);
    if (withCondition && p.condition) expr(*p.condition, expr);
    for (auto& alt : p.alternatives)
        for (auto& m : alt.modules)
            for (auto& arg : m.args) expr(arg, expr);
}

// Whether a condition has no effect but its value: no draws, files or stop(). A writing pass, which applies the
// production its match pass chose, need not evaluate such a condition again.
bool conditionIsPure(const ir::Production& p);

// Whether a writing pass walks `pattern`, a context of p: only for the parameters it binds, and only when the
// statements or the successor read them, or the condition, evaluated again for its effects, may.
bool writingWalks(const ir::Production& p, const std::vector<ir::PatternModule>& pattern);

// For each module of a successor, the index of the bracket it pairs within the successor, or none: the
// successor gives these brackets their partners itself.
std::vector<std::optional<size_t>> pairedBrackets(const ir::Alternative& alt);

} // namespace simeco::codegen
