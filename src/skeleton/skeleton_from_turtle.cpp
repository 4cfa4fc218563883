#include "skeleton/skeleton_from_turtle.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "compute/shared/organ_layout.h"
#include "ir/grammar.h"

namespace simeco::skeleton {

namespace {

glm::dvec3 xyz(const shared::vec4& v) { return {v.x, v.y, v.z}; }

// Where the turtle stands in the skeleton: on point `point` of stem `stem` (-1: before any stem), and whether the
// next segment starts a stem of its own (the first one in a bracket).
struct Cursor {
    int stem = -1;
    int point = -1;
    bool lateral = false;
};

class SkeletonWalk {
public:
    SkeletonWalk(const std::vector<shared::OrganInstance>& organs, double size)
        : organs_(organs), tolerance_(1e-6 * (size > 0.0 ? size : 1.0)) {}

    void enter() {
        stack_.push_back(cursor_);
        cursor_.lateral = true;
    }
    void leave() {
        if (stack_.empty()) return;
        cursor_ = stack_.back();
        stack_.pop_back();
    }

    void organ(const shared::OrganInstance& o) {
        if (o.kind == shared::kOrganStem) segment(o);
        else if (o.kind == shared::kOrganLeaf || o.kind == shared::kOrganSphere || o.kind == shared::kOrganDisc)
            sits(o);
    }

    Plant finish() {
        joinStraightOn();
        renumber();
        for (Stem& s : plant_.stems) {
            bool same = true;
            for (double w : s.widths) same = same && std::abs(w - s.widths.front()) <= 1e-6 * std::abs(w);
            if (same) s.widths.clear();
        }
        return std::move(plant_);
    }

private:
    const std::vector<shared::OrganInstance>& organs_;
    double tolerance_;
    Plant plant_;
    Cursor cursor_;
    std::vector<Cursor> stack_;
    std::set<std::pair<int, int>> occupied_; // points a branch or an organ sits on

    void segment(const shared::OrganInstance& o) {
        const double length = o.position.w;
        if (!(length > tolerance_ * 1e-3)) return; // draws nothing
        const glm::dvec3 start = xyz(o.position), end = start + xyz(o.heading) * length;
        // A pixel line's radius is in pixels of the picture, not in the plant's units: its width is not known.
        const double width = o.shape == shared::kLinePixel ? 0.0 : 2.0 * double(o.heading.w);
        Stem* at = cursor_.stem >= 0 ? &plant_.stems[size_t(cursor_.stem)] : nullptr;
        const bool connected = at && glm::length(at->points[size_t(cursor_.point)] - start) <= tolerance_;
        int index = 0;
        if (connected && !cursor_.lateral) {
            extend(*at, end, width);
            index = at->id;
        } else {
            Stem s;
            s.id = index = int(plant_.stems.size());
            if (connected) {
                s.parent = at->id;
                s.attach = cursor_.point;
                occupied_.insert({at->id, cursor_.point});
            }
            s.points = {start, end};
            s.width = width;
            s.widths = {width};
            plant_.stems.push_back(std::move(s)); // `at` is no longer valid
        }
        cursor_ = {index, int(plant_.stems[size_t(index)].points.size()) - 1, false};
    }

    // A branch that is all that grows from its parent's tip, straight on at the same width and with nothing else
    // on that point, continues its parent: the point is not a node of the plant. (A bracket's first segment starts
    // a stem before the turtle knows whether the parent goes on.) One pass in stem order, parents before their
    // branches, each stem taking over such branches for as long as its new tip has one.
    void joinStraightOn() {
        std::vector<std::vector<int>> branches(plant_.stems.size());
        for (const Stem& l : plant_.stems)
            if (l.parent >= 0) branches[size_t(l.parent)].push_back(l.id);
        std::set<std::pair<int, int>> organPoints;
        for (const Organ& o : plant_.organs) organPoints.insert({o.stem, o.point});
        auto branchesAt = [&](int stem, int point) {
            int count = 0, only = -1;
            for (int b : branches[size_t(stem)])
                if (plant_.stems[size_t(b)].attach == point) {
                    ++count;
                    only = b;
                }
            return std::pair{count, only};
        };
        for (Stem& s : plant_.stems) {
            while (!s.points.empty()) {
                const int tip = int(s.points.size()) - 1;
                const auto [count, only] = branchesAt(s.id, tip);
                if (count != 1 || organPoints.count({s.id, tip}) || organPoints.count({only, 0}) ||
                    branchesAt(only, 0).first > 0)
                    break;
                Stem& l = plant_.stems[size_t(only)];
                const glm::dvec3 last = glm::normalize(s.points[size_t(tip)] - s.points[size_t(tip) - 1]);
                const glm::dvec3 next = glm::normalize(l.points[1] - l.points[0]);
                const bool straight = glm::dot(last, next) > 0.0 && glm::length(glm::cross(last, next)) < 1e-5;
                if (!straight || std::abs(s.widths.back() - l.widths.front()) > 1e-6 * s.widths.back()) break;
                join(s, l, branches, organPoints);
            }
        }
    }

