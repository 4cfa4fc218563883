// The prediction grammar of seed 002 (section 3.4.2): the initial state's rules grouped by their shape (whether
// the stem goes on, how many branches it has), each group merged into a template whose numbers are the ranges its
// rules span (rand(a, b)), so that once the plant has regrown its skeleton its tips grow on by rules like its own.
// The rules are those of the young growth, the outer half of the levels: the tips go on as the plant last grew,
// not with its trunk's length and width.
#pragma once

#include <vector>

#include "skeleton/infer.h"

namespace simeco::skeleton {

struct Range {
    float min = 0.0f, max = 0.0f;
    void add(float v);
    bool empty() const { return min > max; }
};

struct RuleTemplate {
    bool goesOn = false;     // it has a main child
    size_t branches = 0;     // besides the main child
    size_t members = 0;      // internodes of this shape
    Range length, width;
    std::vector<Range> pitch, roll; // per child position: the main child first, then the branches
    size_t leaves = 0;              // leaves per rule, the members' typical count
    Range leafPitch, leafRoll;
};

struct Prediction {
    std::vector<RuleTemplate> templates; // most frequent first
    size_t internodes = 0;               // that the templates were made from (the young growth)
};

// The templates of a regrowth's rules (in the unit of its turns).
Prediction predictionOf(const Plant& plant, const Regrowth& growth);

} // namespace simeco::skeleton
