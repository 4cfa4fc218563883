// Combining three views of a stem into 3D. Each pair of views shares one world axis (front and side: y, front and
// top: x, side and top: z). Where a stem's three polylines have as many points, point k of each is the same 3D
// point, as in the thesis, where the user picks matching points in the same order: each coordinate is the mean of
// the two views that show it.
//
// Where the counts differ, one view leads: its points become the stem's, with the two coordinates it shows as
// drawn, and the third comes from the two other views. The leading view is the one in which the stem is longest
// (then the one with more points; then front, side, top): it sees the stem least end-on, and where the leading
// view sees a stem end-on its points cannot say where along the stem they lie. Each other view shares one axis
// with the leading view, and the place along it that matches a leading point is where the normalized running
// total of |change| of that shared coordinate (0 at the base, 1 at the tip) is the same. Both views see that
// coordinate as the same function along the stem, so this parameter agrees between them however each view samples
// the stem, also where the coordinate turns back (a bent branch's x), where the coordinate's own value would not,
// and unlike the views' arc lengths it is not shortened by foreshortening. Where the shared coordinate hardly
// changes near a leading point (a trunk's x seen from the front), the parameter does not locate the point, so the
// two estimates of the third coordinate are weighted by how much each shared coordinate changes over the leading
// point's neighbouring segments. A view that misses a turning point of a shared coordinate (a coarse polyline cut
// across a bend) puts the parameter off along the rest of the stem, so draw each view through the stem's bends.
#include "skeleton/three_views.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "skeleton/json_reader.h"
#include "skeleton/stem_parents.h"

namespace simeco::skeleton {

namespace {

enum Axis { X = 0, Y = 1, Z = 2 };

const char* axisName(Axis a) {
    return a == X ? "x" : a == Y ? "y" : "z";
}

// A stem's polyline in one view, and the world axes of its (u, v).
struct Drawn {
    const ViewStem* stem = nullptr;
    Axis u = X, v = Y;
    const char* view = "";

