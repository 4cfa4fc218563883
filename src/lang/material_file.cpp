#include "lang/material_file.h"

#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "ir/source_loc.h"
#include "lang/color_map.h"

namespace simeco::lang {

std::vector<std::array<float, 3>> readMaterialColors(const std::string& path) {
    constexpr size_t kMaterials = 256, kRecord = 15, kDiffuse = 5;
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ir::InputError({path, 0, 0}, "cannot open file");
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (in.bad()) throw ir::InputError({path, 0, 0}, "cannot read file");
    if (bytes.empty() || bytes.size() % kRecord != 0 || bytes.size() > kMaterials * kRecord)
        throw ir::InputError({path, 0, 0}, fmt::format("a material file holds up to 256 materials of 15 bytes, "
                                                       "this one has {} bytes",
                                                       bytes.size()));
    std::vector<std::array<float, 3>> palette(kMaterials, {0.0f, 0.0f, 0.0f});
    for (size_t offset = 0; offset < bytes.size(); offset += kRecord) {
        size_t index = static_cast<unsigned char>(bytes[offset]);
        for (size_t c = 0; c < 3; ++c)
            palette[index][c] = srgbToLinear(static_cast<unsigned char>(bytes[offset + kDiffuse + c]) / 255.0f);
    }
    return palette;
}

} // namespace simeco::lang
