// Leaf models read from Wavefront `.obj` files (lang/obj_leaf_model.h), and a scene's leaf stages that name them
// (grow::growingSpecies): the model in the leaf's frame, its shape given to those leaves, one warning for the
// models that cannot be read.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "field/plant_statistics.h"
#include "grow/growing_species.h"
#include "lang/eco_parser.h"
#include "lang/load_grammar.h"
#include "lang/obj_leaf_model.h"
#include "turtle/turtle_settings.h"

namespace simeco {
namespace {

namespace fs = std::filesystem;

// A folder of its own for the test's files, removed at the end.
// The surface the first model read is drawn as, and the shape the turtle draws surface `name` of `g` with
// (~0 where `g` has no such symbol).
const std::string kFirstModel = "leafModel" + std::to_string(shared::kSurfaceLastShape + 1);
uint32_t surfaceShape(const ir::Grammar& g, const std::string& name) {
    const std::optional<ir::SymbolId> symbol = g.alphabet.find(name);
    return symbol ? turtle::turtleSettings(g, g.alphabet).surfaceShape[*symbol] : ~0u;
}

class ObjLeafModel : public ::testing::Test {
protected:
    void SetUp() override {
        folder_ = fs::temp_directory_path() /
                  ("simeco-obj-" + std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
        fs::create_directories(folder_);
    }
    void TearDown() override { fs::remove_all(folder_); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(folder_ / name) << text;
        return (folder_ / name).string();
    }
    fs::path folder_;
};

// A diamond two units long along x, one wide, in two triangles facing +z.
const char* kDiamond = "v 0 0 0\nv 1 -0.5 0\nv 2 0 0\nv 1 0.5 0\nf 1 2 3\nf 1 3 4\n";

TEST_F(ObjLeafModel, AModelIsPlacedInTheLeafsFrame) {
    std::string why;
    const std::optional<ir::LeafModel> model = lang::readObjLeafModel(write("diamond.obj", kDiamond), why);
    ASSERT_TRUE(model) << why;
    ASSERT_EQ(model->corners.size(), 6u);
    ASSERT_EQ(model->normals.size(), 2u);
    float lo = 1e9f, hi = -1e9f;
    for (const auto& c : model->corners) lo = std::min(lo, c[0]), hi = std::max(hi, c[0]);
    EXPECT_FLOAT_EQ(lo, 0.0f); // its base at 0, its tip at 1: a unit of the leaf's length
    EXPECT_FLOAT_EQ(hi, 1.0f);
    EXPECT_FLOAT_EQ(model->area, 0.25f);
    for (const auto& n : model->normals) EXPECT_FLOAT_EQ(n[2], 1.0f);
    // A quad is triangulated.
    const std::optional<ir::LeafModel> quad =
        lang::readObjLeafModel(write("quad.obj", "v 0 0 0\nv 4 0 0\nv 4 1 0\nv 0 1 0\nf 1 2 3 4\n"), why);
    ASSERT_TRUE(quad) << why;
    EXPECT_EQ(quad->normals.size(), 2u);
    EXPECT_FLOAT_EQ(quad->area, 0.25f);
}

TEST_F(ObjLeafModel, FilesWithoutALeafAreRefusedWithTheirReason) {
    std::string why;
    EXPECT_FALSE(lang::readObjLeafModel((folder_ / "none.obj").string(), why));
    EXPECT_FALSE(why.empty());
    EXPECT_FALSE(lang::readObjLeafModel(write("points.obj", "v 0 0 0\nv 1 0 0\n"), why));
    EXPECT_NE(why.find("no face"), std::string::npos) << why;
    EXPECT_FALSE(lang::readObjLeafModel(write("flat.obj", "v 0 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\n"), why));
    EXPECT_NE(why.find("extent along x"), std::string::npos) << why;
    EXPECT_FALSE(lang::readObjLeafModel(write("bad.obj", "v 0 0 0\nv 1 0 0\nf 1 2 9\n"), why));
}

TEST_F(ObjLeafModel, LeafStagesNamingAModelAreDrawnWithIt) {
    write("diamond.obj", kDiamond);
    const std::string scene = write("models.eco", R"(EcoSystem 1.0 "Models" {
        Plant "Herb" {
            Leaf {
                Stage 1 { Model = "missing.obj"; }
                Stage 2 { Model = "thesis.i"; }
                Default { Model = "diamond.obj"; }
            }
            Grow { w = S(0)[L(0)][L(1)][L(2)]; }
        }
    })");
    std::vector<ir::EcoWarning> warnings;
    const grow::GrowingSpecies g = grow::growingSpecies(lang::parseEcoFile(scene), &warnings);
    ASSERT_EQ(g.assets.models.size(), 1u);
    EXPECT_FLOAT_EQ(g.assets.models[0].area, 0.25f);
    // One warning names both models that cannot be read.
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].message.find("\"missing.obj\""), std::string::npos) << warnings[0].message;
    EXPECT_NE(warnings[0].message.find("\"thesis.i\""), std::string::npos) << warnings[0].message;
    // The model's leaves have its shape, the others the built-in blade of the plant's name.
    EXPECT_EQ(surfaceShape(g.species[0], kFirstModel), shared::kSurfaceLastShape + 1);
    EXPECT_EQ(surfaceShape(g.species[0], "leaf"), shared::kLeafOvate);
}

