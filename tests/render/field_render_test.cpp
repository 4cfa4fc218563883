// End to end on the device: a field of plants derived and interpreted by the reference turtle, rendered, and
// the frame checked against the turtle's geometry: every plant placed shows with its id, and the silhouette
// spans where the projected segments lie.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "cpu/derive.h"
#include "draw/renderer.h"
#include "field/field_parts.h"
#include "same_organs.h"
#include "gpu_fixture.h"
#include "lang/load_grammar.h"
#include "test_scene.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"

namespace {

using namespace simeco;

class FieldRender : public test::GpuTest {};

TEST_F(FieldRender, PlantsShowWithTheirIdsWhereTheTurtlePutThem) {
    ir::Grammar g = lang::loadGrammarFile(std::string(SIMECO_SOURCE_DIR) + "/grammars/abop/fig1.24d.l");
    stream::DeriveOptions options;
    options.plants = 4;
    options.steps = 4;
    options.homomorphism = true;
    stream::ModuleString string = cpu::deriveCpu(g, options).string;
    turtle::Interpretation interp = turtle::interpretCpu(string, turtle::turtleCommands(g.alphabet),
                                                         {turtle::turtleSettings(g, g.alphabet)});
    ASSERT_GT(interp.count[shared::kOrganStem], 0u);

    test::TestScene scene = test::uploadScene(context(), interp.organs);
    draw::RenderSettings settings;
    settings.width = 320;
    settings.height = 240;
    settings.shadows = draw::Shadows::None;
    draw::Renderer renderer(context());
    draw::Frame frame = renderer.render(scene.instances, scene.table, scene.bounds, settings);
    test::maybeSavePreview(frame, "field_of_four");

    std::set<uint32_t> plantsSeen, modulesDrawn, modulesSeen;
    for (const shared::OrganInstance& o : interp.organs) modulesDrawn.insert(o.module);
    for (size_t i = 0; i < frame.pixelCount(); ++i) {
        if (frame.plant[i] == draw::Frame::kNoId) continue;
        plantsSeen.insert(frame.plant[i]);
        modulesSeen.insert(frame.organ[i]);
    }
    EXPECT_EQ(plantsSeen, (std::set<uint32_t>{0, 1, 2, 3}));
    for (uint32_t m : modulesSeen) EXPECT_TRUE(modulesDrawn.count(m)) << "organ id " << m << " drew nothing";

    // The silhouette's box against the box of the projected segment ends (a margin for the stems' radius).
    draw::CameraView camera = draw::frameCamera(scene.bounds, settings);
    float minX = 1e9f, minY = 1e9f, maxX = -1e9f, maxY = -1e9f;
    for (const shared::OrganInstance& o : interp.organs) {
        glm::vec3 base(o.position.x, o.position.y, o.position.z), heading(o.heading.x, o.heading.y, o.heading.z);
        for (glm::vec3 p : {base, base + heading * o.position.w}) {
            glm::vec2 px = test::projectToPixel(camera, p, settings.width, settings.height);
            minX = std::min(minX, px.x), maxX = std::max(maxX, px.x);
            minY = std::min(minY, px.y), maxY = std::max(maxY, px.y);
        }
    }
    test::PixelBox box = test::organPixels(frame);
    ASSERT_FALSE(box.empty());
    const float margin = 4.0f;
    EXPECT_NEAR(box.minX, minX, margin);
    EXPECT_NEAR(box.maxX, maxX, margin);
    EXPECT_NEAR(box.minY, minY, margin);
    EXPECT_NEAR(box.maxY, maxY, margin);
}

// ABOP's figure 2.6 tree without a view file is in cpfg's default pixel lines: a slender tree whose trunk, 10 pixels
// wide, is a small share of its height; with a view that sets the width alone (world units) its trunk is 10 units
// wide, as tall as the tree.
TEST_F(FieldRender, ATreeWithoutAViewIsDrawnInPixelLines) {
    namespace fs = std::filesystem;
    const fs::path copy = fs::temp_directory_path() / ("simeco-pixel-lines-" + std::to_string(::getpid()));
    fs::create_directories(copy);
    fs::copy_file(fs::path(SIMECO_SOURCE_DIR) / "grammars/abop/fig2.6-monopodial.l", copy / "tree.l",
                  fs::copy_options::overwrite_existing);
    auto trunkShare = [&](const std::string& name) {
        ir::Grammar g = lang::loadGrammarFile((copy / "tree.l").string());
        stream::DeriveOptions options;
        options.homomorphism = true;
        stream::ModuleString string = cpu::deriveCpu(g, options).string;
        turtle::Interpretation interp = turtle::interpretCpu(string, turtle::turtleCommands(g.alphabet),
                                                             {turtle::turtleSettings(g, g.alphabet)});
        test::TestScene scene = test::uploadScene(context(), interp.organs);
        draw::RenderSettings settings;
        settings.width = 240;
        settings.height = 240;
        settings.shadows = draw::Shadows::None;
        settings.ground = false;
        draw::Renderer renderer(context());
        // Framed as simeco frames the field: on the turtle's bounds, which hold a pixel line's ends only.
        const draw::Bounds bounds{interp.bounds.min, interp.bounds.max};
        draw::Frame frame = renderer.render(scene.instances, scene.table, bounds, settings);
        test::maybeSavePreview(frame, name);
        // The trunk's first segment (the string's first F, module 1): its widest row against the tree's height.
        test::PixelBox tree = test::organPixels(frame);
        int widest = 0;
        for (uint32_t y = 0; y < frame.height; ++y) {
            int row = 0;
            for (uint32_t x = 0; x < frame.width; ++x) row += frame.organ[frame.index(x, y)] == 1u ? 1 : 0;
            widest = std::max(widest, row);
        }
        return float(widest) / float(tree.maxY - tree.minY + 1);
    };
    const float pixelLines = trunkShare("fig2.6_pixel_lines");
    std::ofstream(copy / "tree.v") << "angle increment: 45\ninitial line width: 1\n";
    const float worldWidths = trunkShare("fig2.6_world_widths");
    fs::remove_all(copy);
    EXPECT_GT(pixelLines, 0.0f);
    EXPECT_LT(pixelLines, 0.08f);
    EXPECT_GT(worldWidths, 0.5f);
}

// A field too large for one interpretation is interpreted in batches of plants copied out of its derived string,
// standing where one interpretation puts them: the organs of the batches, merged, are the organs of one.
TEST_F(FieldRender, AFieldInBatchesIsInterpretedAsInOne) {
    field::FieldSource source;
    source.file = std::string(SIMECO_SOURCE_DIR) + "/grammars/abop/fig2.8-ternary.l";
    source.plants = 7;
    source.steps = 3;
    field::Field whole = field::deriveField(source, &context());
    const turtle::Interpretation want =
        turtle::readBack(context(), *field::interpretInParts(source, whole, context()).front(), 7);
    field::Field cut = field::deriveField(source, &context());
    // About two plants' modules per batch: four batches.
    const std::vector<const turtle::DeviceOrgans*> parts =
        field::interpretInParts(source, cut, context(), cut.modules / 7 * 2 + 1);
    ASSERT_EQ(parts.size(), 1u); // the batches' organs fit one binding
    const turtle::Interpretation got = turtle::readBack(context(), *parts.front(), 7);
    ASSERT_GT(want.organs.size(), 100u);
    EXPECT_EQ(test::organDifference(want, got), "");
}

} // namespace
