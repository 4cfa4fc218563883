#include "codegen/successor_slots.h"

#include <algorithm>
#include <optional>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "codegen/production_analysis.h"

namespace simeco::codegen {

bool successorsKeepBracketsBalanced(const std::vector<ir::Grammar>& species) {
    auto isBracket = [](ir::SymbolId s) { return s == ir::kBranchOpen || s == ir::kBranchClose; };
    for (const ir::Grammar& g : species) {
        std::optional<ir::SymbolId> equals = g.alphabet.find("=");
        for (const ir::Production& p : g.productions.productions) {
            if (std::any_of(p.strict.begin(), p.strict.end(), [&](const ir::PatternModule& m) { return isBracket(m.sym); }))
                return false;
            if (equals && std::any_of(p.right.begin(), p.right.end(),
                                      [&](const ir::PatternModule& m) { return m.sym == *equals; }))
                return false;
            for (const ir::Alternative& alt : p.alternatives) {
                int depth = 0;
                for (const ir::SuccessorModule& m : alt.modules) {
                    depth += m.sym == ir::kBranchOpen ? 1 : m.sym == ir::kBranchClose ? -1 : 0;
                    if (depth < 0) return false;
                }
                if (depth != 0) return false;
            }
        }
    }
    return true;
}

SuccessorSlots successorSlots(const std::vector<ir::Grammar>& species, RuleKind kind, uint32_t copiedParams) {
    SuccessorSlots slots;
    slots.params.assign(1, copiedParams);
    slots.pairs.assign(1, false);
    for (const ir::Grammar& g : species)
        for (const ir::Production& p : (kind == RuleKind::Step ? g.productions : g.decomposition).productions)
            for (const ir::Alternative& alt : p.alternatives) {
                if (alt.modules.size() > slots.params.size()) {
                    slots.params.resize(alt.modules.size(), 0);
                    slots.pairs.resize(alt.modules.size(), false);
                }
                std::vector<std::optional<size_t>> partner = pairedBrackets(alt);
                for (size_t j = 0; j < alt.modules.size(); ++j) {
                    slots.params[j] = std::max(slots.params[j], static_cast<uint32_t>(alt.modules[j].args.size()));
                    if (partner[j]) slots.pairs[j] = true;
                }
            }
    return slots;
}

std::string slotDeclarations(const SuccessorSlots& slots) {
    std::string s;
    for (size_t j = 0; j < slots.params.size(); ++j) {
        s += fmt::format("uint slotWord{};", j);
        for (uint32_t a = 0; a < slots.params[j]; ++a) s += fmt::format(" float slotParam{}_{};", j, a);
        if (slots.pairs[j]) s += fmt::format(" uint slotPartner{};", j);
        s += "\n";
    }
    return s + "\n";
}

namespace {

// The stores of one slot at pos + `at` (a number or, in the loop over slots, j), its word in `word`.
std::string slotStores(const std::string& at, const std::string& word, const std::vector<std::string>& params,
                       const std::string& partner, bool provenance, uint32_t paramVector) {
    std::string s = fmt::format("        symOut[pos + {}] = {};\n", at, word);
    if (paramVector == 1) {
        for (size_t a = 0; a < params.size(); ++a)
            s += fmt::format("        if (({} >> kSymbolBits) > {}u) parOut[(pos + {}) * pc.stride + {}u] = {};\n", word, a,
                             at, a, params[a]);
    } else if (!params.empty()) {
        std::vector<std::string> components = params;
        components.resize(paramVector, "0.0");
        s += fmt::format("        if (({} >> kSymbolBits) > 0u) parOut[pos + {}] = vec{}({});\n", word, at, paramVector,
                         fmt::join(components, ", "));
    }
    if (provenance) s += fmt::format("        originOut[pos + {0}] = origin;\n        liveOut[pos + {0}] = 1u;\n", at);
    if (!partner.empty())
        s += fmt::format("        if ({0} != kNoModule) partnersOut[pos + {1}] = pos + {0};\n", partner, at);
    return s;
}

} // namespace

uint32_t parameterVectorWidth(uint32_t stride) { return stride == 2 || stride == 4 ? stride : 1; }

std::string slotStoreCode(const SuccessorSlots& slots, bool provenance, bool partners, uint32_t paramVector) {
    // Up to this many slots are stored one by one; more go through a loop (below).
    constexpr size_t kMostSlotsStoredOneByOne = 16;
    size_t count = slots.params.size();
    bool loop = count > kMostSlotsStoredOneByOne;
    std::string accessors, s = "void storeSlots(uint pos, uint n, uint origin) {\n";
    for (size_t j = 0; j < (loop ? 1 : count); ++j) {
        std::vector<std::string> params;
        for (uint32_t a = 0; a < slots.params[j]; ++a) params.push_back(fmt::format("slotParam{}_{}", j, a));
        std::string partner = partners && slots.pairs[j] ? fmt::format("slotPartner{}", j) : "";
        s += fmt::format("    if ({}u < n) {{\n", j) +
             slotStores(fmt::format("{}u", j), fmt::format("slotWord{}", j), params, partner, provenance, paramVector) +
             "    }\n";
    }
    if (loop) {
        // The slots after the first in a loop as long as the subgroup's longest successor: every store in the
        // kernel's code costs a loop over the subgroup on lavapipe, taken or not, and most subgroups copy all
        // their modules, so the loop ends after one pass where the stores one by one would be many.
        uint32_t mostParams = *std::max_element(slots.params.begin() + 1, slots.params.end());
        bool anyPairs = partners && std::find(slots.pairs.begin() + 1, slots.pairs.end(), true) != slots.pairs.end();
        accessors += "uint slotWordAt(uint j) {\n    uint w = 0u;\n";
        for (size_t j = 1; j < count; ++j) accessors += fmt::format("    if (j == {0}u) w = slotWord{0};\n", j);
        accessors += "    return w;\n}\n";
        std::vector<std::string> params;
        for (uint32_t a = 0; a < mostParams; ++a) {
            accessors += fmt::format("float slotParamAt{}(uint j) {{\n    float v = 0.0;\n", a);
            for (size_t j = 1; j < count; ++j)
                if (slots.params[j] > a) accessors += fmt::format("    if (j == {0}u) v = slotParam{0}_{1};\n", j, a);
            accessors += "    return v;\n}\n";
            params.push_back(fmt::format("slotParamAt{}(j)", a));
        }
        if (anyPairs) {
            accessors += "uint slotPartnerAt(uint j) {\n    uint p = kNoModule;\n";
            for (size_t j = 1; j < count; ++j)
                if (slots.pairs[j]) accessors += fmt::format("    if (j == {0}u) p = slotPartner{0};\n", j);
            accessors += "    return p;\n}\n";
        }
        s += "    uint most = subgroupMax(n);\n"
             "    for (uint j = 1u; j < most; ++j) {\n"
             "        if (j >= n) continue;\n"
             "        uint word = slotWordAt(j);\n";
        if (anyPairs) s += "        uint partner = slotPartnerAt(j);\n";
        s += slotStores("j", "word", params, anyPairs ? "partner" : "", provenance, paramVector);
        s += "    }\n";
    }
    return accessors + s + "}\n\n";
}

std::string resetSlotPartners(const SuccessorSlots& slots) {
    std::string s;
    for (size_t j = 0; j < slots.pairs.size(); ++j)
        if (slots.pairs[j]) s += fmt::format("    slotPartner{} = kNoModule;\n", j);
    return s;
}

} // namespace simeco::codegen
