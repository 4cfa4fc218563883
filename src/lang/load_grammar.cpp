#include "lang/load_grammar.h"

#include <filesystem>

#include <fmt/format.h>

#include "compute/shared/organ_layout.h"

#include "lang/color_map.h"
#include "lang/cpfg_parser.h"
#include "lang/cpfg_preprocessor.h"
#include "lang/cpfg_view.h"
#include "lang/eco_assets.h"
#include "lang/eco_parser.h"
#include "lang/material_file.h"
#include "lang/quick_grammar.h"
#include "lang/source_text.h"

namespace simeco::lang {

namespace fs = std::filesystem;

std::string findViewFile(const std::string& lsystemPath) {
    return findModelFile(lsystemPath, ".v");
}

std::string findModelFile(const std::string& lsystemPath, const std::string& extension) {
    fs::path path(lsystemPath);
    fs::path sameName = path.parent_path() / (path.stem().string() + extension);
    std::error_code ec;
    if (fs::is_regular_file(sameName, ec)) return sameName.string();
    std::string only;
    fs::path dir = path.parent_path().empty() ? fs::path(".") : path.parent_path();
    for (const fs::directory_entry& entry : fs::directory_iterator(dir, ec)) {
        if (entry.path().extension() != extension) continue;
        if (!only.empty()) return {}; // several such files: none is clearly this model's
        only = entry.path().string();
    }
    return only;
}

namespace {

ir::Grammar loadCpfgModel(const std::string& path) {
    CpfgView view;
    std::string viewPath = findViewFile(path);
    if (!viewPath.empty()) view = readCpfgView(viewPath);
    ir::Grammar g = parseCpfg(preprocessFile(path, view.macros), std::move(view.functions));
    g.view = view.view;
    g.curves = std::move(view.curves);
    // A model is coloured by its colour map (`cpfg -m`) or, without one, by its materials (`cpfg -M`).
    if (std::string map = findModelFile(path, ".map"); !map.empty()) g.view.palette = readColorMap(map);
    else if (std::string mat = findModelFile(path, ".mat"); !mat.empty()) g.view.palette = readMaterialColors(mat);
    return g;
}

// The `.s` surfaces a model's view read become models the renderer draws, and their shapes.
void addSurfaceModels(ir::Grammar& g, ir::DrawAssets& assets) {
    for (ir::ViewSettings::Surface& surface : g.view.surfaces) {
        if (!surface.model || surface.shape) continue;
        surface.shape = shared::kSurfaceLastShape + 1 + static_cast<uint32_t>(assets.models.size());
        assets.models.push_back(surface.model->mesh);
    }
}

} // namespace

ir::Grammar loadScenePlantGrammar(const ir::EcoScene& scene, const ir::EcoPlant& plant,
                                  std::vector<ir::EcoWarning>* warnings) {
    const fs::path path = fs::path(scene.file).parent_path() / plant.grammar;
    const std::string extension = path.extension().string();
    if (extension != ".l" && extension != ".lsys")
        throw ir::InputError(plant.grammarLoc,
                             fmt::format("a plant's Grammar is a cpfg .l or quick .lsys file, not {}", path.string()));
    if (!fs::is_regular_file(path))
        throw ir::InputError(plant.grammarLoc, fmt::format("cannot open the grammar file {}", path.string()));
    return loadSpecies(path.string(), warnings).front();
}

std::vector<ir::Grammar> loadSpecies(const std::string& path, std::vector<ir::EcoWarning>* warnings,
                                     ir::DrawAssets* assets) {
    std::string ext = fs::path(path).extension().string();
    std::vector<ir::Grammar> species;
    if (ext == ".eco") {
        ir::EcoScene scene = parseEcoFile(path);
        if (warnings) warnings->insert(warnings->end(), scene.warnings.begin(), scene.warnings.end());
        if (scene.plants.empty()) throw ir::InputError(scene.loc, "the scene has no plant");
        const EcoAssets found = assets ? loadEcoAssets(scene, *assets, warnings) : EcoAssets{};
        for (size_t i = 0; i < scene.plants.size(); ++i)
            species.push_back(scene.plants[i].grammar.empty()
                                  ? compileEcoPlant(scene, i, EcoDrawing::Final, &found)
                                  : loadScenePlantGrammar(scene, scene.plants[i], warnings));
    } else if (ext == ".lsys") {
        species.push_back(parseQuickGrammar(readSourceFile(path), path));
    } else if (ext == ".l") {
        species.push_back(loadCpfgModel(path));
    } else {
        throw ir::InputError({path, 0, 0},
                             fmt::format("unknown grammar file type '{}' (expected .l, .lsys or .eco)", ext));
    }
    if (assets)
        for (ir::Grammar& g : species) addSurfaceModels(g, *assets);
    return species;
}

ir::Grammar loadGrammarFile(const std::string& path) {
    return std::move(loadSpecies(path).front());
}

} // namespace simeco::lang
