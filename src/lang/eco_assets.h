// The model and texture files a scene's stages name (`Model = "leaf.obj"; Texture = "leaf.png";`), read for the
// renderer, and which surface shape and texture layer each name stands for in the compiled plants.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "ir/draw_assets.h"
#include "ir/eco_scene.h"

namespace simeco::lang {

struct EcoAssets {
    std::map<std::string, uint32_t> modelShapes;   // a Model as the script writes it: its surface shape
    std::map<std::string, uint32_t> textureLayers; // a Texture as the script writes it: its texture layer
};

// The models the scene's leaf, flower and fruit stages name and the textures any stage names, each read once from
// beside the scene into `assets`; one warning names the models that cannot be read (the thesis' own `.i` models)
// and one the textures.
EcoAssets loadEcoAssets(const ir::EcoScene& scene, ir::DrawAssets& assets, std::vector<ir::EcoWarning>* warnings);

} // namespace simeco::lang
