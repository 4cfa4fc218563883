#include "draw/leaf_silhouette.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace simeco::draw {
namespace {

// Hull corners searched for the quadrilateral at most (it is found in cubic time); a larger hull is thinned evenly.
constexpr std::size_t kMostHullCorners = 48;

// Twice the signed area of triangle (o, a, b): positive when it turns counter-clockwise.
float turn(glm::vec2 o, glm::vec2 a, glm::vec2 b) {
    return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
}

// The convex hull counter-clockwise, without corners on its edges (Andrew's monotone chain).
std::vector<glm::vec2> convexHull(std::vector<glm::vec2> points) {
    std::sort(points.begin(), points.end(),
              [](glm::vec2 a, glm::vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    points.erase(std::unique(points.begin(), points.end()), points.end());
    if (points.size() < 3) return points;
    std::vector<glm::vec2> hull(2 * points.size());
    std::size_t k = 0;
    for (glm::vec2 p : points) { // the lower chain
        while (k >= 2 && turn(hull[k - 2], hull[k - 1], p) <= 0.0f)
            --k;
        hull[k++] = p;
    }
    const std::size_t lower = k + 1;
    for (std::size_t i = points.size() - 1; i-- > 0;) { // the upper chain, back to the first point
        while (k >= lower && turn(hull[k - 2], hull[k - 1], points[i]) <= 0.0f)
            --k;
        hull[k++] = points[i];
    }
    hull.resize(k - 1);
    return hull;
}

// The centroid of a simple polygon, and twice its signed area.
glm::vec2 centroid(std::span<const glm::vec2> polygon, float& twiceArea) {
    glm::vec2 sum(0.0f);
    twiceArea = 0.0f;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const glm::vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
        const float c = a.x * b.y - b.x * a.y;
        twiceArea += c;
        sum += (a + b) * c;
    }
    return sum / (3.0f * twiceArea);
}

} // namespace

std::optional<std::array<glm::vec2, 4>> silhouetteQuad(std::vector<glm::vec2> points, float area) {
    if (!(area > 0.0f)) return std::nullopt;
    std::vector<glm::vec2> hull = convexHull(std::move(points));
    if (hull.size() > kMostHullCorners) {
        std::vector<glm::vec2> thinned;
        for (std::size_t i = 0; i < kMostHullCorners; ++i)
            thinned.push_back(hull[i * hull.size() / kMostHullCorners]);
        hull = std::move(thinned);
    }
    const std::size_t n = hull.size();
    if (n < 4) return std::nullopt;

    // The largest quadrilateral (i, j, k, l) on the hull: for each diagonal (i, k), the corner farthest from it on
    // either side.
    float best = 0.0f;
    std::array<std::size_t, 4> chosen{};
    for (std::size_t i = 0; i < n; ++i)
        for (std::size_t k = i + 2; k < n; ++k) {
            float left = 0.0f, right = 0.0f;
            std::size_t j = i, l = k;
            for (std::size_t m = i + 1; m < k; ++m) {
                const float t = turn(hull[i], hull[m], hull[k]);
                if (t > left) left = t, j = m;
            }
            for (std::size_t m = k + 1; m < i + n; ++m) {
                const float t = turn(hull[k], hull[m % n], hull[i]);
                if (t > right) right = t, l = m % n;
            }
            if (!(left > 0.0f) || !(right > 0.0f) || left + right <= best) continue;
            best = left + right;
            chosen = {i, j, k, l};
        }
    if (!(best > 0.0f)) return std::nullopt;

    std::array<glm::vec2, 4> quad;
    for (std::size_t c = 0; c < 4; ++c)
        quad[c] = hull[chosen[c]];
    float twiceArea = 0.0f;
    const glm::vec2 middle = centroid(quad, twiceArea);
    const float scale = std::sqrt(area / (0.5f * twiceArea));
    for (glm::vec2& p : quad)
        p = middle + scale * (p - middle);
    return quad;
}

float coveredArea(std::span<const glm::vec2> corners) {
    if (corners.size() < 3) return 0.0f;
    glm::vec2 low(corners[0]), high(corners[0]);
    for (glm::vec2 p : corners) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    const glm::vec2 cell = (high - low) / float(kSilhouetteGrid);
    if (!(cell.x > 0.0f) || !(cell.y > 0.0f)) return 0.0f;
    std::vector<bool> covered(std::size_t{kSilhouetteGrid} * kSilhouetteGrid, false);
    const auto clampCell = [](float c) { return std::clamp(int(c), 0, int(kSilhouetteGrid) - 1); };
    for (std::size_t t = 0; t + 2 < corners.size(); t += 3) {
        const glm::vec2 a = corners[t], b = corners[t + 1], c = corners[t + 2];
        const float whole = turn(a, b, c);
        if (whole == 0.0f) continue;
        const glm::vec2 from = (glm::min(a, glm::min(b, c)) - low) / cell,
                        to = (glm::max(a, glm::max(b, c)) - low) / cell;
        for (int y = clampCell(from.y); y <= clampCell(to.y); ++y)
            for (int x = clampCell(from.x); x <= clampCell(to.x); ++x) {
                const glm::vec2 p = low + (glm::vec2(x, y) + 0.5f) * cell;
                // Inside: on the same side of all three edges as the triangle turns.
                if (turn(a, b, p) * whole >= 0.0f && turn(b, c, p) * whole >= 0.0f && turn(c, a, p) * whole >= 0.0f)
                    covered[std::size_t(y) * kSilhouetteGrid + std::size_t(x)] = true;
            }
    }
    return float(std::count(covered.begin(), covered.end(), true)) * cell.x * cell.y;
}

} // namespace simeco::draw
