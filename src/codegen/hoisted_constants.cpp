#include "codegen/hoisted_constants.h"

#include <cstring>

#include "codegen/production_analysis.h"

namespace simeco::codegen {

namespace {

// Calls onConstant for every constant of g's productions and decompositions, in a fixed order.
template <typename Grammar, typename OnConstant>
void forEachConstant(Grammar& g, OnConstant&& onConstant) {
    for (auto* rules : {&g.productions, &g.decomposition})
        for (auto& p : rules->productions)
            walkProductionCode(
                p,
                [&](auto& e) {
                    if (e.op == ir::Op::Const) onConstant(e);
                },
                [](const auto&) {});
}

} // namespace

bool isHoisted(const ir::Expr& e) { return e.op == ir::Op::Const && e.slot > 0; }

uint32_t hoistedIndex(const ir::Expr& e) { return static_cast<uint32_t>(e.slot - 1); }

std::vector<double> constantsOf(const ir::Grammar& g) {
    std::vector<double> values;
    forEachConstant(g, [&](const ir::Expr& e) { values.push_back(e.value); });
    return values;
}

ir::Grammar withHoistedConstants(ir::Grammar g, const std::vector<bool>& hoist) {
    size_t position = 0;
    int next = 0;
    forEachConstant(g, [&](ir::Expr& e) {
        e.slot = position < hoist.size() && hoist[position] ? ++next : 0; // 0: a literal in the code
        ++position;
    });
    return g;
}

bool sameConstant(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

} // namespace simeco::codegen
