#include "bench/suite.h"

#include <filesystem>

namespace simeco::bench {

const std::vector<SuiteGrammar>& suiteGrammars() {
    // maxSteps lies well past the step at which one plant alone reaches 10^7 modules (1.24d: 13, 2.6: 21,
    // 1.31a: 61, 1.27: 12), so it only stops grammars that saturate, such as Lantana's bounded shoots.
    static const std::vector<SuiteGrammar> grammars = {
        {"abop-1.24d", "grammars/abop/fig1.24d.l", "D0L (bracketed, deterministic)", 40},
        {"abop-2.6", "grammars/abop/fig2.6-monopodial.l", "parametric", 40},
        {"abop-1.31a", "grammars/abop/fig1.31a.l", "context-sensitive (signals)", 100},
        {"abop-1.27", "grammars/abop/fig1.27-stochastic.l", "stochastic", 40},
        {"lantana", "scenes/lantana-camara.eco", "SimEco plant (stochastic, context-sensitive, parametric)", 30},
    };
    return grammars;
}

std::vector<SuiteEntry> benchSuite(bool quick) {
    std::vector<SuiteEntry> entries;
    for (const SuiteGrammar& g : suiteGrammars()) {
        for (std::uint32_t plants :
             quick ? std::vector<std::uint32_t>{1, 10} : std::vector<std::uint32_t>{1, 100, 10'000}) {
            entries.push_back({g, plants});
        }
    }
    return entries;
}

std::string defaultSuiteRoot() {
    std::filesystem::path root = SIMECO_SOURCE_ROOT;
    std::error_code error;
    if (std::filesystem::exists(root / suiteGrammars().front().file, error)) {
        return root.string();
    }
    return ".";
}

} // namespace simeco::bench
