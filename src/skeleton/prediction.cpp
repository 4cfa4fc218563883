#include "skeleton/prediction.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace simeco::skeleton {

void Range::add(float v) {
    if (empty()) {
        min = max = v;
        return;
    }
    min = std::min(min, v);
    max = std::max(max, v);
}

Prediction predictionOf(const Plant& plant, const Regrowth& growth) {
    Prediction out;
    std::map<std::pair<bool, size_t>, RuleTemplate> byShape;
    std::map<std::pair<bool, size_t>, size_t> leafCount;
    // The young growth, the outer half of the levels, is what the tips go on like (all of it for a plant of few).
    int youngFrom = growth.tree.levels / 2;
    size_t young = 0;
    for (const Internode& n : growth.tree.internodes) young += n.level >= youngFrom;
    if (young < 8) youngFrom = 0;
    for (size_t i = 0; i < growth.internodes.size(); ++i) {
        if (growth.tree.internodes[i].level < youngFrom) continue;
        const GrownInternode& g = growth.internodes[i];
        // A main child continues its parent's stem (or straightest on); a tip has none.
        const bool goesOn = !g.children.empty();
        const size_t branches = goesOn ? g.children.size() - 1 : 0;
        RuleTemplate& t = byShape[{goesOn, branches}];
        if (t.members == 0) {
            t = RuleTemplate{};
            t.length = t.width = t.leafPitch = t.leafRoll = Range{1.0f, 0.0f};
            t.goesOn = goesOn;
            t.branches = branches;
            t.pitch.assign(g.children.size(), Range{1.0f, 0.0f});
            t.roll.assign(g.children.size(), Range{1.0f, 0.0f});
        }
        ++t.members;
        ++out.internodes;
        t.length.add(g.length);
        t.width.add(g.width);
        for (size_t c = 0; c < g.children.size(); ++c) {
            t.pitch[c].add(g.children[c].turn.pitch);
            t.roll[c].add(g.children[c].turn.roll);
        }
        for (const GrownOrgan& o : g.organs) {
            if (plant.organs[size_t(o.organ)].kind != OrganKind::Leaf) continue;
            t.leafPitch.add(o.turn.pitch);
            t.leafRoll.add(o.turn.roll);
            ++leafCount[{goesOn, branches}];
        }
    }
    for (auto& [shape, t] : byShape) {
        t.leaves = size_t(std::lround(double(leafCount[shape]) / double(t.members)));
        out.templates.push_back(t);
    }
    std::stable_sort(out.templates.begin(), out.templates.end(),
                     [](const RuleTemplate& a, const RuleTemplate& b) { return a.members > b.members; });
    return out;
}

} // namespace simeco::skeleton
