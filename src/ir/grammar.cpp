#include "ir/grammar.h"

#include <algorithm>

namespace simeco::ir {

SymbolId Grammar::symbol(const std::string& name, uint32_t space) {
    SymbolId id = alphabet.intern(name, space);
    if (contextSkip.size() < alphabet.size()) contextSkip.resize(alphabet.size(), contextSkipDefault);
    return id;
}

int Grammar::maxParams() const {
    size_t most = 0;
    for (const SuccessorModule& m : axiom) most = std::max(most, m.args.size());
    for (const RuleSet* rules : {&productions, &decomposition, &homomorphism}) {
        for (const Production& p : rules->productions) {
            for (const Alternative& alt : p.alternatives)
                for (const SuccessorModule& m : alt.modules) most = std::max(most, m.args.size());
        }
    }
    return static_cast<int>(most);
}

} // namespace simeco::ir
