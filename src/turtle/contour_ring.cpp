#include "turtle/contour_ring.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace simeco::turtle {

namespace {

// The point at t of the uniform cubic B-spline through the contour's points (wrapping past the last one).
glm::vec3 splinePoint(const ir::CylinderContour& c, float t) {
    // Held on the curve: a contour of enormous coordinates can make the arc-length table's steps infinite.
    t = std::isnan(t) ? 0.0f : std::clamp(t, 0.0f, static_cast<float>(c.points.size()));
    const float first = std::floor(t), u = t - first;
    const float u2 = u * u, u3 = u2 * u;
    const float w[4] = {(-u3 + 3 * u2 - 3 * u + 1) / 6.0f, (3 * u3 - 6 * u2 + 4) / 6.0f,
                        (-3 * u3 + 3 * u2 + 3 * u + 1) / 6.0f, u3 / 6.0f};
    const size_t n = c.points.size();
    glm::vec3 p(0.0f);
    for (size_t k = 0; k < 4; ++k) {
        const std::array<float, 3>& q = c.points[(static_cast<size_t>(first) + k) % n];
        p += w[k] * glm::vec3(q[0], q[1], q[2]);
    }
    return p;
}

float planarDistance(glm::vec3 a, glm::vec3 b) { return std::hypot(a.x - b.x, a.y - b.y); }

constexpr int kTableStepsPerSpan = 10;

} // namespace

std::vector<glm::vec3> contourRing(const ir::CylinderContour* contour, int sides) {
    std::vector<glm::vec3> ring(static_cast<size_t>(sides) + 1);
    if (contour == nullptr) {
        const float step = static_cast<float>(2.0 * M_PI) / static_cast<float>(sides);
        float angle = 0.0f;
        for (int i = 0; i < sides; ++i, angle += step) ring[size_t(i)] = {std::cos(angle), std::sin(angle), 0.0f};
        ring[size_t(sides)] = ring[0];
        return ring;
    }
    const ir::CylinderContour& c = *contour;
    // The summed planar chord lengths at every tenth of a span: the last tenth of an open curve is left out.
    const int spans = static_cast<int>(c.points.size()) - (c.closed ? 0 : 3);
    const int entries = spans * kTableStepsPerSpan;
    std::vector<float> lengths(static_cast<size_t>(entries));
    float t = 0.0f, total = 0.0f;
    glm::vec3 previous = splinePoint(c, 0.0f);
    for (int k = 0; k < entries; ++k, t += 0.1f) {
        const glm::vec3 p = splinePoint(c, t);
        total += planarDistance(p, previous);
        lengths[size_t(k)] = total;
        previous = p;
    }
    if (c.closed) total += planarDistance(previous, splinePoint(c, 0.0f));
    const float step = total / static_cast<float>(sides);
    // A closed contour turned so that its first point lies on +x.
    float cosine = 1.0f, sine = 0.0f;
    if (c.closed) {
        const glm::vec3 p0 = splinePoint(c, 0.0f);
        const float r = std::hypot(p0.x, p0.y);
        if (r * r >= 1e-9f) cosine = p0.x / r, sine = p0.y / r;
    }
    const int count = c.closed ? sides : sides + 1;
    const float flat = 1e-10f / step;
    size_t j = 0;
    const size_t last = size_t(entries) - 1;
    float target = 0.0f;
    for (int i = 0; i < count; ++i) {
        float at = 0.0f;
        if (i == 0) {
            while (lengths[j] < flat && j < last) ++j;
        } else {
            target += step;
            while (lengths[j] < target && j < last) ++j;
            size_t j2 = j > 0 ? j - 1 : 0;
            while (j2 > 0 && lengths[j] - lengths[j2] <= flat) --j2;
            const float span = lengths[j] - lengths[j2];
            at = static_cast<float>(j2) / 10.0f + (span > 0.0f ? (target - lengths[j2]) / span / 10.0f : 0.0f);
        }
        const glm::vec3 p = splinePoint(c, at);
        ring[size_t(i)] = {p.x * cosine + p.y * sine, -p.x * sine + p.y * cosine, c.dimension > 2 ? p.z : 0.0f};
    }
    if (c.closed) ring[size_t(sides)] = ring[0];
    return ring;
}

} // namespace simeco::turtle
