#include "ir/function_curve.h"

#include <cmath>

#include "ir/grammar.h"

namespace simeco::ir {

namespace {

// Knots of the clamped uniform cubic B-spline over control points 0..n: [0,0,0,0,1,...,n-2,n-2,n-2,n-2].
int knot(int j, int n) {
    if (j < 4) return 0;
    if (j > n) return n - 2;
    return j - 3;
}

// Cox-de Boor recursion with half-open spans, as cpfg evaluates it.
double basis(int k, int order, double u, int n) {
    if (order == 1) return (knot(k, n) <= u && u < knot(k + 1, n)) ? 1.0 : 0.0;
    double value = 0.0;
    int d1 = knot(k + order - 1, n) - knot(k, n);
    if (d1 != 0) value += (u - knot(k, n)) / d1 * basis(k, order - 1, u, n);
    int d2 = knot(k + order, n) - knot(k + 1, n);
    if (d2 != 0) value += (knot(k + order, n) - u) / d2 * basis(k + 1, order - 1, u, n);
    return value;
}

double directValue(const FunctionCurve& f, double v) {
    double low = 0.0, high = 1.0, x = 0.0, y = 0.0;
    for (int guard = 0; guard < 200; ++guard) {
        double check = (low + high) / 2;
        curvePoint(f, check, x, y);
        if (x > v) high = check;
        else low = check;
        if (std::fabs(x - v) <= 0.001) break;
    }
    return y;
}

} // namespace

void curvePoint(const FunctionCurve& f, double d, double& x, double& y) {
    int n = static_cast<int>(f.xs.size()) - 1;
    double u = d * (n - 2);
    x = 0.0;
    y = 0.0;
    for (int k = 0; k <= n; ++k) {
        double b = basis(k, 4, u, n);
        x += f.xs[static_cast<size_t>(k)] * b;
        y += f.ys[static_cast<size_t>(k)] * b;
    }
}

double evaluateCurve(const FunctionCurve& f, double x) {
    if (x < 0) x = 0;
    if (x > 1) x = 1;
    if (f.samples > 2 && !f.table.empty()) {
        double index = x * (f.samples - 1);
        int i = static_cast<int>(std::floor(index));
        double w2 = index - i, w1 = 1 - w2;
        if (i >= f.samples - 1) return f.table[static_cast<size_t>(f.samples - 1)];
        return w1 * f.table[static_cast<size_t>(i)] + w2 * f.table[static_cast<size_t>(i + 1)];
    }
    return directValue(f, x);
}

void precomputeCurve(FunctionCurve& f) {
    f.table.clear();
    if (f.samples <= 2) return;
    for (int i = 0; i < f.samples; ++i)
        f.table.push_back(directValue(f, static_cast<double>(i) / static_cast<double>(f.samples - 1)));
}

} // namespace simeco::ir
