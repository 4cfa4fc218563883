#include "skeleton/stem_parents.h"

#include <algorithm>
#include <limits>

#include <glm/geometric.hpp>

namespace simeco::skeleton {

namespace {

double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    glm::dvec3 ab = b - a;
    double l2 = glm::dot(ab, ab);
    double along = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::length(a + ab * along - p);
}

double distanceToPolyline(const glm::dvec3& p, const std::vector<glm::dvec3>& line) {
    if (line.size() == 1) return glm::length(line.front() - p);
    double best = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k + 1 < line.size(); ++k)
        best = std::min(best, distanceToSegment(p, line[k], line[k + 1]));
    return best;
}

// Where a stem touches the stems of one level: the nearest of them, and whether it is the stem's tip that touches.
struct Touch {
    double distance = std::numeric_limits<double>::infinity();
    size_t parent = 0;
    bool atTip = false;
};

Touch nearestTouch(const Plant& plant, const Stem& s, const std::vector<size_t>& level, StemDirection direction) {
    Touch best;
    for (size_t p : level) {
        const std::vector<glm::dvec3>& line = plant.stems[p].points;
        double base = distanceToPolyline(s.points.front(), line);
        // Strictly nearer only: on a tie the earlier stem of the level, and the stem's own first point, win.
        if (base < best.distance) best = {base, p, false};
        if (direction == StemDirection::BaseFirst) continue;
        double tip = distanceToPolyline(s.points.back(), line);
        if (tip < best.distance) best = {tip, p, true};
    }
    return best;
}

// Its points (and per-segment widths) from the other end.
void turnAround(Stem& s) {
    std::reverse(s.points.begin(), s.points.end());
    std::reverse(s.widths.begin(), s.widths.end());
}

} // namespace

void linkStemsByGeometry(Plant& plant, double tolerance, StemDirection direction) {
    std::vector<Stem>& stems = plant.stems;
    size_t root = stems.size();
    bool rootAtTip = false;
    double lowest = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < stems.size(); ++k) {
        stems[k].parent = -1;
        if (stems[k].points.empty()) continue; // checkPlant refuses it
        if (stems[k].points.front().y < lowest) {
            lowest = stems[k].points.front().y;
            root = k;
            rootAtTip = false;
        }
        if (direction == StemDirection::Unknown && stems[k].points.back().y < lowest) {
            lowest = stems[k].points.back().y;
            root = k;
            rootAtTip = true;
        }
    }
    if (root == stems.size()) return;
    if (rootAtTip) turnAround(stems[root]);

    std::vector<bool> placed(stems.size(), false);
    placed[root] = true;
    std::vector<size_t> level{root};
    while (!level.empty()) {
        std::vector<size_t> next;
        for (size_t k = 0; k < stems.size(); ++k) {
            if (placed[k] || stems[k].points.empty()) continue;
            Touch touch = nearestTouch(plant, stems[k], level, direction);
            if (touch.distance > tolerance) continue;
            stems[k].parent = stems[touch.parent].id;
            if (touch.atTip) turnAround(stems[k]);
            next.push_back(k);
        }
        // Placed only once the whole level is done, so that stems of one level never become each other's parents.
        for (size_t k : next)
            placed[k] = true;
        level = std::move(next);
    }
}

} // namespace simeco::skeleton
