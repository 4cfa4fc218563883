// Loading a grammar file of any supported language into the IR, chosen by the file's extension.
#pragma once

#include <string>
#include <vector>

#include "ir/eco_scene.h"
#include "ir/grammar.h"
#include "ir/draw_assets.h"

namespace simeco::lang {

// The one entry point for every input language, chosen by the file's extension: `.l`: cpfg / L-studio (with the
// model's view file from the same folder, when there is one); `.lsys`: quick (Houdini-style) grammar; `.eco`:
// SimEco scene, one grammar per plant (species) of the scene, its warnings added to `warnings` when given. With
// `assets`, the models and textures a scene's stages name are read into it and draw those stages' organs
// (lang/eco_assets.h).
std::vector<ir::Grammar> loadSpecies(const std::string& path, std::vector<ir::EcoWarning>* warnings = nullptr,
                                     ir::DrawAssets* assets = nullptr);

// The grammar of a scene's plant that names a Grammar file (relative to the scene's folder).
ir::Grammar loadScenePlantGrammar(const ir::EcoScene& scene, const ir::EcoPlant& plant,
                                  std::vector<ir::EcoWarning>* warnings = nullptr);

// The first of loadSpecies(path): the grammar of an `.l` or `.lsys` file, or an `.eco` scene's first plant.
ir::Grammar loadGrammarFile(const std::string& path);

// The cpfg view file that belongs to an `.l` file: `<name>.v` beside it, else the only `.v` there.
std::string findViewFile(const std::string& lsystemPath);
// A file of the model with that extension (".map"): `<name><extension>` beside it, else the only one there.
std::string findModelFile(const std::string& lsystemPath, const std::string& extension);

} // namespace simeco::lang
