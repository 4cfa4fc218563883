// User-defined functions of one variable on [0, 1] (cpfg `.func` files), evaluated the way cpfg does.
//
// The curve is a clamped uniform cubic B-spline through control points (x, y); func(id, x) finds the curve
// parameter whose x matches by bisection to cpfg's tolerance and returns y there. With `samples` > 2 the
// values are precomputed at i/(samples-1) and interpolated linearly, as cpfg does; GPU kernels read the
// same table.
#pragma once

#include <string>
#include <vector>

namespace simeco::ir {

struct FunctionCurve;

// The point of the curve at parameter d in [0, 1].
void curvePoint(const FunctionCurve& f, double d, double& x, double& y);
// The function value at x (clamped to [0, 1]).
double evaluateCurve(const FunctionCurve& f, double x);
// Fills f.table from the curve when f.samples > 2.
void precomputeCurve(FunctionCurve& f);

} // namespace simeco::ir
