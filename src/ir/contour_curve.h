// cpfg contour curves (`curve:` lines of a view file, `.con` files), read by curveX/curveY/curveZ(id, t)
// and curveGAL(id) in expressions.
//
// cpfg evaluates these curves by arc length: when a curve is loaded it samples the curve at `samples`
// evenly spaced parameters (100 unless the `curve:` line gives a count), sums the chord lengths into a
// normalised table, and curveX(id, t) looks t up in that table before evaluating the curve. curveGAL is the
// summed chord length.
#pragma once

#include <string>
#include <vector>

namespace simeco::ir {

// The `type:` of a `.con` file. cpfg's fifth type, bezier-surface, is refused by the reader.
enum class ContourType { BSpline, BSplineClosed, BSplineEndpoint, BSplinePhantom, Bezier };

struct ContourPoint {
    double x = 0, y = 0, z = 0;
    int multiplicity = 1;
};

struct ContourCurve {
    std::string name;
    ContourType type = ContourType::BSpline;
    std::vector<ContourPoint> points; // as the file lists them

    // Filled by sampleContourCurve.
    std::vector<double> xs, ys, zs;  // control points, repeated by their multiplicity, plus the extra
                                     // points of closed and phantom curves
    std::vector<double> arcFraction; // cumulative chord length at sample i / (samples - 1), over length
    double length = 0.0;             // summed chord length of the samples (curveGAL)
};

// Builds the evaluation points and the arc-length table from `points` with `samples` samples (cpfg's
// default is 100; counts below 2 are raised to 2).
void sampleContourCurve(ContourCurve& c, int samples = 100);

// Coordinate `axis` (0 = x, 1 = y, 2 = z) of the curve at t in [0, 1] (clamped), as cpfg computes it.
double curveCoordinate(const ContourCurve& c, int axis, double t);
// The length of the curve, as cpfg's curveGAL returns it.
double curveLength(const ContourCurve& c);

} // namespace simeco::ir
