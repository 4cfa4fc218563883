#include "codegen/species_classes.h"

#include <string>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "codegen/curve_codegen.h"
#include "codegen/hoisted_constants.h"
#include "codegen/kernel_traits.h"
#include "codegen/production_codegen.h"

namespace simeco::codegen {

namespace {

// The generated code's comments name the productions' lines, which differ between copies of one plant.
std::string withoutComments(const std::string& code) {
    std::string kept;
    kept.reserve(code.size());
    for (size_t at = 0; at < code.size();) {
        size_t comment = code.find("//", at);
        if (comment == std::string::npos) comment = code.size();
        kept.append(code, at, comment - at);
        at = code.find('\n', comment);
        if (at == std::string::npos) break;
    }
    return kept;
}

// What a species' kernel code is made of, generated as the species of index 0 (names, error sites and table
// offsets are then its own, not its place among the species) with every constant of its productions read from the
// table, with the numbers it reads from tables and the weights it draws by. Two species with the same key get the
// same code but for their constants. Numbers are written in full (shortest round trip), so different values never
// make the same key.
std::string codeKey(const ir::Grammar& species) {
    const ir::Grammar g = withHoistedConstants(species, std::vector<bool>(constantsOf(species).size(), true));
    std::string code;
    std::vector<ErrorSite> errors;
    std::vector<double> tables;
    code += functionTableCode(g, 0, tables);
    code += curveTableCode(g, 0, tables);
    std::string numbers = fmt::format("tables {}\n", fmt::join(tables, " "));
    for (RuleKind kind : {RuleKind::Step, RuleKind::Decomposition}) {
        const ir::RuleSet& rules = kind == RuleKind::Step ? g.productions : g.decomposition;
        numbers += fmt::format("{} productions to depth {}, weights", rules.productions.size(), rules.maxDepth);
        for (size_t i = 0; i < rules.productions.size(); ++i) {
            const ir::Production& p = rules.productions[i];
            numbers += fmt::format(" {}", p.weight);
            emitProduction(g, 0, p, kind, i, FrameStyle::Fresh, errors, code);
            emitProduction(g, 0, p, kind, i, FrameStyle::Persistent, errors, code);
        }
        numbers += "\n";
    }
    numbers += "skipped ";
    for (size_t s = 0; s < g.alphabet.size(); ++s)
        numbers += g.skippedInContext(static_cast<ir::SymbolId>(s)) ? '1' : '0';
    return numbers + "\n" + withoutComments(code);
}

// A class's representative and its members' hoisted values: the constants in which any member differs from the
// first are hoisted; where none does, the code keeps them all as literals.
void settleClass(const std::vector<ir::Grammar>& species, const std::vector<size_t>& members, SpeciesClasses& classes) {
    const ir::Grammar& first = species[members.front()];
    std::vector<std::vector<double>> constants;
    for (size_t m : members) constants.push_back(constantsOf(species[m]));
    std::vector<bool> hoist(constants.front().size(), false);
    bool any = false;
    for (size_t j = 0; j < hoist.size(); ++j)
        for (const std::vector<double>& c : constants)
            if (!sameConstant(c[j], constants.front()[j])) hoist[j] = any = true;
    classes.representatives.push_back(withHoistedConstants(first, hoist));
    if (!any) return;
    for (size_t i = 0; i < members.size(); ++i) {
        std::vector<double>& row = classes.hoisted[members[i]];
        for (size_t j = 0; j < hoist.size(); ++j)
            if (hoist[j]) row.push_back(constants[i][j]);
    }
}

} // namespace

bool SpeciesClasses::hoists() const {
    for (const std::vector<double>& row : hoisted)
        if (!row.empty()) return true;
    return false;
}

SpeciesClasses classifySpecies(const std::vector<ir::Grammar>& species) {
    SpeciesClasses classes;
    std::unordered_map<std::string, uint32_t> byKey;
    std::vector<std::vector<size_t>> members;
    for (size_t s = 0; s < species.size(); ++s) {
        auto [found, added] = byKey.try_emplace(codeKey(species[s]), static_cast<uint32_t>(members.size()));
        if (added) members.emplace_back();
        members[found->second].push_back(s);
        classes.classOf.push_back(found->second);
    }
    classes.hoisted.resize(species.size());
    for (const std::vector<size_t>& m : members) settleClass(species, m, classes);
    return classes;
}

} // namespace simeco::codegen
