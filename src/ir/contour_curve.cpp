// Contour curves evaluated the way cpfg evaluates them.
//
// This work is based on cpfg's CCurveXYZ class (vlab, AlgorithmicBotany/vlab: cpfg/curveXYZ.cpp and
// cpfg/curveXYZc.cpp, called from Eval in cpfg/generate.c for curveX/Y/Z and curveGAL):
// - The control points are repeated by their multiplicity; a closed B-spline appends its first three
//   points, a phantom B-spline adds a reflected point at each end.
// - bspline / closed / phantom: uniform cubic B-spline with integer knots; parameter t in [0, 1] maps to
//   u = 3 + t * (n - 3.000001) over the segments between control points 3 .. n-1.
//   bspline-endpoint: clamped knots (0,0,0,0,1,...,n-3,n-3,n-3,n-3), u = t * (n - 3.000001).
//   bezier: floor((n - 4) / 3) + 1 cubic segments of four points sharing their ends; the segment index and
//   the local parameter are scaled by 1.000001 so that t = 1 stays inside the last segment.
//   Fewer than four points give the origin.
// - At load time the curve is sampled at i / (samples - 1), i = 0 .. samples - 1 (100 samples by default);
//   the chord lengths are summed (curveGAL returns that sum) and their running sums, divided by the total,
//   form an arc-length table.
// - curveX/Y/Z(id, t) clamp t to [0, 1], bisect the table for the samples around t, interpolate linearly
//   to a curve parameter, and evaluate the curve there. Everything is in double precision.
#include "ir/contour_curve.h"

#include <algorithm>
#include <cmath>

