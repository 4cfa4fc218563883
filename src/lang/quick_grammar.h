// Quick grammars (`.lsys`): L-systems written the way Houdini's L-system node and textbooks show them,
// one character per module.
//
//     # the ABOP fig. 1.24d tree
//     axiom: X               (or premise:)
//     angle: 20              (degrees; a trailing ° is allowed; default 90)
//     iterations: 7          (or generations:; required)
//     step: 1                (optional turtle step)
//     ignore: +-             (optional: modules that context matching skips)
//     X = F[+X]F[-X]+X       (also `->` and `→`)
//     F -> FF
//     A < B > C = BB : 0.5   (optional contexts, and a stochastic weight as in Houdini's `:prob`)
//
// Every non-blank character is one module (F f + - [ ] X Y \ / ^ & | ! % ...); spaces are ignored. A
// module may carry numeric parameters, `F(0.5)` or `+(30)`, in the axiom and successors. Lines whose first
// non-blank character is `#` are comments. Rules with a `:p` suffix compete for their predecessor with
// probability proportional to p; the others apply deterministically, first rule first.
#pragma once

#include <string>

#include "ir/grammar.h"

namespace simeco::lang {

// Parses a quick grammar; `file` names it in errors. Throws ir::InputError with line and column.
ir::Grammar parseQuickGrammar(const std::string& text, const std::string& file);

// Reads and parses a `.lsys` file.
ir::Grammar parseQuickGrammarFile(const std::string& path);

} // namespace simeco::lang
