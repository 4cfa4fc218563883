// How a picture of a model looks, as its view file may ask in simeco's own lines (`render style:`, `shadows:`,
// `ground:`, `background:`); the command line's options override them.
#pragma once

#include <array>
#include <optional>
#include <string_view>

namespace simeco::ir {

enum class PictureStyle {
    Lit,      // Lambert sun and hemisphere sky light
    Toon,     // the same light in colour bands
    Outline,  // toon bands with ink outlines along silhouettes and creases (depth edges)
    PaperCut, // flat colour where the sun reaches, the paper showing through elsewhere and along every edge
};

// "lit", "toon", "outline", "paper-cut"; none for another name.
std::optional<PictureStyle> pictureStyleNamed(std::string_view name);

// What shows where nothing is drawn.
struct Background {
    enum class Kind {
        Sky,      // the renderer's pale blue
        Paper,    // a warm off-white, as decorative paper
        Colormap, // the model colour map's entry 0, as cpfg clears its window
        Color,    // a colour given as #rrggbb
    };
    Kind kind = Kind::Sky;
    std::array<float, 3> color{}; // linear RGB, for Kind::Color
};

struct PictureLook {
    // cpfg's `viewpoint:` and `view reference point:`, where a view gives either (each defaults to the other's
    // default: 0,0,1 and the origin); the camera looks from the one towards the other, framed on the plants.
    std::optional<std::array<float, 3>> viewpoint;
    std::optional<std::array<float, 3>> viewReferencePoint;
    std::optional<bool> parallel; // cpfg's `projection: parallel` (else perspective)
    std::optional<PictureStyle> style;
    std::optional<bool> shadows; // the sun's shadow volumes
    std::optional<bool> ground;
    std::optional<Background> background;
    // cpfg's first directional `light: V: x,y,z` (or `light direction:`): toward the light, which the sun becomes.
    std::optional<std::array<float, 3>> sunDirection;
};

} // namespace simeco::ir
