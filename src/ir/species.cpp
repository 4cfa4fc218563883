#include "ir/species.h"

namespace simeco::ir {

namespace {

void renumber(std::vector<PatternModule>& modules, const std::vector<SymbolId>& to) {
    for (PatternModule& m : modules) m.sym = to[m.sym];
}

void renumber(std::vector<SuccessorModule>& modules, const std::vector<SymbolId>& to) {
    for (SuccessorModule& m : modules) m.sym = to[m.sym];
}

void renumber(RuleSet& rules, const std::vector<SymbolId>& to) {
    for (Production& p : rules.productions) {
        renumber(p.left, to);
        renumber(p.strict, to);
        renumber(p.right, to);
        for (Alternative& alt : p.alternatives) renumber(alt.modules, to);
    }
}

} // namespace

std::vector<Grammar> unifySpecies(const std::vector<Grammar>& grammars) {
    Alphabet all;
    for (const Grammar& g : grammars)
        for (SymbolId s = 0; s < g.alphabet.size(); ++s) all.intern(g.alphabet.name(s), g.alphabet.space(s));
    std::vector<Grammar> unified;
    unified.reserve(grammars.size());
    for (const Grammar& g : grammars) {
        Grammar u = g;
        std::vector<SymbolId> to(g.alphabet.size());
        for (SymbolId s = 0; s < g.alphabet.size(); ++s) to[s] = all.intern(g.alphabet.name(s), g.alphabet.space(s));
        renumber(u.axiom, to);
        renumber(u.productions, to);
        renumber(u.decomposition, to);
        renumber(u.homomorphism, to);
        // Symbols of other species never occur in this species' plants; they get the grammar's default.
        u.contextSkip.assign(all.size(), g.contextSkipDefault);
        for (SymbolId s = 0; s < g.alphabet.size(); ++s) u.contextSkip[to[s]] = g.skippedInContext(s);
        u.alphabet = all;
        unified.push_back(std::move(u));
    }
    return unified;
}

} // namespace simeco::ir
