// What a scene's stages draw with besides the built-in meshes and their colours: the `.obj` models their `Model`s
// name and the images their `Texture`s name, read by the scene front end (lang/eco_assets.h) for the renderer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ir/leaf_model.h"

namespace simeco::ir {

// An image as read from its file: rows from the top, 8-bit sRGB red, green, blue and alpha per pixel.
struct TextureImage {
    std::string file;
    uint32_t width = 0, height = 0;
    std::vector<uint8_t> rgba;
};

struct DrawAssets {
    std::vector<LeafModel> models;      // model k is surface shape kSurfaceLastShape + 1 + k
    std::vector<TextureImage> textures; // image k is texture layer k (OrganInstance.color.w, organ_layout.h)
};

} // namespace simeco::ir
