#include "grow/growing_species.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "compute/shared/organ_layout.h"
#include "ir/source_loc.h"
#include "ir/species.h"
#include "lang/eco_parser.h"
#include "lang/obj_leaf_model.h"
#include "lang/load_grammar.h"

namespace simeco::grow {

namespace {

// The models the scene's leaf, flower and fruit stages name, each read once from beside the scene: those read go to
// `models` and get their surface shapes; one warning names those that cannot be read (the thesis' own `.i` models).
lang::EcoModelShapes loadLeafModels(const ir::EcoScene& scene, std::vector<ir::LeafModel>& models,
                                    std::vector<ir::EcoWarning>* warnings) {
    lang::EcoModelShapes shapes;
    std::vector<std::string> unread;
    std::optional<ir::SourceLoc> firstUnread;
    std::string firstWhy;
    auto consider = [&](const ir::EcoStage& stage, bool leafStage) {
        if (!stage.model) return;
        if (auto known = shapes.find(*stage.model); known != shapes.end()) {
            models[known->second - shared::kSurfaceLastShape - 1].leaf |= leafStage;
            return;
        }
        if (std::find(unread.begin(), unread.end(), *stage.model) != unread.end()) return;
        const std::filesystem::path path = std::filesystem::path(scene.file).parent_path() / *stage.model;
        std::string why = "it is not a Wavefront .obj file";
        std::optional<ir::LeafModel> model;
        if (path.extension() == ".obj") model = lang::readObjLeafModel(path.string(), why);
        if (!model) {
            unread.push_back(*stage.model);
            if (!firstUnread) firstUnread = stage.loc, firstWhy = why;
            return;
        }
        shapes[*stage.model] = shared::kSurfaceLastShape + 1 + uint32_t(models.size());
        model->leaf = leafStage;
        models.push_back(std::move(*model));
    };
    for (const ir::EcoPlant& plant : scene.plants) {
        if (!plant.grammar.empty()) continue;
        for (ir::EcoOrganKind kind : {ir::EcoOrganKind::Leaf, ir::EcoOrganKind::Flower, ir::EcoOrganKind::Fruit}) {
            const ir::EcoOrgan& organ = plant.organ(kind);
            const bool leafStage = kind == ir::EcoOrganKind::Leaf;
            for (const auto& [number, stage] : organ.stages) consider(stage, leafStage);
            if (organ.defaultStage) consider(*organ.defaultStage, leafStage);
        }
    }
    if (!unread.empty() && warnings) {
        std::string names;
        for (const std::string& name : unread) names += (names.empty() ? "\"" : ", \"") + name + "\"";
        warnings->push_back(
            {*firstUnread, fmt::format("Model{} {} not read, drawn with the built-in organs (the first: {})",
                                       unread.size() > 1 ? "s" : "", names, firstWhy)});
    }
    return shapes;
}

} // namespace

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
    const lang::EcoModelShapes models = loadLeafModels(*scene, g.leafModels, warnings);
    std::vector<ir::Grammar> species;
    for (size_t i = 0; i < scene->plants.size(); ++i) {
        const ir::EcoPlant& plant = scene->plants[i];
        if (plant.grammar.empty()) {
            species.push_back(lang::compileEcoPlant(*scene, i, lang::EcoDrawing::Grown, &models));
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
