#include "ir/picture_look.h"

namespace simeco::ir {

std::optional<PictureStyle> pictureStyleNamed(std::string_view name) {
    if (name == "lit") return PictureStyle::Lit;
    if (name == "toon") return PictureStyle::Toon;
    if (name == "outline") return PictureStyle::Outline;
    if (name == "paper-cut") return PictureStyle::PaperCut;
    return std::nullopt;
}

} // namespace simeco::ir
