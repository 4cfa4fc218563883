// Summary figures of a derived string: what `simeco derive --format stats|json` reports.
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "stream/module_string.h"

namespace simeco::stream {

struct StringStatistics {
    uint64_t modules = 0;
    uint64_t plants = 0;
    std::map<std::string, uint64_t> perSymbol; // by module name
    int maxBranchDepth = 0;                    // deepest bracket nesting
};

StringStatistics computeStatistics(const ModuleString& s, const ir::Alphabet& alphabet);

} // namespace simeco::stream
