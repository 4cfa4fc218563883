#include "skeleton/infer.h"

#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "turtle/frame.h"

namespace simeco::skeleton {

namespace {

// Where the turtle stands and which way it faces, in the plant's own space, as it computes them.
struct Place {
    turtle::Frame frame;
    glm::vec3 position{0.0f};
};

class Regrower {
public:
    Regrower(const Plant& plant, Dialect dialect) : plant_(plant) {
        out_.tree = internodeTree(plant);
        out_.dialect = dialect;
        out_.internodes.resize(out_.tree.internodes.size());
    }

    Regrowth run() {
        const Place base;
        for (int r : out_.tree.roots) out_.roots.push_back({r, aimAt(base, target(r))});
        for (int k : out_.tree.baseOrgans) out_.baseOrgans.push_back({k, aimAlong(base, heading(k))});
        // Depth first with a stack of its own: a skeleton may be thousands of internodes deep.
        std::vector<std::pair<int, Place>> pending;
        for (size_t k = out_.roots.size(); k-- > 0;)
            pending.push_back({out_.roots[k].internode, turned(base, out_.roots[k].turn, k > 0)});
        bool trunk = true;
        while (!pending.empty()) {
            auto [i, place] = pending.back();
            pending.pop_back();
            grow(i, place, trunk);
            trunk = false;
            const GrownInternode& g = out_.internodes[size_t(i)];
            for (size_t k = g.children.size(); k-- > 0;)
                pending.push_back({g.children[k].internode, turned(place, g.children[k].turn, k > 0)});
        }
        return std::move(out_);
    }

private:
    const Plant& plant_;
    Regrowth out_;

    float radians(float angle) const {
        return out_.dialect == Dialect::Cpfg ? angle * turtle::kRadiansPerDegree : angle;
    }

    // The skeleton point internode i ends at, in the plant's own space (its base at the origin).
    glm::dvec3 target(int i) const { return out_.tree.internodes[size_t(i)].end - out_.tree.base; }
    glm::dvec3 heading(int organ) const { return plant_.organs[size_t(organ)].heading; }

    // The turn from `from`'s frame toward the point `to`, or along `direction`.
    Turn aimAt(const Place& from, const glm::dvec3& to) const { return aimAlong(from, to - glm::dvec3(from.position)); }

    Turn aimAlong(const Place& from, const glm::dvec3& direction) const {
        const turtle::Frame& f = from.frame;
        const glm::dvec3 u = glm::normalize(direction);
        const double along = glm::dot(u, glm::dvec3(f.heading));
        const double up = glm::dot(u, glm::dvec3(f.up)), left = glm::dot(u, glm::dvec3(f.left));
        const double across = std::hypot(up, left);
        const double pitch = std::atan2(across, along);
        const double roll = across > 1e-12 ? std::atan2(-left, -up) : 0.0;
        const double unit = out_.dialect == Dialect::Cpfg ? 180.0 / std::numbers::pi : 1.0;
        return {float(pitch * unit), float(roll * unit)};
    }

    // The frame after a turn, as the turtle turns it: roll, then pitch; a SimEco branch then rolls a quarter turn
    // back, `/(-90)`, to take its parent's direction as its reference axis.
    Place turned(Place p, const Turn& t, bool branch) const {
        turtle::turnToward(p.frame.up, p.frame.left, radians(t.roll));
        turtle::turnToward(p.frame.heading, p.frame.up, -radians(t.pitch));
        if (branch && out_.dialect == Dialect::SimEco)
            turtle::turnToward(p.frame.up, p.frame.left, -90.0f * turtle::kRadiansPerDegree);
        return p;
    }

    // Internode i drawn from `place`, its turtle at its end; its children's and organs' turns from there.
    void grow(int i, Place& place, bool trunk) {
        const Internode& n = out_.tree.internodes[size_t(i)];
        GrownInternode& g = out_.internodes[size_t(i)];
        g.length = float(glm::length(target(i) - glm::dvec3(place.position)));
        g.width = float(n.width);
        place.position += place.frame.heading * g.length;
        if (trunk && !n.children.empty()) {
            g.rollAfter = aimAt(place, target(n.children.front())).roll;
            turtle::turnToward(place.frame.up, place.frame.left, radians(g.rollAfter));
        }
        for (int c : n.children) g.children.push_back({c, aimAt(place, target(c))});
        for (int k : n.organs) g.organs.push_back({k, aimAlong(place, heading(k))});
    }
};

} // namespace

Regrowth regrowth(const Plant& plant, Dialect dialect) { return Regrower(plant, dialect).run(); }

} // namespace simeco::skeleton
