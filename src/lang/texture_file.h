// Reads a stage's Texture: a PNG (Debian's libpng) or an uncompressed Windows bitmap (`.bmp`, 24 or 32 bits per
// pixel, as the SimEco thesis' textures are).
#pragma once

#include <optional>
#include <string>

#include "ir/draw_assets.h"

namespace simeco::lang {

// Nullopt, with the reason in `why`, for a file that cannot be read as either.
std::optional<ir::TextureImage> readTextureFile(const std::string& path, std::string& why);

} // namespace simeco::lang
