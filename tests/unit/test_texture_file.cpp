// A stage's Texture read from its file (PNG or Windows bitmap), and a scene's stages tinting the textures read.
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <png.h>

#include "compute/shared/organ_layout.h"
#include "grow/growing_species.h"
#include "lang/eco_parser.h"
#include "lang/texture_file.h"
#include "turtle/turtle_settings.h"

namespace simeco {
namespace {

class TextureFile : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = std::filesystem::temp_directory_path() /
                  ("simeco-texture-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        std::filesystem::create_directories(folder_);
    }
    void TearDown() override { std::filesystem::remove_all(folder_); }
    std::string path(const std::string& name) const { return (folder_ / name).string(); }
    std::string write(const std::string& name, const std::vector<uint8_t>& bytes) const {
        std::ofstream(path(name), std::ios::binary)
            .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
        return path(name);
    }

    std::filesystem::path folder_;
};

// A 3 x 2 bitmap of `bits` bits per pixel: top row red, green, blue; bottom row white, black, grey; stored from
// the bottom up, each row padded to four bytes.
std::vector<uint8_t> bitmap(uint32_t bits) {
    const uint8_t top[3][3] = {{255, 0, 0}, {0, 255, 0}, {0, 0, 255}}, bottom[3][3] = {{255, 255, 255}, {0, 0, 0},
                                                                                       {128, 128, 128}};
    const size_t rowBytes = (3 * bits / 8 + 3) / 4 * 4;
    std::vector<uint8_t> b(54 + 2 * rowBytes, 0);
    auto put = [&](size_t at, uint32_t v, size_t bytes) {
        for (size_t k = 0; k < bytes; ++k) b[at + k] = uint8_t(v >> (8 * k));
    };
    b[0] = 'B', b[1] = 'M';
    put(2, uint32_t(b.size()), 4), put(10, 54, 4), put(14, 40, 4), put(18, 3, 4), put(22, 2, 4), put(26, 1, 2);
    put(28, bits, 2);
    for (size_t row = 0; row < 2; ++row)
        for (size_t x = 0; x < 3; ++x) {
            const uint8_t* rgb = row == 0 ? bottom[x] : top[x];
            uint8_t* p = &b[54 + row * rowBytes + x * bits / 8];
            p[0] = rgb[2], p[1] = rgb[1], p[2] = rgb[0];
        }
    return b;
}

TEST_F(TextureFile, BitmapsAreReadTopRowFirstInRgba) {
    for (uint32_t bits : {24u, 32u}) {
        std::string why;
        const std::optional<ir::TextureImage> image = lang::readTextureFile(write("rgb.bmp", bitmap(bits)), why);
        ASSERT_TRUE(image) << why;
        ASSERT_EQ(image->width, 3u);
        ASSERT_EQ(image->height, 2u);
        const std::vector<uint8_t> want = {255, 0,   0,   255, 0, 255, 0, 255, 0,   0,   255, 255,
                                           255, 255, 255, 255, 0, 0,   0, 255, 128, 128, 128, 255};
        EXPECT_EQ(image->rgba, want) << bits << " bits";
    }
}

TEST_F(TextureFile, PngsAreReadWithTheirAlpha) {
    const std::vector<uint8_t> pixels = {10, 20, 30, 0, 200, 100, 50, 255};
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = 2;
    image.height = 1;
    image.format = PNG_FORMAT_RGBA;
    ASSERT_TRUE(png_image_write_to_file(&image, path("two.png").c_str(), 0, pixels.data(), 0, nullptr));
    std::string why;
    const std::optional<ir::TextureImage> read = lang::readTextureFile(path("two.png"), why);
    ASSERT_TRUE(read) << why;
    EXPECT_EQ(read->width, 2u);
    EXPECT_EQ(read->height, 1u);
    EXPECT_EQ(read->rgba, pixels);
}

TEST_F(TextureFile, OtherFilesAreRefusedWithTheirReason) {
    std::string why;
    EXPECT_FALSE(lang::readTextureFile(path("none.png"), why));
    EXPECT_NE(why.find("no such file"), std::string::npos) << why;
    EXPECT_FALSE(lang::readTextureFile(write("text.png", {'n', 'o', 't'}), why));
    EXPECT_NE(why.find("not a PNG"), std::string::npos) << why;
    std::vector<uint8_t> eightBits = bitmap(24);
    eightBits[28] = 8;
    EXPECT_FALSE(lang::readTextureFile(write("palette.bmp", eightBits), why));
    EXPECT_NE(why.find("8 bits"), std::string::npos) << why;
    std::vector<uint8_t> cut = bitmap(24);
    cut.resize(60);
    EXPECT_FALSE(lang::readTextureFile(write("cut.bmp", cut), why));
    EXPECT_NE(why.find("shorter"), std::string::npos) << why;
    EXPECT_FALSE(lang::readTextureFile(write("leaf.tga", {0, 0}), why));
    EXPECT_NE(why.find(".png or .bmp"), std::string::npos) << why;
}

TEST_F(TextureFile, AStagesTextureTintedByItsColourIsItsPaletteEntrysLayer) {
    write("rgb.bmp", bitmap(24));
    std::ofstream(path("scene.eco")) << R"(EcoSystem 1.0 "Textures" {
        Plant "Herb" {
            Stem { Default { Texture = "rgb.bmp"; Color = RGBA(0.5, 0.5, 0.5, 1.0); } }
            Leaf {
                Stage 0 { Texture = "rgb.bmp"; }
                Stage 1 { Texture = "gone.bmp"; }
            }
            Grow { w = S(0)[L(0)][L(1)]; }
        }
    })";
    std::vector<ir::EcoWarning> warnings;
    const grow::GrowingSpecies g = grow::growingSpecies(lang::parseEcoFile(path("scene.eco")), &warnings);
    ASSERT_EQ(g.assets.textures.size(), 1u); // read once for both stages
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].message.find("\"gone.bmp\""), std::string::npos) << warnings[0].message;
    const ir::Grammar& herb = g.species[0];
    const turtle::TurtleSettings t = turtle::turtleSettings(herb, herb.alphabet);
    // Some palette entries tint layer 0, the others none.
    int textured = 0;
    for (const glm::vec4& c : t.palette) {
        EXPECT_TRUE(c.w == shared::kColorUntextured || c.w == shared::kColorFirstTexture) << c.w;
        textured += c.w == shared::kColorFirstTexture ? 1 : 0;
    }
    // The stem's colour; the leaf stage's, white, and its three shades (mature, young, old).
    EXPECT_EQ(textured, 5);
}

} // namespace
} // namespace simeco
