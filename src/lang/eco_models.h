// The model files a scene's stages name (`Model = "file.obj"`), read for the renderer.
#pragma once

#include <string>
#include <vector>

#include "ir/eco_scene.h"
#include "ir/leaf_model.h"
#include "lang/eco_geometry.h"

namespace simeco::lang {

// The models the scene's leaf, flower and fruit stages name, each read once from beside the scene: those read go to
// `models` and get their surface shapes; one warning names those that cannot be read (the thesis' own `.i` models).
EcoModelShapes loadEcoModels(const ir::EcoScene& scene, std::vector<ir::LeafModel>& models,
                             std::vector<ir::EcoWarning>* warnings);

} // namespace simeco::lang
