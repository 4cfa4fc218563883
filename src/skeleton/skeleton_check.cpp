#include "skeleton/skeleton_check.h"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "ir/source_loc.h"

namespace simeco::skeleton {

namespace {

std::string format(const glm::dvec3& p) { return fmt::format("({:.6g}, {:.6g}, {:.6g})", p.x, p.y, p.z); }

double distanceToSegment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
    glm::dvec3 ab = b - a;
    double l2 = glm::dot(ab, ab);
    double along = l2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / l2, 0.0, 1.0) : 0.0;
    return glm::length(a + ab * along - p);
}

class PlantCheck {
public:
    PlantCheck(Plant& plant, const std::string& file, size_t index) : plant_(plant), file_(file), index_(index) {}

    void run() {
        if (plant_.stems.empty()) fail("it has no stems");
        size_ = plantSize(plant_);
        tolerance_ = samePointTolerance(size_);
        for (size_t k = 0; k < plant_.stems.size(); ++k) {
            const Stem& s = plant_.stems[k];
            if (!byId_.emplace(s.id, k).second) fail(fmt::format("stem id {} is used twice", s.id));
            checkPoints(s);
        }
        for (const Stem& s : plant_.stems) checkParent(s);
        for (const Stem& s : plant_.stems) checkNoLoop(s);
        for (size_t k = 0; k < plant_.stems.size(); ++k) attach(k);
        checkBase();
        for (size_t k = 0; k < plant_.organs.size(); ++k) checkOrgan(plant_.organs[k], k);
    }

private:
    Plant& plant_;
    const std::string& file_;
    size_t index_;
    double size_ = 0.0, tolerance_ = 0.0;
    std::map<int, size_t> byId_;

    [[noreturn]] void fail(const std::string& message) const {
        throw ir::InputError({file_, 0, 0}, fmt::format("plant {}: {}", index_, message));
    }

    Stem& stem(int id) { return plant_.stems[byId_.at(id)]; }

    void checkPoints(const Stem& s) {
        if (s.points.size() < 2) fail(fmt::format("stem {} has {} point{}: a stem needs two or more", s.id,
                                                  s.points.size(), s.points.size() == 1 ? "" : "s"));
        for (size_t k = 0; k < s.points.size(); ++k) {
            const glm::dvec3& p = s.points[k];
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
                fail(fmt::format("point {} of stem {} is not a finite number", k, s.id));
        }
        for (size_t k = 0; k + 1 < s.points.size(); ++k)
            if (glm::length(s.points[k + 1] - s.points[k]) <= 1e-9 * std::max(size_, 1e-30))
                fail(fmt::format("points {} and {} of stem {} coincide at {}: a stem segment needs a length", k, k + 1,
                                 s.id, format(s.points[k])));
        for (double w : s.widths)
            if (w < 0.0) fail(fmt::format("stem {} has a negative width", s.id));
    }

    void checkParent(const Stem& s) {
        if (s.parent == -1) return;
        if (s.parent == s.id) fail(fmt::format("stem {} is its own parent", s.id));
        if (!byId_.count(s.parent)) fail(fmt::format("stem {} names parent {}, which is not a stem", s.id, s.parent));
    }

    void checkNoLoop(const Stem& s) {
        std::string path = std::to_string(s.id);
        int at = s.parent;
        for (size_t hops = 0; at != -1; ++hops) {
            path += fmt::format(" -> {}", at);
            if (at == s.id || hops > plant_.stems.size())
                fail(fmt::format("the parents of stem {} loop back to it ({}): a plant is a tree", s.id, path));
            at = stem(at).parent;
        }
    }

    // Finds (or checks) the parent's point the stem's base is.
    void attach(size_t k) {
        Stem& s = plant_.stems[k];
        if (s.parent == -1) return;
        Stem& parent = stem(s.parent);
        const glm::dvec3 base = s.points.front();
        if (s.attach >= 0) {
            if (size_t(s.attach) >= parent.points.size())
                fail(fmt::format("stem {} attaches at point {} of stem {}, which has {} points", s.id, s.attach,
                                 parent.id, parent.points.size()));
            double gap = glm::length(parent.points[size_t(s.attach)] - base);
            if (gap > tolerance_)
                fail(fmt::format("stem {} starts at {}, {:.3g} away from point {} of its parent {}: it does not "
                                 "start on its parent",
                                 s.id, format(base), gap, s.attach, parent.id));
            return;
        }
        size_t nearest = 0;
        for (size_t j = 1; j < parent.points.size(); ++j)
            if (glm::length(parent.points[j] - base) < glm::length(parent.points[nearest] - base)) nearest = j;
        if (glm::length(parent.points[nearest] - base) <= tolerance_) {
            s.attach = int(nearest);
            return;
        }
        double best = 1e300;
        size_t segment = 0;
        for (size_t j = 0; j + 1 < parent.points.size(); ++j) {
            double d = distanceToSegment(base, parent.points[j], parent.points[j + 1]);
            if (d < best) {
                best = d;
                segment = j;
            }
        }
        if (best > tolerance_)
            fail(fmt::format("stem {} starts at {}, {:.3g} away from its parent {}: it does not start on its parent",
                             s.id, format(base), best, parent.id));
        insertPoint(parent, segment + 1, base);
        s.attach = int(segment + 1);
    }

    // A point inserted into `parent` at `at`: the stems and organs on later points move up by one.
    void insertPoint(Stem& parent, size_t at, const glm::dvec3& p) {
        parent.points.insert(parent.points.begin() + long(at), p);
        if (!parent.widths.empty()) parent.widths.insert(parent.widths.begin() + long(at - 1), parent.widths[at - 1]);
        for (Stem& other : plant_.stems)
            if (other.parent == parent.id && other.attach >= int(at)) ++other.attach;
        for (Organ& o : plant_.organs)
            if (o.stem == parent.id && o.point >= int(at)) ++o.point;
    }

    void checkBase() {
        const Stem* first = nullptr;
        for (const Stem& s : plant_.stems) {
            if (s.parent != -1) continue;
            if (!first) {
                first = &s;
                continue;
            }
            double gap = glm::length(s.points.front() - first->points.front());
            if (gap > tolerance_)
                fail(fmt::format("stem {} has no parent and starts at {}, {:.3g} away from the plant's base (stem "
                                 "{}'s): the stems are not connected into one plant",
                                 s.id, format(s.points.front()), gap, first->id));
        }
        if (!first) fail("every stem has a parent: none stands on the plant's base");
    }

    void checkOrgan(const Organ& o, size_t k) {
        if (!byId_.count(o.stem)) fail(fmt::format("organ {} sits on stem {}, which is not a stem", k, o.stem));
        const Stem& s = stem(o.stem);
        if (o.point < 0 || size_t(o.point) >= s.points.size())
            fail(fmt::format("organ {} sits on point {} of stem {}, which has {} points", k, o.point, s.id,
                             s.points.size()));
    }
};

} // namespace

void checkPlant(Plant& plant, const std::string& file, size_t index) { PlantCheck(plant, file, index).run(); }

void checkSkeleton(Skeleton& skeleton, const std::string& file) {
    if (skeleton.plants.empty()) throw ir::InputError({file, 0, 0}, "the skeleton has no plants");
    for (size_t p = 0; p < skeleton.plants.size(); ++p) checkPlant(skeleton.plants[p], file, p);
}

} // namespace simeco::skeleton
