// A skeleton's shape in numbers, level by level (internodes.h): how many internodes, how long, at what angle to
// their parent, and how many children each puts out. What the prediction grammar is judged by: grown further, it
// should keep these as the skeleton has them.
#pragma once

#include <string>
#include <vector>

#include "skeleton/internodes.h"

namespace simeco::skeleton {

struct Distribution {
    size_t count = 0;
    double mean = 0.0, deviation = 0.0, min = 0.0, max = 0.0;
};

Distribution distributionOf(const std::vector<double>& values);

struct LevelStatistics {
    int level = 0;
    Distribution length;
    Distribution angle;    // degrees between an internode and its parent (none for those on the base)
    Distribution children; // per internode
};

// One row per level, from 0.
std::vector<LevelStatistics> levelStatistics(const InternodeTree& tree);

// A table with a header line: level, internodes, length mean and deviation, angle mean and deviation, children.
std::string statisticsTable(const std::vector<LevelStatistics>& levels);

} // namespace simeco::skeleton