// `simeco render` draws a scene's stages at their final sizes (lang::loadSpecies), with the same models.
TEST_F(ObjLeafModel, AScenesRenderedStagesAreDrawnWithItsModelsToo) {
    write("diamond.obj", kDiamond);
    const std::string scene = write("rendered.eco", R"(EcoSystem 1.0 "Rendered" {
        Plant "Herb" {
            Leaf { Stage 1 { Model = "diamond.obj"; } }
            Grow { w = S(0)[L(0)][L(1)]; }
        }
    })");
    ir::DrawAssets assets;
    const std::vector<ir::Grammar> species = lang::loadSpecies(scene, nullptr, &assets);
    ASSERT_EQ(assets.models.size(), 1u);
    EXPECT_EQ(surfaceShape(species[0], kFirstModel), shared::kSurfaceLastShape + 1);
    // Without a place for the models, the stages keep the built-in blade.
    const std::vector<ir::Grammar> plain = lang::loadSpecies(scene);
    EXPECT_FALSE(plain[0].alphabet.find(kFirstModel));
}

TEST_F(ObjLeafModel, FlowersAreBlossomsOfThePlantsNameOrTheirModelAndNoLeafArea) {
    write("diamond.obj", kDiamond);
    const std::string scene = write("flowers.eco", R"(EcoSystem 1.0 "Flowers" {
        Plant "Lantana camara" {
            Flower { Stage 1 { Model = "diamond.obj"; } }
            Grow { w = S(0)[F(0)][F(1)]; }
        }
    })");
    const grow::GrowingSpecies g = grow::growingSpecies(lang::parseEcoFile(scene));
    ASSERT_EQ(g.assets.models.size(), 1u);
    EXPECT_FALSE(g.assets.models[0].leaf);
    EXPECT_EQ(surfaceShape(g.species[0], kFirstModel), shared::kSurfaceLastShape + 1);
    EXPECT_EQ(surfaceShape(g.species[0], "blossom"), shared::kBlossomHead);
    // Neither a blossom nor a flower's model counts as leaf area; the blades do.
    const std::vector<float> areas = field::leafShapeAreas(g.assets.models);
    ASSERT_EQ(areas.size(), shared::kSurfaceLastShape + 2u);
    EXPECT_GT(areas[shared::kLeafSerrate], 0.1f);
    for (uint32_t shape = shared::kLeafLastShape + 1; shape < areas.size(); ++shape) EXPECT_EQ(areas[shape], 0.0f);
}

} // namespace
} // namespace simeco
