#include "grow/growing_species.h"

#include <cmath>
#include <filesystem>

#include "ir/source_loc.h"
#include "ir/species.h"
#include "lang/eco_assets.h"
#include "lang/eco_parser.h"
#include "lang/load_grammar.h"

namespace simeco::grow {

float GrowingSpecies::relativeGravity() const {
    if (!scene) return 1.0f;
    const ir::EcoVector& g = scene->gravity;
    return std::sqrt(g.x.typical() * g.x.typical() + g.y.typical() * g.y.typical() + g.z.typical() * g.z.typical()) /
           9.81f;
}

GrowingSpecies loadGrowingSpecies(const std::string& path, std::vector<ir::EcoWarning>* warnings) {
    GrowingSpecies g;
    if (std::filesystem::path(path).extension() != ".eco") {
        g.species = ir::unifySpecies(lang::loadSpecies(path, warnings));
        g.ecoPlants.assign(g.species.size(), nullptr);
        return g;
    }
    ir::EcoScene scene = lang::parseEcoFile(path);
    if (warnings) warnings->insert(warnings->end(), scene.warnings.begin(), scene.warnings.end());
    return growingSpecies(std::move(scene), warnings);
}

GrowingSpecies growingSpecies(ir::EcoScene parsed, std::vector<ir::EcoWarning>* warnings) {
    GrowingSpecies g;
    auto scene = std::make_unique<ir::EcoScene>(std::move(parsed));
    if (scene->plants.empty()) throw ir::InputError(scene->loc, "the scene has no plant");
    const lang::EcoAssets assets = lang::loadEcoAssets(*scene, g.assets, warnings);
    std::vector<ir::Grammar> species;
    for (size_t i = 0; i < scene->plants.size(); ++i) {
        const ir::EcoPlant& plant = scene->plants[i];
        if (plant.grammar.empty()) {
            species.push_back(lang::compileEcoPlant(*scene, i, lang::EcoDrawing::Grown, &assets));
            continue;
        }
        species.push_back(lang::loadScenePlantGrammar(*scene, plant, warnings));
    }
    g.species = ir::unifySpecies(std::move(species));
    for (const ir::EcoPlant& plant : scene->plants)
        g.ecoPlants.push_back(&plant);
    g.scene = std::move(scene);
    return g;
}

} // namespace simeco::grow
