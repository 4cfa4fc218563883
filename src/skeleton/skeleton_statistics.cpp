#include "skeleton/skeleton_statistics.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <fmt/format.h>
#include <glm/geometric.hpp>

namespace simeco::skeleton {

Distribution distributionOf(const std::vector<double>& values) {
    Distribution d;
    d.count = values.size();
    if (values.empty()) return d;
    double sum = 0.0;
    d.min = d.max = values.front();
    for (double v : values) {
        sum += v;
        d.min = std::min(d.min, v);
        d.max = std::max(d.max, v);
    }
    d.mean = sum / double(values.size());
    double squares = 0.0;
    for (double v : values) squares += (v - d.mean) * (v - d.mean);
    d.deviation = std::sqrt(squares / double(values.size()));
    return d;
}

std::vector<LevelStatistics> levelStatistics(const InternodeTree& tree) {
    std::vector<std::vector<double>> lengths(size_t(tree.levels)), angles(size_t(tree.levels)),
        children(size_t(tree.levels));
    for (const Internode& n : tree.internodes) {
        const size_t l = size_t(n.level);
        lengths[l].push_back(n.length);
        children[l].push_back(double(n.children.size()));
        if (n.parent < 0) continue;
        const Internode& p = tree.internodes[size_t(n.parent)];
        const double c = glm::dot(n.end - n.start, p.end - p.start) / (n.length * p.length);
        angles[l].push_back(std::acos(std::clamp(c, -1.0, 1.0)) * 180.0 / std::numbers::pi);
    }
    std::vector<LevelStatistics> out(size_t(tree.levels));
    for (size_t l = 0; l < out.size(); ++l) {
        out[l].level = int(l);
        out[l].length = distributionOf(lengths[l]);
        out[l].angle = distributionOf(angles[l]);
        out[l].children = distributionOf(children[l]);
    }
    return out;
}

std::string statisticsTable(const std::vector<LevelStatistics>& levels) {
    std::string s = "level  internodes   length mean    sd   angle mean    sd   children\n";
    for (const LevelStatistics& l : levels)
        s += fmt::format("{:5}  {:10}  {:12.4g} {:5.2g}  {:11.1f} {:5.1f}  {:9.2f}\n", l.level, l.length.count,
                         l.length.mean, l.length.deviation, l.angle.mean, l.angle.deviation, l.children.mean);
    return s;
}

} // namespace simeco::skeleton
