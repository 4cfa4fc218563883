// The fixed benchmark suite: which grammars, how many plants, and how far each entry is grown.
//
// Every grammar is derived for 1, 100 and 10,000 plants. An entry is grown, one derivation step at a time in
// a calibration pass, until the whole string (all plants) reaches the target size (10^7 modules) or the module
// cap of this machine and device, whichever comes first; a grammar whose plants stop growing stays below it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace simeco::bench {

inline constexpr std::uint64_t kDefaultTargetModules = 10'000'000;
inline constexpr std::uint64_t kQuickTargetModules = 20'000;

struct SuiteGrammar {
    std::string name; // short, for tables and plots
    std::string file; // relative to the repository root
    std::string kind; // what the grammar exercises
    int maxSteps;     // the calibration never grows an entry beyond this many steps
};

struct SuiteEntry {
    SuiteGrammar grammar;
    std::uint32_t plants = 1;
};

// The suite: every grammar at 1, 100 and 10,000 plants; `quick` keeps 1 and 10 plants (for smoke tests).
std::vector<SuiteEntry> benchSuite(bool quick);

// The grammars of the suite, in table order.
const std::vector<SuiteGrammar>& suiteGrammars();

// Where the suite's files are looked up when no --root is given: the source tree simeco was built from if it
// still exists, else the current folder.
std::string defaultSuiteRoot();

} // namespace simeco::bench
