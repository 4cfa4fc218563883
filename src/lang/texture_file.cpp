#include "lang/texture_file.h"

#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>
#include <png.h>

namespace simeco::lang {

namespace {

// Textures larger than this on a side are refused rather than held in memory (the renderer samples them at 256).
constexpr uint32_t kLargestSide = 8192;

std::optional<ir::TextureImage> readPng(const std::string& path, std::string& why) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&image, path.c_str())) {
        why = fmt::format("not a PNG file ({})", image.message);
        return std::nullopt;
    }
    if (image.width == 0 || image.height == 0 || image.width > kLargestSide || image.height > kLargestSide) {
        png_image_free(&image);
        why = fmt::format("{}x{} pixels: each side must be 1 to {}", image.width, image.height, kLargestSide);
        return std::nullopt;
    }
    image.format = PNG_FORMAT_RGBA;
    ir::TextureImage texture;
    texture.width = image.width;
    texture.height = image.height;
    texture.rgba.resize(size_t(PNG_IMAGE_SIZE(image)));
    if (!png_image_finish_read(&image, nullptr, texture.rgba.data(), 0, nullptr)) {
        why = fmt::format("a broken PNG file ({})", image.message);
        png_image_free(&image);
        return std::nullopt;
    }
    return texture;
}

uint32_t little(const std::vector<uint8_t>& b, size_t at, size_t bytes) {
    uint32_t v = 0;
    for (size_t k = 0; k < bytes; ++k) v |= uint32_t(b[at + k]) << (8 * k);
    return v;
}

std::optional<ir::TextureImage> readBmp(const std::string& path, std::string& why) {
    std::ifstream file(path, std::ios::binary);
    const std::vector<uint8_t> b((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    if (b.size() < 54 || b[0] != 'B' || b[1] != 'M') {
        why = "not a Windows bitmap";
        return std::nullopt;
    }
    const uint32_t pixels = little(b, 10, 4), header = little(b, 14, 4);
    const int32_t width = int32_t(little(b, 18, 4)), signedHeight = int32_t(little(b, 22, 4));
    const uint32_t bits = little(b, 28, 2), compression = little(b, 30, 4);
    if (header < 40 || (bits != 24 && bits != 32) || (compression != 0 && compression != 3)) {
        why = fmt::format("a bitmap of {} bits per pixel, compression {}: only uncompressed 24 and 32 bits are read",
                          bits, compression);
        return std::nullopt;
    }
    const uint32_t height = uint32_t(signedHeight < 0 ? -int64_t(signedHeight) : signedHeight);
    if (width <= 0 || height == 0 || uint32_t(width) > kLargestSide || height > kLargestSide) {
        why = fmt::format("{}x{} pixels: each side must be 1 to {}", width, height, kLargestSide);
        return std::nullopt;
    }
    const size_t rowBytes = (size_t(width) * bits / 8 + 3) / 4 * 4;
    if (pixels > b.size() || b.size() - pixels < rowBytes * height) {
        why = "a bitmap shorter than its pixels";
        return std::nullopt;
    }
    ir::TextureImage texture;
    texture.width = uint32_t(width);
    texture.height = height;
    texture.rgba.resize(size_t(width) * height * 4);
    for (uint32_t y = 0; y < height; ++y) {
        // Rows are stored from the bottom unless the height is negative.
        const size_t row = pixels + rowBytes * (signedHeight < 0 ? y : height - 1 - y);
        for (uint32_t x = 0; x < uint32_t(width); ++x) {
            const uint8_t* p = &b[row + size_t(x) * bits / 8]; // blue, green, red (, alpha)
            uint8_t* out = &texture.rgba[(size_t(y) * uint32_t(width) + x) * 4];
            out[0] = p[2];
            out[1] = p[1];
            out[2] = p[0];
            out[3] = 255;
        }
    }
    return texture;
}

} // namespace

std::optional<ir::TextureImage> readTextureFile(const std::string& path, std::string& why) {
    if (!std::filesystem::is_regular_file(path)) {
        why = "no such file";
        return std::nullopt;
    }
    std::string extension = std::filesystem::path(path).extension().string();
    for (char& c : extension) c = char(std::tolower(static_cast<unsigned char>(c)));
    std::optional<ir::TextureImage> texture;
    if (extension == ".png") texture = readPng(path, why);
    else if (extension == ".bmp") texture = readBmp(path, why);
    else why = "not a .png or .bmp file";
    if (texture) texture->file = path;
    return texture;
}

} // namespace simeco::lang