    size_t size() const { return stem->points.size(); }
    bool shows(Axis a) const { return a == u || a == v; }
    double at(size_t k, Axis a) const { return a == u ? stem->points[k].x : stem->points[k].y; }
};

[[noreturn]] void fail(const ViewStem& s, const std::string& file, const std::string& message) {
    throw ir::InputError({file, s.where.line, s.where.col}, message);
}

std::vector<glm::dvec3> pairedByIndex(const std::array<Drawn, 3>& views) {
    const Drawn &front = views[0], &side = views[1], &top = views[2];
    std::vector<glm::dvec3> points;
    for (size_t k = 0; k < front.size(); ++k)
        points.push_back({(front.at(k, X) + top.at(k, X)) / 2.0, (front.at(k, Y) + side.at(k, Y)) / 2.0,
                          (side.at(k, Z) + top.at(k, Z)) / 2.0});
    return points;
}

// The normalized running total of |change| of coordinate `a` along the polyline (the normalized arc length where
// the coordinate does not change at all; all 0 for a polyline that is one point).
std::vector<double> runningChange(const Drawn& d, Axis a) {
    std::vector<double> tau(d.size(), 0.0);
    for (size_t k = 1; k < d.size(); ++k)
        tau[k] = tau[k - 1] + std::abs(d.at(k, a) - d.at(k - 1, a));
    if (tau.back() <= 0.0)
        for (size_t k = 1; k < d.size(); ++k)
            tau[k] = tau[k - 1] + glm::length(d.stem->points[k] - d.stem->points[k - 1]);
    if (tau.back() > 0.0)
        for (double& t : tau)
            t /= tau.back();
    return tau;
}

// Which of the positions where `tau` stays at a value to take: the first where a leading point begins a stretch
// over which the shared coordinate does not change, the last where it ends one, else the middle.
enum class Pick { First, Last, Middle };

// The position (a point index with its fraction) along non-decreasing `tau` where it reaches `target`.
double positionOf(const std::vector<double>& tau, double target, Pick pick) {
    size_t n = tau.size();
    double first = double(n - 1), last = 0.0;
    for (size_t k = 0; k < n; ++k)
        if (tau[k] >= target) {
            first = k == 0 ? 0.0 : double(k - 1) + (target - tau[k - 1]) / (tau[k] - tau[k - 1]);
            break;
        }
    for (size_t k = n; k-- > 0;)
        if (tau[k] <= target) {
            last = k + 1 == n ? double(k) : double(k) + (target - tau[k]) / (tau[k + 1] - tau[k]);
            break;
        }
    if (pick == Pick::First) return first;
    if (pick == Pick::Last) return last;
    return (first + last) / 2.0;
}

double valueAt(const Drawn& d, Axis a, double position) {
    size_t k = size_t(position);
    if (k + 1 >= d.size()) return d.at(d.size() - 1, a);
    double f = position - double(k);
    return d.at(k, a) * (1.0 - f) + d.at(k + 1, a) * f;
}

std::vector<glm::dvec3> resampled(const std::array<Drawn, 3>& views) {
    std::array<double, 3> lengths{};
    size_t leadIndex = 0;
    for (size_t v = 0; v < 3; ++v) {
        const std::vector<glm::dvec2>& p = views[v].stem->points;
        for (size_t k = 1; k < p.size(); ++k)
            lengths[v] += glm::length(p[k] - p[k - 1]);
        bool longer = lengths[v] > lengths[leadIndex] * (1.0 + 1e-9);
        bool asLong = lengths[v] >= lengths[leadIndex] * (1.0 - 1e-9);
        if (longer || (asLong && views[v].size() > views[leadIndex].size())) leadIndex = v;
    }
    const Drawn& lead = views[leadIndex];
    const Axis missing = Axis(3 - lead.u - lead.v);
    const double still = 1e-12 * lengths[leadIndex]; // a change of the shared coordinate this small is none

    struct Other {
        const Drawn* view;
        Axis shared;
        std::vector<double> leadTau, tau;
    };
    std::vector<Other> others;
    for (size_t k = 0; k < 3; ++k) {
        if (k == leadIndex) continue;
        Axis shared = views[k].shows(lead.u) ? lead.u : lead.v;
        others.push_back({&views[k], shared, runningChange(lead, shared), runningChange(views[k], shared)});
    }

    std::vector<glm::dvec3> points;
    const size_t n = lead.size();
    for (size_t k = 0; k < n; ++k) {
        glm::dvec3 p(0.0);
        p[lead.u] = lead.at(k, lead.u);
        p[lead.v] = lead.at(k, lead.v);
        double weighted = 0.0, weights = 0.0, plain = 0.0;
        for (const Other& o : others) {
            double before = k > 0 ? std::abs(lead.at(k, o.shared) - lead.at(k - 1, o.shared)) : 0.0;
            double after = k + 1 < n ? std::abs(lead.at(k + 1, o.shared) - lead.at(k, o.shared)) : 0.0;
            Pick pick = Pick::Middle;
            if (k == 0)
                pick = Pick::First;
            else if (k + 1 == n)
                pick = Pick::Last;
            else if (after <= still && before > still)
                pick = Pick::First;
            else if (before <= still && after > still)
                pick = Pick::Last;
            double c = valueAt(*o.view, missing, positionOf(o.tau, o.leadTau[k], pick));
            weighted += (before + after) * c;
            weights += before + after;
            plain += c;
        }
        p[missing] = weights > 0.0 ? weighted / weights : plain / double(others.size());
        points.push_back(p);
    }
    return points;
}

// Refuses views that disagree on a shared coordinate of the stem's base or tip by more than `limit`.
void checkAgreement(const std::array<Drawn, 3>& views, double limit, const std::string& file) {
    for (size_t a = 0; a < 3; ++a)
        for (size_t b = a + 1; b < 3; ++b) {
            Axis shared = views[b].shows(views[a].u) ? views[a].u : views[a].v;
            for (bool tip : {false, true}) {
                double va = views[a].at(tip ? views[a].size() - 1 : 0, shared);
                double vb = views[b].at(tip ? views[b].size() - 1 : 0, shared);
                if (std::abs(va - vb) <= limit) continue;
                fail(*views[b].stem, file,
                     fmt::format("stem {}: its {} is at {} = {:.6g} in the {} view but at {} = {:.6g} in the {} view: "
                                 "the views disagree (is a polyline drawn from tip to base, or are the views drawn "
                                 "with different origins?)",
                                 views[a].stem->id, tip ? "tip" : "base", axisName(shared), va, views[a].view,
                                 axisName(shared), vb, views[b].view));
            }
        }
}

glm::dvec3 nearestOnPolyline(const glm::dvec3& p, const std::vector<glm::dvec3>& line) {
    glm::dvec3 best = line.front();
    for (size_t k = 0; k + 1 < line.size(); ++k) {
        glm::dvec3 ab = line[k + 1] - line[k];
        double l2 = glm::dot(ab, ab);
        double along = l2 > 0.0 ? std::clamp(glm::dot(p - line[k], ab) / l2, 0.0, 1.0) : 0.0;
        glm::dvec3 q = line[k] + ab * along;
        if (glm::length(q - p) < glm::length(best - p)) best = q;
    }
    return best;
}

// Moves each stem's base within `reach` onto its parent, and each parentless stem's within `reach` onto the first
// one's (the plant's base), parents before their children so that a child meets its parent where it ends up.
void snapBases(Plant& plant, double reach) {
    std::vector<Stem>& stems = plant.stems;
    std::map<int, size_t> byId;
    for (size_t k = 0; k < stems.size(); ++k)
        byId.emplace(stems[k].id, k);
    std::vector<size_t> order;
    std::vector<bool> queued(stems.size(), false);
    for (size_t k = 0; k < stems.size(); ++k)
        if (stems[k].parent == -1) {
            order.push_back(k);
            queued[k] = true;
        }
    if (order.empty()) return;
    for (size_t next = 0; next < order.size(); ++next)
        for (size_t k = 0; k < stems.size(); ++k)
            if (!queued[k] && stems[k].parent == stems[order[next]].id) {
                order.push_back(k);
                queued[k] = true;
            }
    const glm::dvec3 ground = stems[order.front()].points.front();
    for (size_t k : order) {
        glm::dvec3& base = stems[k].points.front();
        glm::dvec3 onto =
            stems[k].parent == -1 ? ground : nearestOnPolyline(base, stems[byId.at(stems[k].parent)].points);
        if (glm::length(onto - base) <= reach) base = onto;
    }
}

std::map<int, const ViewStem*> stemsById(const View& view, const char* name, const std::string& file) {
    std::map<int, const ViewStem*> out;
    for (const ViewStem& s : view.stems) {
        if (s.points.empty()) fail(s, file, fmt::format("stem {} has no points in the {} view", s.id, name));
        if (!out.emplace(s.id, &s).second)
            fail(s, file, fmt::format("stem {} is drawn twice in the {} view", s.id, name));
    }
    return out;
}

const ViewStem& counterpart(const ViewStem& front, const std::map<int, const ViewStem*>& view, const char* name,
                            const std::string& file) {
    auto found = view.find(front.id);
    if (found == view.end())
        fail(front, file,
             fmt::format("stem {} is in the front view but not in the {} view: each stem is drawn in "
                         "all three views",
                         front.id, name));
    return *found->second;
}

} // namespace

ThreeViews projectThreeViews(const Plant& plant) {
    ThreeViews views;
    for (const Stem& s : plant.stems) {
        ViewStem front{s.id, s.parent, s.width, {}, {}};
        ViewStem side = front, top = front;
        for (const glm::dvec3& p : s.points) {
            front.points.push_back({p.x, p.y});
            side.points.push_back({p.z, p.y});
            top.points.push_back({p.x, -p.z}); // seen from above, the front at the bottom
        }
        views.front.stems.push_back(std::move(front));
        views.side.stems.push_back(std::move(side));
        views.top.stems.push_back(std::move(top));
    }
    return views;
}

Plant plantFromThreeViews(const ThreeViews& drawnViews, const std::string& file) {
    // The top view's v is -z (the plant seen from above with its front at the bottom, as a drawing's top view is
    // laid out): from here on the top view is (x, z).
    ThreeViews views = drawnViews;
    for (ViewStem& t : views.top.stems)
        for (glm::dvec2& p : t.points) p.y = -p.y;
    auto front = stemsById(views.front, "front", file);
    auto side = stemsById(views.side, "side", file);
    auto top = stemsById(views.top, "top", file);
    for (const auto* other : {&side, &top})
        for (const auto& [id, s] : *other)
            if (!front.count(id))
                fail(*s, file,
                     fmt::format("stem {} is in the {} view but not in the front view", id,
                                 other == &side ? "side" : "top"));

    Plant plant;
    std::vector<std::array<Drawn, 3>> drawn;
    bool parentsGiven = false;
    for (const ViewStem& f : views.front.stems) {
        std::array<Drawn, 3> d{{{&f, X, Y, "front"},
                                {&counterpart(f, side, "side", file), Z, Y, "side"},
                                {&counterpart(f, top, "top", file), X, Z, "top"}}};
        Stem s;
        s.id = f.id;
        s.parent = f.parent.value_or(-1);
        s.width = f.width;
        bool sameCount = d[1].size() == d[0].size() && d[2].size() == d[0].size();
        s.points = sameCount ? pairedByIndex(d) : resampled(d);
        parentsGiven = parentsGiven || f.parent.has_value();
        plant.stems.push_back(std::move(s));
        drawn.push_back(d);
    }
    const double size = plantSize(plant);
    for (const std::array<Drawn, 3>& d : drawn)
        checkAgreement(d, kDisagreementFraction * size, file);
    if (!parentsGiven) linkStemsByGeometry(plant, kSnapFraction * size, StemDirection::BaseFirst);
    snapBases(plant, kSnapFraction * size);
    return plant;
}

Skeleton readThreeViews(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    if (extension != ".json" && extension != ".svg")
        throw ir::InputError({path, 0, 0}, "three views are read from a .json or an .svg file");
    const std::string text = readWholeFile(path, "file of three views");
    return extension == ".json" ? parseThreeViewsJson(text, path) : parseThreeViewsSvg(text, path);
}

} // namespace simeco::skeleton
