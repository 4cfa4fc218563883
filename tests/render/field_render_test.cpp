// End to end on the device: a field of plants derived and interpreted by the reference turtle, rendered, and
// the frame checked against the turtle's geometry: every plant placed shows with its id, and the silhouette
// spans where the projected segments lie.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

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
