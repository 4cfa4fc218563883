#include "app/load_species.h"

#include <cstdio>

#include "lang/eco_parser.h"
#include "lang/load_grammar.h"

namespace simeco::app {

std::vector<ir::Grammar> loadGrammars(const std::string& path) {
    std::vector<ir::Grammar> grammars;
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ".eco") == 0) {
        ir::EcoScene scene = lang::parseEcoFile(path);
        for (const ir::EcoWarning& w : scene.warnings)
            std::fprintf(stderr, "%s:%d:%d: warning: %s\n", w.loc.file.c_str(), w.loc.line, w.loc.col,
                         w.message.c_str());
        if (scene.plants.empty()) throw ir::InputError(scene.loc, "the scene has no plant");
        for (size_t i = 0; i < scene.plants.size(); ++i) grammars.push_back(lang::compileEcoPlant(scene, i));
    } else {
        grammars.push_back(lang::loadGrammarFile(path));
    }
    return grammars;
}

} // namespace simeco::app
