#include "skeleton/dressing.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <glm/geometric.hpp>

#include "skeleton/internodes.h"

namespace simeco::skeleton {

namespace {

constexpr double kDegree = std::numbers::pi / 180.0;
constexpr double kGoldenAngle = 137.50776405 * kDegree;

// A unit vector at right angles to d, turned by `angle` about it from a reference that does not depend on d's
// length (the world's up removed, or x where d is vertical).
glm::dvec3 across(const glm::dvec3& d, double angle) {
    glm::dvec3 ref = std::abs(d.y) < 0.99 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
    glm::dvec3 a = glm::normalize(ref - d * glm::dot(ref, d));
    glm::dvec3 b = glm::cross(d, a);
    return a * std::cos(angle) + b * std::sin(angle);
}

class Dresser {
public:
    Dresser(Plant& plant, const PlantDescription& d) : plant_(plant), d_(d), tree_(internodeTree(plant)) {}

    std::string leaves() {
        if (!plant_.organs.empty() || d_.phyllotaxy == Phyllotaxy::Unsaid) return "";
        // Leaves in proportion to the plant: a herb's large for its height, a tree's small.
        const double share = d_.habit == Habit::Herb ? 0.12 : d_.habit == Habit::Tree ? 0.04 : 0.07;
        size_ = share * plantSize(plant_);
        const size_t before = plant_.organs.size();
        if (d_.phyllotaxy == Phyllotaxy::Basal) {
            const Internode& trunk = tree_.internodes[size_t(tree_.roots.front())];
            const glm::dvec3 d = (trunk.end - trunk.start) / trunk.length;
            for (int k = 0; k < 8; ++k) add(trunk.stem, 0, trunk.start, d, k * kGoldenAngle, 75.0 * kDegree);
        }
        for (const Internode& n : tree_.internodes) {
            const glm::dvec3 d = (n.end - n.start) / n.length;
            const int node = int(n.segment) + 1, point = node;
            switch (d_.phyllotaxy) {
            case Phyllotaxy::Alternate: add(n.stem, point, n.end, d, node * kGoldenAngle, 50.0 * kDegree); break;
            case Phyllotaxy::Opposite:
                for (int k = 0; k < 2; ++k) add(n.stem, point, n.end, d, node * 90.0 * kDegree + k * std::numbers::pi,
                                                50.0 * kDegree);
                break;
            case Phyllotaxy::Whorled:
                for (int k = 0; k < 3; ++k)
                    add(n.stem, point, n.end, d, (node * 60.0 + k * 120.0) * kDegree, 55.0 * kDegree);
                break;
            case Phyllotaxy::Clustered:
                if (n.children.empty())
                    for (int k = 0; k < 5; ++k) add(n.stem, point, n.end, d, k * 72.0 * kDegree, 40.0 * kDegree);
                break;
            default: break;
            }
        }
        return fmt::format("{} {} leaves of {:.3g}", plant_.organs.size() - before, phyllotaxyName(d_.phyllotaxy),
                           size_);
    }

    std::string widths() {
        for (const Stem& s : plant_.stems) {
            if (s.width > 0.0) return "";
            for (double w : s.widths)
                if (w > 0.0) return "";
        }
        // Tips carried by each internode, from the tips down.
        std::vector<double> tips(tree_.internodes.size(), 0.0);
        std::vector<int> order;
        for (int r : tree_.roots) order.push_back(r);
        for (size_t k = 0; k < order.size(); ++k)
            for (int c : tree_.internodes[size_t(order[k])].children) order.push_back(c);
        for (auto it = order.rbegin(); it != order.rend(); ++it) {
            const Internode& n = tree_.internodes[size_t(*it)];
            tips[size_t(*it)] = n.children.empty() ? 1.0 : 0.0;
            for (int c : n.children) tips[size_t(*it)] += tips[size_t(c)];
        }
        double all = 0.0;
        for (int r : tree_.roots) all += tips[size_t(r)];
        const double share = d_.habit == Habit::Herb    ? 0.012
                             : d_.habit == Habit::Shrub ? 0.025
                             : d_.habit == Habit::Tree  ? 0.05
                                                        : 0.02;
        const double base = share * plantSize(plant_);
        for (Stem& s : plant_.stems) s.widths.assign(s.points.size() - 1, 0.0);
        auto stemAt = [&](int id) -> Stem& {
            return *std::find_if(plant_.stems.begin(), plant_.stems.end(), [&](const Stem& s) { return s.id == id; });
        };
        for (size_t i = 0; i < tree_.internodes.size(); ++i) {
            const Internode& n = tree_.internodes[i];
            stemAt(n.stem).widths[n.segment] = base * std::pow(tips[i] / std::max(all, 1.0), 1.0 / 2.5);
        }
        for (Stem& s : plant_.stems) s.width = s.widths.front();
        return fmt::format("widths from {:.3g} at the base (pipe model)", base);
    }

private:
    Plant& plant_;
    const PlantDescription& d_;
    InternodeTree tree_;
    double size_ = 1.0;

    void add(int stem, int point, const glm::dvec3& at, const glm::dvec3& d, double divergence, double angle) {
        Organ o;
        o.kind = OrganKind::Leaf;
        o.stem = stem;
        o.point = point;
        o.position = at;
        o.heading = d * std::cos(angle) + across(d, divergence) * std::sin(angle);
        o.size = size_;
        plant_.organs.push_back(o);
    }
};

} // namespace

std::string dressPlant(Plant& plant, const PlantDescription& description) {
    Dresser dresser(plant, description);
    std::string leaves = dresser.leaves(), widths = dresser.widths();
    if (!leaves.empty() && !widths.empty()) return leaves + "; " + widths;
    return leaves + widths;
}

} // namespace simeco::skeleton
