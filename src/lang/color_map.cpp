#include "lang/color_map.h"

#include <cmath>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "ir/grammar.h"

namespace simeco::lang {

float srgbToLinear(float c) {
    return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f);
}

std::vector<std::array<float, 3>> readColorMap(const std::string& path) {
    constexpr size_t kColors = 256;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ir::InputError({path, 0, 0}, "cannot open file");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw ir::InputError({path, 0, 0}, "cannot read file");
    if (bytes.size() != kColors * 3)
        throw ir::InputError({path, 0, 0}, fmt::format("a colour map has 768 bytes (256 RGB colours), this one {}",
                                                       bytes.size()));
    std::vector<std::array<float, 3>> palette(kColors);
    for (size_t i = 0; i < kColors; ++i)
        for (size_t c = 0; c < 3; ++c)
            palette[i][c] = srgbToLinear(static_cast<unsigned char>(bytes[i * 3 + c]) / 255.0f);
    return palette;
}

void useColorMap(std::vector<ir::Grammar>& species, const std::string& path) {
    const std::vector<std::array<float, 3>> palette = readColorMap(path);
    for (ir::Grammar& g : species) {
        g.view.palette = palette;
        g.view.paletteTextures.clear();
    }
}

std::optional<ir::Background> backgroundNamed(std::string_view name) {
    ir::Background b;
    if (name == "sky") return b;
    if (name == "paper" || name == "colormap") {
        b.kind = name == "paper" ? ir::Background::Kind::Paper : ir::Background::Kind::Colormap;
        return b;
    }
    if (name.size() != 7 || name[0] != '#') return std::nullopt;
    unsigned rgb = 0;
    for (char c : name.substr(1)) {
        int digit = c >= '0' && c <= '9' ? c - '0' : c >= 'a' && c <= 'f' ? c - 'a' + 10 : -1;
        if (c >= 'A' && c <= 'F') digit = c - 'A' + 10;
        if (digit < 0) return std::nullopt;
        rgb = rgb * 16 + static_cast<unsigned>(digit);
    }
    b.kind = ir::Background::Kind::Color;
    for (int c = 0; c < 3; ++c)
        b.color[size_t(c)] = srgbToLinear(static_cast<float>((rgb >> (16 - 8 * c)) & 0xFFu) / 255.0f);
    return b;
}

} // namespace simeco::lang