namespace simeco::ir {

namespace {

struct Point3 {
    double x = 0, y = 0, z = 0;
};

// Cox-de Boor recursion over the integer knots 0, 1, 2, ..., in cpfg's order of operations.
double uniformBasis(int order, int i, double t) {
    double ti = i;
    if (order == 1) return (ti <= t && t < ti + 1) ? 1.0 : 0.0;
    double left = (t - ti) / (double(i + order - 1) - ti) * uniformBasis(order - 1, i, t);
    double right = (double(i + order) - t) / (double(i + order) - double(i + 1)) * uniformBasis(order - 1, i + 1, t);
    return left + right;
}

// Knot k of the clamped (end-point interpolating) cubic B-spline over n control points.
double clampedKnot(int k, int n) {
    if (k < 4) return 0.0;
    if (k > n - 1) return double(n) - 3.0;
    return double(k) - 3.0;
}

// Cox-de Boor recursion over the clamped knots; spans of zero width contribute nothing.
double clampedBasis(int order, int k, double u, int n) {
    if (order == 1) return (clampedKnot(k, n) <= u && u < clampedKnot(k + 1, n)) ? 1.0 : 0.0;
    double result = 0.0;
    double d1 = clampedKnot(k + order - 1, n) - clampedKnot(k, n);
    if (d1 != 0.0) result += (u - clampedKnot(k, n)) / d1 * clampedBasis(order - 1, k, u, n);
    double d2 = clampedKnot(k + order, n) - clampedKnot(k + 1, n);
    if (d2 != 0.0) result += (clampedKnot(k + order, n) - u) / d2 * clampedBasis(order - 1, k + 1, u, n);
    return result;
}

Point3 controlPoint(const ContourCurve& c, int i) {
    auto k = static_cast<size_t>(i);
    return {c.xs[k], c.ys[k], c.zs[k]};
}

// The curve at parameter t in [0, 1] (no arc-length mapping).
Point3 pointAtParameter(const ContourCurve& c, double t) {
    int n = static_cast<int>(c.xs.size());
    Point3 p;
    if (n < 4) return p;
    switch (c.type) {
    case ContourType::Bezier: {
        int segments = 1 + (n - 4) / 3;
        int segment = std::clamp(static_cast<int>(t / (1.000001 / double(segments))), 0, segments - 1);
        double u = (t - double(segment) * (1.0 / double(segments))) * double(segments) / 1.000001;
        double w[4];
        for (int j = 0; j < 4; ++j)
            w[j] = clampedBasis(4, j, u, 4);
        Point3 q[4];
        for (int j = 0; j < 4; ++j)
            q[j] = controlPoint(c, segment * 3 + j);
        p.x = q[0].x * w[0] + q[1].x * w[1] + q[2].x * w[2] + q[3].x * w[3];
        p.y = q[0].y * w[0] + q[1].y * w[1] + q[2].y * w[2] + q[3].y * w[3];
        p.z = q[0].z * w[0] + q[1].z * w[1] + q[2].z * w[2] + q[3].z * w[3];
        return p;
    }
    case ContourType::BSplineEndpoint: {
        double u = t * (double(n) - 3.000001);
        for (int i = 0; i < n; ++i) {
            double w = clampedBasis(4, i, u, n);
            Point3 q = controlPoint(c, i);
            p.x += q.x * w;
            p.y += q.y * w;
            p.z += q.z * w;
        }
        return p;
    }
    case ContourType::BSpline:
    case ContourType::BSplineClosed:
    case ContourType::BSplinePhantom: {
        int i = std::clamp(3 + static_cast<int>(t * (n - 3.000001)), 3, n - 1);
        double u = 3.0 + t * (double(n) - 3.000001);
        double w[4];
        for (int j = 0; j < 4; ++j)
            w[j] = uniformBasis(4, i - 3 + j, u);
        Point3 q[4];
        for (int j = 0; j < 4; ++j)
            q[j] = controlPoint(c, i - 3 + j);
        p.x = q[0].x * w[0] + q[1].x * w[1] + q[2].x * w[2] + q[3].x * w[3];
        p.y = q[0].y * w[0] + q[1].y * w[1] + q[2].y * w[2] + q[3].y * w[3];
        p.z = q[0].z * w[0] + q[1].z * w[1] + q[2].z * w[2] + q[3].z * w[3];
        return p;
    }
    }
    return p;
}

void buildEvaluationPoints(ContourCurve& c) {
    std::vector<Point3> pts;
    bool phantom = c.type == ContourType::BSplinePhantom;
    if (phantom) pts.emplace_back();
    for (const ContourPoint& q : c.points)
        for (int m = 0; m < q.multiplicity; ++m)
            pts.push_back({q.x, q.y, q.z});
    if (c.type == ContourType::BSplineClosed) {
        // Appended one by one from the front, so a curve with fewer than three points repeats itself.
        size_t n = pts.size();
        pts.resize(n + 3);
        for (size_t i = 0; i < 3; ++i)
            pts[n + i] = pts[i];
    }
    if (phantom) {
        pts.emplace_back();
        size_t last = pts.size() - 1;
        if (pts.size() >= 4) {
            pts[0] = {2 * pts[1].x - pts[2].x, 2 * pts[1].y - pts[2].y, 2 * pts[1].z - pts[2].z};
            pts[last] = {2 * pts[last - 1].x - pts[last - 2].x, 2 * pts[last - 1].y - pts[last - 2].y,
                         2 * pts[last - 1].z - pts[last - 2].z};
        }
    }
    c.xs.clear();
    c.ys.clear();
    c.zs.clear();
    for (const Point3& q : pts) {
        c.xs.push_back(q.x);
        c.ys.push_back(q.y);
        c.zs.push_back(q.z);
    }
}

} // namespace

void sampleContourCurve(ContourCurve& c, int samples) {
    samples = std::max(samples, 2);
    buildEvaluationPoints(c);
    c.arcFraction.assign(static_cast<size_t>(samples), 0.0);
    c.length = 0.0;
    Point3 previous;
    for (int i = 0; i < samples; ++i) {
        Point3 p = pointAtParameter(c, i / double(samples - 1));
        if (i > 0) {
            double dx = p.x - previous.x, dy = p.y - previous.y, dz = p.z - previous.z;
            c.length += std::sqrt(dx * dx + dy * dy + dz * dz);
        }
        c.arcFraction[static_cast<size_t>(i)] = c.length;
        previous = p;
    }
    // A curve of zero length keeps the raw sums (all zero); curveCoordinate then uses t as the parameter.
    if (c.length > 0.0)
        for (double& l : c.arcFraction)
            l /= c.length;
}

double curveCoordinate(const ContourCurve& c, int axis, double t) {
    if (std::isnan(t)) t = 0.0;
    t = std::clamp(t, 0.0, 1.0);
    double parameter = t;
    const std::vector<double>& l = c.arcFraction;
    if (l.size() >= 2 && c.length > 0.0) {
        size_t low = 0, high = l.size() - 1;
        while (high - low > 1) {
            size_t mid = (low + high) / 2;
            if (l[mid] > t)
                high = mid;
            else
                low = mid;
        }
        double span = l[high] - l[low];
        double fraction = span != 0.0 ? (t - l[low]) / span : 0.0;
        parameter = (double(low) + fraction) / double(l.size() - 1);
    }
    Point3 p = pointAtParameter(c, parameter);
    return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

double curveLength(const ContourCurve& c) {
    return c.length;
}

} // namespace simeco::ir
