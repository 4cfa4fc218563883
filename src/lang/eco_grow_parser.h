// The Grow block of a SimEco script: the axiom `w = ...;` and the production rules, with their
// expressions parsed into ir::Expr and their variables bound to frame slots.
#pragma once

#include <vector>

#include "ir/eco_scene.h"
#include "lang/eco_lexer.h"

namespace simeco::lang {

// Parses `{ w = ...; rules }` at the cursor, just after the keyword `Grow`.
ir::EcoGrow parseEcoGrowBlock(EcoTokenCursor& cur, std::vector<ir::EcoWarning>& warnings);

} // namespace simeco::lang
