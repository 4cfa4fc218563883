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

} // namespace simeco::lang
