// One tick of a field recorded into one submission: the turtle kernels interpret again the string the
// derivation left on the device and the renderer draws their organs into its target, with no host read or wait
// inside; the frame equals the one the blocking calls draw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "compute/shared/organ_layout.h"
#include "draw/bounds.h"
#include "draw/renderer.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "lang/load_grammar.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_gpu.h"
#include "turtle/turtle_settings.h"
#include "vk/buffer.h"

namespace {

using namespace simeco;

class FieldTick : public test::GpuTest {};

TEST_F(FieldTick, ATickRecordedInOneSubmissionDrawsWhatTheBlockingCallsDraw) {
    ir::Grammar g = lang::loadGrammarFile(std::string(SIMECO_SOURCE_DIR) + "/grammars/abop/fig2.8-ternary.l");
    stream::DeriveOptions options;
    options.plants = 100;
    options.steps = 3;
    gpu::GpuDeriver deriver(context(), g);
    deriver.derive(options, /*readBack=*/false);
    stream::DeviceModules modules = deriver.lastString();
    ASSERT_EQ(modules.plants, 100u);

    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    const turtle::DeviceOrgans& organs = turtle.interpret(modules, {});
    shared::OrganTable table = vk::downloadVector<shared::OrganTable>(context(), organs.table, 1)[0];
    draw::Bounds bounds = draw::decodeBounds(table);
    draw::RenderSettings settings;
    settings.width = 240;
    settings.height = 180;
    settings.shadows = draw::Shadows::Volume;
    draw::Renderer renderer(context());
    draw::Frame blocking = renderer.render(organs.instances, organs.table, bounds, settings);

    // The tick's host part comes first, from what the last interpretation left (the organ counts that size the
    // shadow volumes); then nothing of the blocking run is left for the tick to show.
    draw::FrameSetup setup = renderer.prepare(organs.table, bounds, settings);
    const draw::RenderTarget& target = renderer.offscreenTarget(settings.width, settings.height);
    context().submitAndWait([&](VkCommandBuffer cmd) {
        for (const vk::Buffer* b : {&organs.instances, &organs.table, &target.color(), &target.depth(),
                                    &target.plant(), &target.organ()})
            vk::cmdFill(cmd, *b, 0);
    });

    context().submitAndWait([&](VkCommandBuffer cmd) {
        const turtle::DeviceOrgans& ticked = turtle.record(cmd, modules, {});
        renderer.record(cmd, target, ticked.instances, ticked.table, setup);
    });
    draw::Frame tick = renderer.readBack(target, setup);

    ASSERT_EQ(tick.pixelCount(), blocking.pixelCount());
    EXPECT_TRUE(tick.plant == blocking.plant);
    EXPECT_TRUE(tick.organ == blocking.organ);
    float largest = 0;
    for (size_t i = 0; i < tick.rgba.size(); ++i) largest = std::max(largest, std::abs(tick.rgba[i] - blocking.rgba[i]));
    EXPECT_LE(largest, 1e-6f);
    // A field, not an empty frame that equals another empty frame.
    std::set<uint32_t> plantsSeen(tick.plant.begin(), tick.plant.end());
    plantsSeen.erase(draw::Frame::kNoId);
    EXPECT_GT(plantsSeen.size(), 50u);
}

TEST_F(FieldTick, RecordingAStringTheTurtleHasNotInterpretedIsRefused) {
    ir::Grammar g = lang::loadGrammarFile(std::string(SIMECO_SOURCE_DIR) + "/grammars/abop/fig2.8-ternary.l");
    gpu::GpuDeriver deriver(context(), g);
    stream::DeriveOptions options;
    options.steps = 2;
    deriver.derive(options, false);
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    EXPECT_THROW(context().submitAndWait([&](VkCommandBuffer cmd) { turtle.record(cmd, deriver.lastString(), {}); }),
                 std::logic_error);
}

} // namespace
