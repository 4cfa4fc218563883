// Contour curves (curveX/curveY/curveZ/curveGAL) in generated kernels, evaluated with the same double-precision
// operations as ir/contour_curve.cpp, so that the device derives the same parameters as the CPU reference.
//
// A curve is a record in funcTables (gpu/curve_codegen.cpp writes it): its type (ir::ContourType), the count n
// of evaluation points, the count of arc-length samples and the curve's length, then the n x, the n y and the
// n z coordinates, then the arc-length table. Expects funcTables before it.

const int kCurveBezier = 4;          // ir::ContourType::Bezier
const int kCurveBSplineEndpoint = 2; // ir::ContourType::BSplineEndpoint

// Knot k of the cubic B-spline over n points: integer knots, or the clamped knots 0,0,0,0,1,...,n-3 (x4).
double curveKnot(int k, int n, bool clamped) {
    if (!clamped) return double(k);
    if (k < 4) return 0.0LF;
    if (k > n - 1) return double(n) - 3.0LF;
    return double(k) - 3.0LF;
}

// The cubic basis function that starts at knot k, at u: the Cox-de Boor recursion computed bottom-up (GLSL has
// no recursion), one order at a time, with the host's operations; spans of zero width contribute nothing.
double curveBasis(int k, double u, int n, bool clamped) {
    double b[4];
    for (int j = 0; j < 4; ++j)
        b[j] = (curveKnot(k + j, n, clamped) <= u && u < curveKnot(k + j + 1, n, clamped)) ? 1.0LF : 0.0LF;
    for (int order = 2; order <= 4; ++order)
        for (int j = 0; j <= 4 - order; ++j) {
            int m = k + j;
            double result = 0.0LF;
            double d1 = curveKnot(m + order - 1, n, clamped) - curveKnot(m, n, clamped);
            if (d1 != 0.0LF) result += (u - curveKnot(m, n, clamped)) / d1 * b[j];
            double d2 = curveKnot(m + order, n, clamped) - curveKnot(m + 1, n, clamped);
            if (d2 != 0.0LF) result += (curveKnot(m + order, n, clamped) - u) / d2 * b[j + 1];
            b[j] = result;
        }
    return b[0];
}

dvec3 curveControlPoint(uint record, int n, int i) {
    uint at = record + 4u + uint(i);
    return dvec3(funcTables[at], funcTables[at + uint(n)], funcTables[at + 2u * uint(n)]);
}

// Four control points from `first` weighted by the basis functions that start at `firstBasis`, summed in order.
dvec3 curveSegment(uint record, int n, int first, int firstBasis, double u, int basisPoints, bool clamped) {
    dvec3 p = curveControlPoint(record, n, first) * curveBasis(firstBasis, u, basisPoints, clamped);
    for (int j = 1; j < 4; ++j)
        p += curveControlPoint(record, n, first + j) * curveBasis(firstBasis + j, u, basisPoints, clamped);
    return p;
}

// The curve at parameter t in [0, 1], before the arc-length mapping.
dvec3 curvePointAtParameter(uint record, double t) {
    int type = int(funcTables[record]);
    int n = int(funcTables[record + 1u]);
    if (n < 4) return dvec3(0.0LF);
    if (type == kCurveBezier) {
        int segments = 1 + (n - 4) / 3;
        int segment = clamp(int(t / (1.000001LF / double(segments))), 0, segments - 1);
        double u = (t - double(segment) * (1.0LF / double(segments))) * double(segments) / 1.000001LF;
        return curveSegment(record, n, segment * 3, 0, u, 4, true);
    }
    if (type == kCurveBSplineEndpoint) {
        double u = t * (double(n) - 3.000001LF);
        dvec3 p = dvec3(0.0LF);
        for (int i = 0; i < n; ++i)
            p += curveControlPoint(record, n, i) * curveBasis(i, u, n, true);
        return p;
    }
    // bspline, closed and phantom: uniform knots
    int i = clamp(3 + int(t * (double(n) - 3.000001LF)), 3, n - 1);
    double u = 3.0LF + t * (double(n) - 3.000001LF);
    return curveSegment(record, n, i - 3, i - 3, u, n, false);
}

// curveX/Y/Z: coordinate `axis` of the curve at arc-length fraction t (clamped to [0, 1]).
double curveCoordinate(uint record, int axis, double t) {
    if (isnan(t)) t = 0.0LF;
    t = clamp(t, 0.0LF, 1.0LF);
    int n = int(funcTables[record + 1u]);
    int samples = int(funcTables[record + 2u]);
    double length = funcTables[record + 3u];
    uint table = record + 4u + 3u * uint(n);
    double parameter = t;
    if (samples >= 2 && length > 0.0LF) {
        uint low = 0u, high = uint(samples - 1);
        while (high - low > 1u) {
            uint mid = (low + high) / 2u;
            if (funcTables[table + mid] > t)
                high = mid;
            else
                low = mid;
        }
        double span = funcTables[table + high] - funcTables[table + low];
        double fraction = span != 0.0LF ? (t - funcTables[table + low]) / span : 0.0LF;
        parameter = (double(low) + fraction) / double(samples - 1);
    }
    dvec3 p = curvePointAtParameter(record, parameter);
    return axis == 0 ? p.x : axis == 1 ? p.y : p.z;
}

// curveGAL: the curve's summed chord length.
double curveLength(uint record) { return funcTables[record + 3u]; }
