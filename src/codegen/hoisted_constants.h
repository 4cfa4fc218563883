// Constants that species of one code shape hold different values of. Species that differ only in numbers (a
// branching angle, a rate, a threshold per species) would otherwise each compile their own copy of the same
// code; instead their class's code reads those numbers from a per-species table through hoisted(plant, k), and
// the numbers that all members share stay literals.
#pragma once

#include <cstdint>
#include <vector>

#include "ir/grammar.h"

namespace simeco::codegen {

// A constant the kernels read from the species' row of hoisted values, at hoistedIndex(e). Marked on the
// representative's copy of the grammar only: constants leave Expr::slot unused, and the mark is slot = index + 1.
bool isHoisted(const ir::Expr& e);
uint32_t hoistedIndex(const ir::Expr& e);

// The constants of a species' productions and decompositions, in walkProductionCode's order.
std::vector<double> constantsOf(const ir::Grammar& g);

// g with the constants at the positions `hoist` marks (in constantsOf's order) read from the table, the k-th of
// them at index k, and every other constant a literal.
ir::Grammar withHoistedConstants(ir::Grammar g, const std::vector<bool>& hoist);

// Whether two constants are the same number, bit for bit (NaN included, 0 and -0 apart).
bool sameConstant(double a, double b);

} // namespace simeco::codegen
