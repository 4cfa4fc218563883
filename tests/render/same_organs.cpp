#include "same_organs.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace simeco::test {

std::string organDifference(const turtle::Interpretation& want, const turtle::Interpretation& got) {
    if (got.count != want.count || got.first != want.first) return "the organs of each kind differ in number";
    float size = 0;
    for (int axis = 0; axis < 3; ++axis) size = std::max(size, want.bounds.max[axis] - want.bounds.min[axis]);
    if (!(size > 0.0f)) return "the field has no extent";
    auto near = [&](float a, float b) { return std::fabs(a - b) <= 1e-4f * size; };
    for (size_t i = 0; i < want.organs.size(); ++i) {
        const shared::OrganInstance &w = want.organs[i], &g = got.organs[i];
        if (g.plant != w.plant || g.module != w.module || g.kind != w.kind)
            return fmt::format("organ {}: plant {} module {} kind {}, not plant {} module {} kind {}", i, g.plant,
                               g.module, g.kind, w.plant, w.module, w.kind);
        if (!near(g.position.x, w.position.x) || !near(g.position.y, w.position.y) ||
            !near(g.position.z, w.position.z) || !near(g.position.w, w.position.w) ||
            !near(g.heading.w, w.heading.w))
            return fmt::format("organ {} (plant {}, module {}) stands or measures otherwise", i, w.plant, w.module);
    }
    return "";
}

} // namespace simeco::test
