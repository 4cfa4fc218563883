#include "codegen/context_codegen.h"

#include <algorithm>
#include <map>
#include <optional>
#include <set>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "codegen/hoisted_constants.h"
#include "codegen/production_analysis.h"

namespace simeco::codegen {

namespace {

// GLSL for the value (a double) and the truth of a condition part that reads only the predecessor's own
// parameters (ownParam(i, k)) and constants, through comparisons, negation and logic: std::nullopt for any other
// part. No sums or products, which a compiler may fuse differently here and in the production.
struct OwnParameterCode {
    const ir::PatternModule& predecessor;

    std::optional<std::string> value(const ir::Expr& e) const {
        using ir::Op;
        switch (e.op) {
        case Op::Const: return isHoisted(e) ? std::nullopt : std::optional(literal(e.value)); // per species
        case Op::Local: {
            const std::vector<int>& slots = predecessor.paramSlots;
            auto at = std::find(slots.begin(), slots.end(), e.slot);
            if (at == slots.end()) return std::nullopt;
            return fmt::format("ownParam(i, {}u)", at - slots.begin());
        }
        case Op::Neg: {
            std::optional<std::string> a = value(e.args[0]);
            return a ? std::optional(fmt::format("(-{})", *a)) : std::nullopt;
        }
        default: {
            std::optional<std::string> t = truth(e);
            return t ? std::optional(fmt::format("({} ? 1.0LF : 0.0LF)", *t)) : std::nullopt;
        }
        }
    }

