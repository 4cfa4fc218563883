// cpfg material files: diffuse colours by material index, and a clear error for a file of the wrong size.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "ir/source_loc.h"
#include "lang/load_grammar.h"
#include "lang/material_file.h"

namespace {

namespace fs = std::filesystem;
using namespace simeco;

fs::path writeBytes(const std::string& bytes) {
    fs::path p = fs::temp_directory_path() / ("simeco-material-" + std::to_string(::getpid()) + ".mat");
    std::ofstream(p, std::ios::binary) << bytes;
    return p;
}

TEST(MaterialFile, DiffuseColoursByIndex) {
    // Two materials, written out of order: index 7 red-diffuse, index 2 with a white ambient and black diffuse.
    std::string bytes;
    bytes += std::string("\x07\x00\x10\x10\x10\xff\x00\x00\x80\x80\x80\x00\x00\x00\x05", 15);
    bytes += std::string("\x02\x00\xff\xff\xff\x00\x00\x00\x00\x00\x00\x00\x00\x00\x00", 15);
    fs::path p = writeBytes(bytes);
    std::vector<std::array<float, 3>> palette = lang::readMaterialColors(p.string());
    fs::remove(p);
    ASSERT_EQ(palette.size(), 256u);
    EXPECT_FLOAT_EQ(palette[7][0], 1.0f);
    EXPECT_FLOAT_EQ(palette[7][1], 0.0f);
    EXPECT_FLOAT_EQ(palette[2][0], 0.0f); // the ambient is not the colour
    EXPECT_FLOAT_EQ(palette[3][0], 0.0f); // not described: black
}

TEST(MaterialFile, AFileOfTheWrongSizeIsAnInputError) {
    fs::path p = writeBytes(std::string(20, '\0'));
    try {
        lang::readMaterialColors(p.string());
        ADD_FAILURE() << "no error for 20 bytes";
    } catch (const ir::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("15 bytes"), std::string::npos) << e.what();
    }
    fs::remove(p);
}

// A corpus model shaded with materials: material 1 of 03-decussate-shaded is diffuse (0xca, 0xc6, 0x00).
TEST(MaterialFile, CorpusModelsWithoutAColourMapTakeTheirMaterials) {
    fs::path model = fs::path(SIMECO_SHARED_DIR) / "corpus" / "cpfg-vlab" / "models" / "02-Mod-vis-3D" /
                     "03-decussate-shaded" / "leaf.l";
    if (!fs::exists(model)) GTEST_FAIL() << model << " not found";
    ir::Grammar g = lang::loadGrammarFile(model.string());
    ASSERT_EQ(g.view.palette.size(), 256u);
    EXPECT_GT(g.view.palette[1][0], 0.5f);
    EXPECT_GT(g.view.palette[1][1], 0.5f);
    EXPECT_FLOAT_EQ(g.view.palette[1][2], 0.0f);
}

} // namespace
