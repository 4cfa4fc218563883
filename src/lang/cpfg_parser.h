// The cpfg / L-studio `.l` language: parsed from preprocessed text into the grammar IR.
//
// Follows cpfg's reader: every module is one character (`@Gs` is the three modules `@`, `G`, `s`, as cpfg
// stores it), parameters in parentheses, `*` for an empty successor or context, `-->` (also `->`, `→`).
// One extension: when predecessors use names of several characters (`SYM(a,b)`, `C1Aend_s(c)`,
// `milt-tail(T,t)`), or a `module` line declares them, those names are modules and are matched longest
// first wherever modules are read.
#pragma once

#include <string>

#include "ir/grammar.h"
#include "lang/cpfg_preprocessor.h"

namespace simeco::lang {

// Parses the first L-system of a preprocessed file. Function curves already loaded (from the view file)
// are passed in `functions` so that `func(id, x)` can be checked.
ir::Grammar parseCpfg(const PreprocessedText& text, std::vector<ir::FunctionCurve> functions);

} // namespace simeco::lang