    std::optional<std::string> truth(const ir::Expr& e) const {
        using ir::Op;
        switch (e.op) {
        case Op::Lt: case Op::Le: case Op::Gt: case Op::Ge: case Op::Eq: case Op::Ne: {
            static const char* ops[] = {"<", "<=", ">", ">=", "==", "!="};
            std::optional<std::string> a = value(e.args[0]), b = value(e.args[1]);
            if (!a || !b) return std::nullopt;
            return fmt::format("({} {} {})", *a, ops[static_cast<int>(e.op) - static_cast<int>(Op::Lt)], *b);
        }
        case Op::And: case Op::Or: {
            std::optional<std::string> a = truth(e.args[0]), b = truth(e.args[1]);
            if (!a || !b) return std::nullopt;
            return fmt::format("({} {} {})", *a, e.op == Op::And ? "&&" : "||", *b);
        }
        case Op::Not: {
            std::optional<std::string> a = value(e.args[0]);
            return a ? std::optional(fmt::format("({} == 0.0LF)", *a)) : std::nullopt;
        }
        case Op::Const: case Op::Local: case Op::Neg: {
            std::optional<std::string> a = value(e);
            return a ? std::optional(fmt::format("({} != 0.0LF)", *a)) : std::nullopt;
        }
        default: return std::nullopt;
        }
    }
};

// Whether evaluating e can have no effect and raise no error: no calls, divisions or array elements.
bool harmless(const ir::Expr& e) {
    using ir::Op;
    switch (e.op) {
    case Op::Call: case Op::Div: case Op::Mod: case Op::Pow: case Op::ArrayElem: case Op::String: return false;
    default: return std::all_of(e.args.begin(), e.args.end(), harmless);
    }
}

// What a module must satisfy for step production p to apply, decided by its own parameters before any context is
// walked: the conjuncts of p's condition that OwnParameterCode can write, among those before the first one that is
// not harmless, as GLSL; "" for none. The CPU reference evaluates the condition after the contexts, from the left
// and stopping at the first false conjunct, so a module these reject draws nothing and raises no error there:
// skipping its walk changes nothing. Statements before the condition might, so p has none.
std::string ownParameterGuard(const ir::Production& p) {
    if (!p.condition || !p.before.empty() || p.strict.size() != 1) return "";
    std::vector<const ir::Expr*> conjuncts;
    auto flatten = [&](const ir::Expr& e, auto& self) -> void {
        if (e.op == ir::Op::And) {
            self(e.args[0], self);
            self(e.args[1], self);
        } else {
            conjuncts.push_back(&e);
        }
    };
    flatten(*p.condition, flatten);
    OwnParameterCode code{p.strict.front()};
    std::vector<std::string> guards;
    for (const ir::Expr* c : conjuncts) {
        if (std::optional<std::string> t = code.truth(*c))
            guards.push_back(*t);
        else if (!harmless(*c))
            break;
    }
    return fmt::format("{}", fmt::join(guards, " && "));
}

// Per species, the predecessors of the productions one prefetched walk serves, each with the guards
// (ownParameterGuard) of those productions; an empty guard lets every module of the symbol walk.
using WalkerSymbols = std::vector<std::map<ir::SymbolId, std::set<std::string>>>;

// A condition on `species`, `sym` and the module's own parameters that holds for the modules whose productions
// read a prefetched walk, so that the others do not walk: lavapipe runs a loop as long as its longest walk among
// the invocations that enter it. A species with many such symbols walks for all, where the comparisons would cost
// more than the walks they save.
std::string walkerCondition(const WalkerSymbols& walkers) {
    constexpr size_t kMostComparisons = 16;
    std::vector<std::string> terms;
    for (size_t sp = 0; sp < walkers.size(); ++sp) {
        if (walkers[sp].empty()) continue;
        std::vector<std::string> symbols;
        for (const auto& [sym, guards] : walkers[sp]) {
            if (guards.count(""))
                symbols.push_back(fmt::format("sym == {}u", sym));
            else
                symbols.push_back(fmt::format("(sym == {}u && ({}))", sym, fmt::join(guards, " || ")));
        }
        std::string bySymbol = walkers[sp].size() > kMostComparisons ? "true" : fmt::format("{}", fmt::join(symbols, " || "));
        terms.push_back(walkers.size() == 1 ? bySymbol : fmt::format("(species == {}u && ({}))", sp, bySymbol));
    }
    return fmt::format("{}", fmt::join(terms, " || "));
}

// The first context walks of the `kind` rules of all species: per species, the predecessors whose productions read
// each kind of walk (of the patterns a writing pass walks, when `writing`).
struct PrefetchedWalks {
    WalkerSymbols right, rightBranch, left;
};

PrefetchedWalks prefetchedWalks(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing) {
    PrefetchedWalks walks{WalkerSymbols(species.size()), WalkerSymbols(species.size()), WalkerSymbols(species.size())};
    for (size_t sp = 0; sp < species.size(); ++sp) {
        const ir::Grammar& g = species[sp];
        for (const ir::Production& p : (kind == RuleKind::Step ? g.productions : g.decomposition).productions) {
            // A decomposition kernel keeps its predecessor's parameters elsewhere (strictParam).
            std::string guard = kind == RuleKind::Step ? ownParameterGuard(p) : "";
            if (firstRightWalkPrefetched(g, p) && (!writing || writingWalks(p, p.right))) {
                bool enters = p.right.front().sym == ir::kBranchOpen;
                (enters ? walks.rightBranch : walks.right)[sp][p.strict.front().sym].insert(guard);
            }
            if (firstLeftWalkPrefetched(g, p) && (!writing || writingWalks(p, p.left))) {
                walks.left[sp][p.strict.front().sym].insert(guard);
            }
        }
    }
    return walks;
}

bool anyWalker(const WalkerSymbols& walkers) {
    return std::any_of(walkers.begin(), walkers.end(), [](const auto& symbols) { return !symbols.empty(); });
}

// Whether every module of some symbol walks: a production of it has no guard (ownParameterGuard).
bool anyUnguardedWalker(const WalkerSymbols& walkers) {
    return std::any_of(walkers.begin(), walkers.end(), [](const auto& symbols) {
        return std::any_of(symbols.begin(), symbols.end(), [](const auto& entry) { return entry.second.count("") > 0; });
    });
}

} // namespace

std::string contextPrefetchCode(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing) {
    PrefetchedWalks walks = prefetchedWalks(species, kind, writing);
    std::string code = "void prefetchContexts(uint i, uint species, uint sym, int ctxLeft, uint ctxRight, uint pBegin, uint pEnd) {\n";
    if (anyWalker(walks.right) || anyWalker(walks.rightBranch) || anyWalker(walks.left))
        code += fmt::format("    uint skipRow = species * {}u;\n", skipWords(species.front()));
    // One walk: `name` is firstRight, firstRightBranch or firstLeft, `walk` the call that moves it.
    auto prefetch = [&](const WalkerSymbols& walkers, const std::string& name, const std::string& start, const std::string& walk) {
        std::string condition = walkerCondition(walkers);
        if (condition.empty()) return;
        code += fmt::format("    {0}Found = false;\n"
                            "    if ({1}) {{\n"
                            "        {0} = {2};\n"
                            "        {0}Found = {3};\n"
                            "        if ({0}Found) {0}Word = walkWord;\n"
                            "    }}\n",
                            name, condition, start, walk);
    };
    prefetch(walks.right, "firstRight", "ctxRight", "walkRight(firstRight, false, pEnd, skipRow)");
    prefetch(walks.rightBranch, "firstRightBranch", "ctxRight", "walkRight(firstRightBranch, true, pEnd, skipRow)");
    prefetch(walks.left, "firstLeft", "ctxLeft", "walkLeft(firstLeft, pBegin, skipRow)");
    return code + "}\n\n";
}

bool everyModuleOfASymbolWalks(const std::vector<ir::Grammar>& species) {
    PrefetchedWalks walks = prefetchedWalks(species, RuleKind::Step, false);
    return anyUnguardedWalker(walks.right) || anyUnguardedWalker(walks.rightBranch) || anyUnguardedWalker(walks.left);
}

std::string contextChunkConstants(const std::vector<ir::Grammar>& species) {
    PrefetchedWalks walks = prefetchedWalks(species, RuleKind::Step, false);
    return fmt::format("const bool kChunkRight = {};\n"
                       "const bool kChunkRightBranch = {};\n"
                       "const bool kChunkLeft = {};\n"
                       "const uint kSkipWords = {}u;\n",
                       anyWalker(walks.right), anyWalker(walks.rightBranch), anyWalker(walks.left),
                       skipWords(species.front()));
}

std::vector<uint32_t> contextSkipBits(const std::vector<ir::Grammar>& species) {
    size_t symbols = species.front().alphabet.size();
    size_t rowWords = skipWords(species.front());
    std::vector<uint32_t> bits(rowWords * species.size(), 0);
    for (size_t sp = 0; sp < species.size(); ++sp)
        for (size_t s = 0; s < symbols; ++s)
            if (species[sp].skippedInContext(static_cast<ir::SymbolId>(s)))
                bits[sp * rowWords + s / 32] |= 1u << (s % 32);
    return bits;
}

std::string contextSkipCode(const std::vector<uint32_t>& bits) {
    // Few words become constants, so a walk tests a symbol without a load; many stay in the speciesTable buffer.
    constexpr size_t kMostConstantWords = 16;
    if (bits.size() > kMostConstantWords) return "uint contextSkipWord(uint word) { return speciesTable[word]; }\n";
    std::string code = "uint contextSkipWord(uint word) {\n    uint bits = 0u;\n";
    for (size_t w = 0; w < bits.size(); ++w)
        if (bits[w] != 0) code += fmt::format("    bits = word == {}u ? 0x{:08x}u : bits;\n", w, bits[w]);
    return code + "    return bits;\n}\n";
}

} // namespace simeco::codegen
