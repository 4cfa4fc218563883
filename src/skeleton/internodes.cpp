#include "skeleton/internodes.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>

#include <glm/geometric.hpp>

namespace simeco::skeleton {

namespace {

// A point of the skeleton, named by the first stem it belongs to: a stem's base is its parent's point.
struct Node {
    int stem = -1; // -1: the plant's base
    size_t point = 0;
    bool operator<(const Node& o) const { return stem != o.stem ? stem < o.stem : point < o.point; }
};

class TreeBuilder {
public:
    explicit TreeBuilder(const Plant& plant) : plant_(plant) {
        for (size_t k = 0; k < plant.stems.size(); ++k) index_[plant.stems[k].id] = k;
    }

    InternodeTree build() {
        // Internodes in stem order, each stem's from its base.
        std::map<std::pair<int, size_t>, int> bySegment;
        for (const Stem& s : plant_.stems)
            for (size_t k = 0; k + 1 < s.points.size(); ++k) {
                Internode n;
                n.stem = s.id;
                n.segment = k;
                n.start = s.points[k];
                n.end = s.points[k + 1];
                n.length = glm::length(n.end - n.start);
                n.width = s.widths.empty() ? s.width : s.widths[k];
                bySegment[{s.id, k}] = int(tree_.internodes.size());
                tree_.internodes.push_back(n);
            }
        // Each internode's parent: the one ending where it starts.
        for (size_t i = 0; i < tree_.internodes.size(); ++i) {
            Internode& n = tree_.internodes[i];
            Node at = canonical({n.stem, n.segment});
            if (at.stem < 0) {
                tree_.roots.push_back(int(i));
                continue;
            }
            n.parent = bySegment.at({at.stem, at.point - 1});
            tree_.internodes[size_t(n.parent)].children.push_back(int(i));
        }
        for (size_t k = 0; k < plant_.organs.size(); ++k) {
            const Organ& o = plant_.organs[k];
            Node at = canonical({o.stem, size_t(o.point)});
            if (at.stem < 0) tree_.baseOrgans.push_back(int(k));
            else tree_.internodes[size_t(bySegment.at({at.stem, at.point - 1}))].organs.push_back(int(k));
        }
        if (!plant_.stems.empty()) tree_.base = plant_.stems.front().points.front();
        for (Internode& n : tree_.internodes) mainChildFirst(n);
        levels();
        return std::move(tree_);
    }

private:
    const Plant& plant_;
    std::map<int, size_t> index_;
    InternodeTree tree_;

    // The node a stem's point is: a stem's base is its parent's point `attach`, a root stem's base the plant's.
    Node canonical(Node at) const {
        while (at.point == 0) {
            const Stem& s = plant_.stems[index_.at(at.stem)];
            if (s.parent < 0) return {-1, 0};
            at = {s.parent, size_t(s.attach)};
        }
        return at;
    }

    // The child at the smallest angle to the parent's direction is its main child (the first such, on ties).
    void mainChildFirst(Internode& n) {
        if (n.children.size() < 2) return;
        const glm::dvec3 d = (n.end - n.start) / n.length;
        auto angle = [&](int c) {
            const Internode& child = tree_.internodes[size_t(c)];
            return std::acos(std::clamp(glm::dot(d, (child.end - child.start) / child.length), -1.0, 1.0));
        };
        auto main = std::min_element(n.children.begin(), n.children.end(),
                                     [&](int a, int b) { return angle(a) < angle(b); });
        std::rotate(n.children.begin(), main, main + 1);
    }

    // Levels by breadth-first search from the base: the shortest path of unit steps, as the thesis' Dijkstra.
    void levels() {
        std::deque<int> queue(tree_.roots.begin(), tree_.roots.end());
        while (!queue.empty()) {
            const Internode& n = tree_.internodes[size_t(queue.front())];
            queue.pop_front();
            tree_.levels = std::max(tree_.levels, n.level + 1);
            for (int c : n.children) {
                tree_.internodes[size_t(c)].level = n.level + 1;
                queue.push_back(c);
            }
        }
    }
};

} // namespace

InternodeTree internodeTree(const Plant& plant) { return TreeBuilder(plant).build(); }

} // namespace simeco::skeleton
