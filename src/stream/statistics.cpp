#include "stream/statistics.h"

#include <algorithm>
#include <vector>

namespace simeco::stream {

StringStatistics computeStatistics(const ModuleString& s, const ir::Alphabet& alphabet) {
    StringStatistics stats;
    stats.modules = s.size();
    stats.plants = s.plants();
    std::vector<uint64_t> counts(alphabet.size(), 0);
    int depth = 0;
    for (uint32_t sym : s.sym) {
        ++counts[sym];
        if (sym == ir::kBranchOpen) stats.maxBranchDepth = std::max(stats.maxBranchDepth, ++depth);
        else if (sym == ir::kBranchClose) depth = std::max(depth - 1, 0);
    }
    for (size_t i = 0; i < counts.size(); ++i)
        if (counts[i]) stats.perSymbol[alphabet.name(static_cast<ir::SymbolId>(i))] = counts[i];
    return stats;
}

} // namespace simeco::stream