    // `s` takes over `l`: l's points after its base follow s's tip in its place, and what sits on them moves too.
    void join(Stem& s, Stem& l, std::vector<std::vector<int>>& branches,
              std::set<std::pair<int, int>>& organPoints) {
        const int shift = int(s.points.size()) - 2; // l's point j is s's point j + shift
        s.points.pop_back();
        s.widths.pop_back();
        s.points.insert(s.points.end(), l.points.begin() + 1, l.points.end());
        s.widths.insert(s.widths.end(), l.widths.begin(), l.widths.end());
        std::vector<int>& own = branches[size_t(s.id)];
        own.erase(std::find(own.begin(), own.end(), l.id));
        for (int b : branches[size_t(l.id)]) {
            plant_.stems[size_t(b)].parent = s.id;
            plant_.stems[size_t(b)].attach += shift;
            own.push_back(b);
        }
        branches[size_t(l.id)].clear();
        for (Organ& o : plant_.organs)
            if (o.stem == l.id) {
                organPoints.erase({o.stem, o.point});
                o.stem = s.id;
                o.point += shift;
                organPoints.insert({o.stem, o.point});
            }
        l.points.clear();
        l.parent = -2; // joined
    }

    // Stems joined into others are dropped and the rest numbered from 0 again.
    void renumber() {
        std::vector<int> id(plant_.stems.size(), -1);
        std::vector<Stem> kept;
        for (const Stem& s : plant_.stems)
            if (!s.points.empty()) {
                id[size_t(s.id)] = int(kept.size());
                kept.push_back(s);
            }
        for (Stem& s : kept) {
            s.id = id[size_t(s.id)];
            if (s.parent >= 0) s.parent = id[size_t(s.parent)];
        }
        for (Organ& o : plant_.organs) o.stem = id[size_t(o.stem)];
        plant_.stems = std::move(kept);
    }

    // The segment continues the stem from its tip: straight on, at its width, and with nothing on the tip, the
    // tip moves; else the segment adds a point.
    void extend(Stem& s, const glm::dvec3& end, double width) {
        const size_t tip = s.points.size() - 1;
        const glm::dvec3 last = glm::normalize(s.points[tip] - s.points[tip - 1]);
        const glm::dvec3 next = glm::normalize(end - s.points[tip]);
        const bool straight = glm::dot(last, next) > 0.0 && glm::length(glm::cross(last, next)) < 1e-5;
        const bool sameWidth = std::abs(width - s.widths.back()) <= 1e-6 * std::max(width, 1e-30);
        if (straight && sameWidth && !occupied_.count({s.id, int(tip)})) {
            s.points[tip] = end;
        } else {
            s.points.push_back(end);
            s.widths.push_back(width);
        }
    }

    void sits(const shared::OrganInstance& o) {
        if (cursor_.stem < 0) return; // nothing to sit on yet
        Organ organ;
        organ.stem = cursor_.stem;
        organ.point = cursor_.point;
        organ.position = xyz(o.position);
        organ.heading = xyz(o.heading);
        if (o.kind == shared::kOrganLeaf) {
            const bool blossom = o.shape > shared::kLeafLastShape && o.shape <= shared::kSurfaceLastShape;
            organ.kind = blossom ? OrganKind::Flower : OrganKind::Leaf;
            organ.size = o.position.w;
        } else {
            organ.kind = o.kind == shared::kOrganSphere ? OrganKind::Fruit : OrganKind::Flower;
            organ.size = 2.0 * double(o.heading.w);
        }
        occupied_.insert({organ.stem, organ.point});
        plant_.organs.push_back(organ);
    }
};

} // namespace

Plant plantFromTurtle(const stream::ModuleString& string, const turtle::Interpretation& interpretation,
                      uint32_t plant) {
    const size_t begin = string.plantStart[plant], end = string.plantStart[plant + 1];
    std::unordered_map<uint32_t, std::vector<size_t>> byModule;
    glm::dvec3 lo(1e300), hi(-1e300);
    for (size_t k = 0; k < interpretation.organs.size(); ++k) {
        const shared::OrganInstance& o = interpretation.organs[k];
        if (o.plant != plant) continue;
        byModule[o.module].push_back(k);
        if (o.kind == shared::kOrganStem) {
            glm::dvec3 a = xyz(o.position), b = a + xyz(o.heading) * double(o.position.w);
            lo = glm::min(lo, glm::min(a, b));
            hi = glm::max(hi, glm::max(a, b));
        }
    }
    // Organs of one kind are in module order, and a module's several stem segments (a tube) in drawing order.
    for (auto& [module, list] : byModule)
        std::stable_sort(list.begin(), list.end(), [&](size_t a, size_t b) {
            return interpretation.organs[a].kind < interpretation.organs[b].kind;
        });
    SkeletonWalk walk(interpretation.organs, hi.x >= lo.x ? glm::length(hi - lo) : 0.0);
    for (size_t i = begin; i < end; ++i) {
        if (string.sym[i] == ir::kBranchOpen) walk.enter();
        else if (string.sym[i] == ir::kBranchClose) walk.leave();
        auto found = byModule.find(uint32_t(i));
        if (found == byModule.end()) continue;
        for (size_t k : found->second) walk.organ(interpretation.organs[k]);
    }
    return walk.finish();
}

} // namespace simeco::skeleton
