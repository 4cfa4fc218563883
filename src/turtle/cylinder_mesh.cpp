#include "turtle/cylinder_mesh.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

namespace simeco::turtle {

namespace {

using dvec3 = glm::dvec3;

// cpfg's frames have our up reversed: the mesh is built in cpfg's, where a contour's x runs along up and its y
// against left.
struct CpfgFrame {
    dvec3 heading, left, up;
};
CpfgFrame cpfgFrame(const Frame& f) { return {dvec3(f.heading), dvec3(f.left), -dvec3(f.up)}; }

// cpfg's smallest rotation taking heading a to b, applied to v: about a x b by the arcsine of |a x b| (so by less
// than the angle between them where it is over 90 degrees, as cpfg turns).
dvec3 turnedWithHeading(dvec3 a, dvec3 b, dvec3 v, double least) {
    const dvec3 axis = glm::cross(a, b);
    const double s = glm::length(axis);
    if (!(s > least)) return v;
    return rotateAbout(v, axis / s, std::asin(std::min(s, 1.0)));
}

// The ring of `sides` + 1 corners around `centre`: each contour point p (the two contours blended by `blend`,
// times `radius`) at p.x along up, p.y against left, and its z along `depth`; its normal across the contour
// between its neighbours (around the seam of a closed contour, whose last point repeats its first), placed alike.
std::vector<MeshCorner> ring(dvec3 centre, const CpfgFrame& f, dvec3 depth, double radius, double blend,
                             const glm::vec3* first, const glm::vec3* second, int sides) {
    std::vector<dvec3> p(static_cast<size_t>(sides) + 1);
    for (int i = 0; i <= sides; ++i) p[size_t(i)] = radius * ((1.0 - blend) * dvec3(first[i]) + blend * dvec3(second[i]));
    const bool closed = first[0] == first[sides] && second[0] == second[sides];
    std::vector<MeshCorner> out(p.size());
    for (int i = 0; i <= sides; ++i) {
        const int before = i > 0 ? i - 1 : (closed ? sides - 1 : 0), after = i < sides ? i + 1 : (closed ? 1 : sides);
        const dvec3 along = p[size_t(after)] - p[size_t(before)];
        const dvec3 across = along.y * f.up + along.x * f.left; // (along.y, -along.x) placed as a point is
        const double n = glm::length(across);
        out[size_t(i)] = {glm::vec3(centre + p[size_t(i)].x * f.up - p[size_t(i)].y * f.left + p[size_t(i)].z * depth),
                          n > 0.0 ? glm::vec3(across / n) : glm::vec3(0.0f)};
    }
    return out;
}

} // namespace

void setRadiusTangents(CylinderPoint& p, const std::vector<float>& params) {
    if (params.empty()) return;
    if (params.size() == 1) {
        p.scaleRadius = params[0];
        return;
    }
    constexpr double kRadians = 3.14159265358979323846 / 180.0;
    auto tangent = [&](size_t k) {
        return glm::vec2(float(std::cos(params[k] * kRadians) * params[k + 1]),
                         float(std::sin(params[k] * kRadians) * params[k + 1]));
    };
    p.radiusIn = p.radiusOut = tangent(0);
    if (params.size() >= 4) p.radiusOut = tangent(2);
}

float cylinderTwist(const CylinderPoint& from, const CylinderPoint& to) {
    const CpfgFrame s = cpfgFrame(from.frame), t = cpfgFrame(to.frame);
    const dvec3 carried = turnedWithHeading(s.heading, t.heading, s.up, 1e-6);
    double angle = std::asin(std::min(1.0, glm::length(glm::cross(t.up, carried))));
    if (glm::dot(t.up, carried) < 0.0) angle = 3.14159265358979323846 - angle;
    if (glm::dot(t.left, carried) < 0.0) angle = -angle;
    return float(angle);
}

Frame carriedFrame(const Frame& from, const Frame& to) {
    const CpfgFrame s = cpfgFrame(from), t = cpfgFrame(to);
    const dvec3 up = turnedWithHeading(s.heading, t.heading, s.up, 0.0);
    Frame out;
    out.heading = to.heading;
    out.up = glm::vec3(-up);
    out.left = glm::vec3(glm::cross(t.heading, up));
    return out;
}

CylinderCurve::CylinderCurve(const CylinderPoint& a, const CylinderPoint& b) {
    const dvec3 pa(a.position), pb(b.position);
    len_ = glm::length(pb - pa);
    const glm::vec3 t0 = glm::vec3(dvec3(a.frame.heading) * (len_ * a.tangents.y));
    const glm::vec3 t1 = glm::vec3(dvec3(b.frame.heading) * (len_ * b.tangents.x));
    const glm::vec3 d = a.position - b.position;
    c0_ = a.position;
    c1_ = t0;
    c2_ = -3.0f * d - 2.0f * t0 - t1;
    c3_ = 2.0f * d + t0 + t1;
    startRadius_ = 0.5f * a.width;
    half_ = 0.5f * (b.width - a.width);
    r0_ = a.radiusOut;
    r1_ = b.radiusIn;
    if (b.scaleRadius != 0.0f) r0_.y *= float(len_), r1_.y *= float(len_);
    if (r0_ == glm::vec2(0.0f)) r0_ = {1.0f, half_};
    if (r1_ == glm::vec2(0.0f)) r1_ = {1.0f, half_};
}

float CylinderCurve::parameterAt(float r) const {
    return r * r0_.x + r * r * (3 - 2 * r0_.x - r1_.x) + r * r * r * (-2 + r0_.x + r1_.x);
}

glm::vec3 CylinderCurve::pointAt(float t) const { return ((c3_ * t + c2_) * t + c1_) * t + c0_; }

glm::vec3 CylinderCurve::slopeAt(float t) const { return (3.0f * c3_ * t + 2.0f * c2_) * t + c1_; }

float CylinderCurve::radiusAt(float r) const {
    return startRadius_ + r * r0_.y + r * r * (3 * half_ - 2 * r0_.y - r1_.y) +
           r * r * r * (-2 * half_ + r0_.y + r1_.y);
}

std::vector<glm::vec3> tubePoints(const CylinderPoint& a, const CylinderPoint& b, int pieces) {
    const CylinderCurve curve(a, b);
    std::vector<glm::vec3> points;
    const float step = 1.0f / float(pieces);
    float r = step;
    for (int k = 1; k < pieces; ++k, r += step) points.push_back(curve.pointAt(curve.parameterAt(r)));
    return points;
}

void cylinderMesh(const CylinderPoint& a, const CylinderPoint& b, int rings, float twist, int sides,
                  const std::vector<glm::vec3>& contourRings, float shortest,
                  const std::function<void(const MeshCorner&, const MeshCorner&, const MeshCorner&)>& triangle) {
    const CylinderCurve curve(a, b);
    const double len = curve.chord();
    if (!(len > shortest)) return;
    const dvec3 pa(a.position), pb(b.position);
    const CpfgFrame fa = cpfgFrame(a.frame), fb = cpfgFrame(b.frame);
    const size_t stride = static_cast<size_t>(sides) + 1;
    const glm::vec3* ca = &contourRings[a.contour * stride];
    const glm::vec3* cb = &contourRings[b.contour * stride];

    std::vector<MeshCorner> previous =
        ring(pa, fa, fa.heading * double(a.tangents.y), 0.5 * a.width, 0.0, ca, cb, sides);
    auto strip = [&](const std::vector<MeshCorner>& next) {
        for (int i = 1; i <= sides; ++i) {
            triangle(next[size_t(i - 1)], next[size_t(i)], previous[size_t(i - 1)]);
            triangle(previous[size_t(i - 1)], next[size_t(i)], previous[size_t(i)]);
        }
    };
    const float step = 1.0f / float(rings);
    float r = step;
    for (int k = 1; k < rings; ++k, r += step) {
        const float t = curve.parameterAt(r);
        const glm::vec3 p = curve.pointAt(t);
        const glm::vec3 slope = curve.slopeAt(t);
        CpfgFrame f;
        f.heading = glm::normalize(dvec3(slope));
        f.up = rotateAbout(turnedWithHeading(fa.heading, f.heading, fa.up, 0.0), f.heading, -double(twist) * t);
        f.left = glm::cross(f.heading, f.up);
        std::vector<MeshCorner> next = ring(dvec3(p), f, f.heading / len, curve.radiusAt(r), t, ca, cb, sides);
        strip(next);
        previous = std::move(next);
    }
    const std::vector<MeshCorner> last = ring(pb, fb, fb.heading * double(b.tangents.x), 0.5 * b.width, 1.0, ca, cb, sides);
    strip(last);
}

} // namespace simeco::turtle
