// cpfg view files (`.v`): the turtle settings and the user-defined functions a model reads.
#pragma once

#include <string>
#include <vector>

#include "ir/grammar.h"
#include "lang/cpfg_preprocessor.h"

namespace simeco::lang {

// cpfg's drawing defaults, with a view file or without: tapered lines, pixel lines, and `$` the end of a
// sub-L-system call rather than a roll.
ir::ViewSettings cpfgDefaultView();

struct CpfgView {
    ir::ViewSettings view = cpfgDefaultView();
    std::vector<ir::FunctionCurve> functions; // func(id, x) ids are 1-based in this order
    std::vector<ir::ContourCurve> curves;     // curveX(id, t) ids are 1-based in this order
    PredefinedMacros macros;                  // NAME=id for functions read from a function set
};

// Reads a view file and the `.func` / `.fset` files it names (relative to the view file).
CpfgView readCpfgView(const std::string& path);

// Reads one function from a `.func` text (`fver 1 1` or the older `range:` format).
ir::FunctionCurve parseFunctionCurve(const std::vector<std::string>& lines, size_t& next, const std::string& file,
                                     int defaultSamples);

} // namespace simeco::lang
