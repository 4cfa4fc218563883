#include "codegen/species_classes.h"

#include <string>
#include <unordered_map>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "codegen/curve_codegen.h"
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
// offsets are then its own, not its place among the species), with the numbers it reads from tables and the
// weights it draws by. Two species with the same key get the same code. Numbers are written in full
// (shortest round trip), so different values never make the same key.
std::string codeKey(const ir::Grammar& g) {
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

} // namespace

SpeciesClasses classifySpecies(const std::vector<ir::Grammar>& species) {
    SpeciesClasses classes;
    std::unordered_map<std::string, uint32_t> byKey;
    for (const ir::Grammar& g : species) {
        auto [found, added] = byKey.try_emplace(codeKey(g), static_cast<uint32_t>(classes.representatives.size()));
        if (added) classes.representatives.push_back(g);
        classes.classOf.push_back(found->second);
    }
    return classes;
}

} // namespace simeco::codegen
