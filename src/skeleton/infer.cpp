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
    Regrower(const Plant& plant, AngleUnit unit) : plant_(plant) {
        out_.tree = internodeTree(plant);
        out_.unit = unit;
        out_.internodes.resize(out_.tree.internodes.size());
    }

    Regrowth run() {
        const Place base;
        for (int r : out_.tree.roots) out_.roots.push_back({r, aimAt(base, target(r))});
        for (int k : out_.tree.baseOrgans) out_.baseOrgans.push_back({k, aimAlong(base, heading(k))});
        // Depth first with a stack of its own: a skeleton may be thousands of internodes deep.
        std::vector<std::pair<int, Place>> pending;
        for (auto it = out_.roots.rbegin(); it != out_.roots.rend(); ++it)
            pending.push_back({it->internode, turned(base, it->turn)});
        bool trunk = true;
        while (!pending.empty()) {
            auto [i, place] = pending.back();
            pending.pop_back();
            grow(i, place, trunk);
            trunk = false;
            const GrownInternode& g = out_.internodes[size_t(i)];
            for (auto it = g.children.rbegin(); it != g.children.rend(); ++it)
                pending.push_back({it->internode, turned(place, it->turn)});
        }
        return std::move(out_);
    }

private:
    const Plant& plant_;
    Regrowth out_;

    float radians(float angle) const {
        return out_.unit == AngleUnit::Degrees ? angle * turtle::kRadiansPerDegree : angle;
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
        const double unit = out_.unit == AngleUnit::Degrees ? 180.0 / std::numbers::pi : 1.0;
        return {float(pitch * unit), float(roll * unit)};
    }

    // The frame after a turn, as the turtle turns it: roll, then pitch.
    Place turned(Place p, const Turn& t) const {
        turtle::turnToward(p.frame.up, p.frame.left, radians(t.roll));
        turtle::turnToward(p.frame.heading, p.frame.up, -radians(t.pitch));
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

Regrowth regrowth(const Plant& plant, AngleUnit unit) { return Regrower(plant, unit).run(); }

} // namespace simeco::skeleton
