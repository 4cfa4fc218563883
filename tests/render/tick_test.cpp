// One tick of a field recorded into one submission, with no host read or wait inside: the turtle kernels
// interpret again the string the derivation left on the device (a growth tick), or the derivation's next step
// too, and the renderer draws their organs into its target; the frame equals the one the blocking calls draw.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <set>
#include <string>

#include "compute/shared/organ_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "draw/bounds.h"
#include "draw/renderer.h"
#include "gpu/derive_gpu.h"
#include "gpu_fixture.h"
#include "lang/load_grammar.h"
#include "same_organs.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_gpu.h"
#include "turtle/turtle_settings.h"
#include "vk/buffer.h"
#include "vk/submission.h"

namespace {

using namespace simeco;

class FieldTick : public test::GpuTest {
protected:
    // The README's tree, of which every test grows a field.
    static ir::Grammar ternaryTree() {
        return lang::loadGrammarFile(std::string(SIMECO_SOURCE_DIR) + "/grammars/abop/fig2.8-ternary.l");
    }
    // Frames small enough for the tests, with shadow volumes.
    static draw::RenderSettings smallFrame() {
        draw::RenderSettings settings;
        settings.width = 240;
        settings.height = 180;
        settings.shadows = draw::Shadows::Volume;
        return settings;
    }
    static stream::DeriveOptions field(uint32_t plants, int steps) {
        stream::DeriveOptions options;
        options.plants = plants;
        options.steps = steps;
        return options;
    }
};

// The frames of two runs that should draw the same field: equal ids, colours within rounding, and a field.
void expectSameFrame(const draw::Frame& tick, const draw::Frame& blocking) {
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

TEST_F(FieldTick, ATickRecordedInOneSubmissionDrawsWhatTheBlockingCallsDraw) {
    ir::Grammar g = ternaryTree();
    const stream::DeriveOptions options = field(100, 3);
    gpu::GpuDeriver deriver(context(), g);
    deriver.derive(options, /*readBack=*/false);
    stream::DeviceModules modules = deriver.lastString();
    ASSERT_EQ(modules.plants, 100u);

    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    const turtle::DeviceOrgans& organs = turtle.interpret(modules, {});
    shared::OrganTable table = vk::downloadVector<shared::OrganTable>(context(), organs.table, 1)[0];
    draw::Bounds bounds = draw::decodeBounds(table);
    const draw::RenderSettings settings = smallFrame();
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
        const turtle::DeviceOrgans& ticked = turtle.record(cmd, modules, {}, turtle.lastRoom());
        renderer.record(cmd, target, ticked.instances, ticked.table, setup);
    });
    draw::Frame tick = renderer.readBack(target, setup);
    EXPECT_TRUE(turtle.recorded().fit);

    expectSameFrame(tick, blocking);
}

// Two strings recorded one after the other in one submission, each into buffers of its own: each target holds the
// organs interpreting its string alone gives, though both recordings share the turtle's passes' arrays; a target
// with too little room says so.
TEST_F(FieldTick, StringsRecordedIntoTargetsOfTheirOwnInOneSubmissionKeepTheirOrgans) {
    ir::Grammar g = ternaryTree();
    gpu::GpuDeriver small(context(), g), large(context(), g);
    small.derive(field(20, 2), /*readBack=*/false);
    large.derive(field(30, 3), /*readBack=*/false);
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    const turtle::Interpretation smallAlone = turtle::readBack(context(), turtle.interpret(small.lastString(), {}), 20);
    const turtle::TurtleRoom smallRoom = turtle.lastRoom();
    const turtle::Interpretation largeAlone = turtle::readBack(context(), turtle.interpret(large.lastString(), {}), 30);
    const turtle::TurtleRoom largeRoom = turtle.lastRoom();
    ASSERT_GT(largeAlone.organs.size(), smallAlone.organs.size());

    turtle::TurtleTarget smallTarget, largeTarget, crampedTarget;
    turtle::TurtleRoom cramped = largeRoom;
    cramped.organs = 1;
    turtle.reserveTargets(large.lastString().count, 30, largeRoom);
    context().submitAndWait([&](VkCommandBuffer cmd) {
        turtle.recordInto(cmd, small.lastString(), {}, smallRoom, smallTarget);
        turtle.recordInto(cmd, large.lastString(), {}, largeRoom, largeTarget);
        turtle.recordInto(cmd, large.lastString(), {}, cramped, crampedTarget);
    });
    EXPECT_TRUE(turtle::GpuTurtle::recordedInto(smallTarget).fit);
    EXPECT_TRUE(turtle::GpuTurtle::recordedInto(largeTarget).fit);
    EXPECT_FALSE(turtle::GpuTurtle::recordedInto(crampedTarget).fit);
    EXPECT_EQ(test::organDifference(smallAlone, turtle::readBack(context(), smallTarget.organs, 20)), "");
    EXPECT_EQ(test::organDifference(largeAlone, turtle::readBack(context(), largeTarget.organs, 30)), "");
    // A string past what the turtle made room for is refused, not recorded over its arrays' ends.
    turtle::TurtleTarget another;
    turtle.reserveTargets(small.lastString().count, 20, smallRoom);
    EXPECT_THROW(context().submitAndWait([&](VkCommandBuffer cmd) {
        turtle.recordInto(cmd, large.lastString(), {}, largeRoom, another);
    }),
                 std::logic_error);
}

// A tick whose string changes: the next step derived, interpreted and drawn with shadow volumes in one
// submission, from what the last interpretation left (the room it needed, the framing); equal to the blocking
// calls' frame of that step.
TEST_F(FieldTick, ADerivationStepInterpretedAndDrawnInOneSubmission) {
    ir::Grammar g = ternaryTree();
    const stream::DeriveOptions before = field(100, 2), after = field(100, 3);
    gpu::GpuDeriver deriver(context(), g);
    ASSERT_TRUE(deriver.recordsSteps());
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    draw::Renderer renderer(context());
    const draw::RenderSettings settings = smallFrame();

    // The blocking calls at the step after: the expected frame, framed as the tick frames it.
    gpu::GpuDeriveStats stats;
    deriver.derive(before, false, &stats);
    const uint64_t modulesBefore = stats.modules;
    const turtle::DeviceOrgans& last = turtle.interpret(deriver.lastString(), {});
    draw::Bounds bounds = draw::decodeBounds(vk::downloadVector<shared::OrganTable>(context(), last.table, 1)[0]);
    const turtle::TurtleRoom needed = turtle.lastRoom();
    deriver.derive(after, false, &stats);
    const uint64_t modulesAfter = stats.modules;
    ASSERT_GT(modulesAfter, modulesBefore);
    const turtle::DeviceOrgans& expected = turtle.interpret(deriver.lastString(), {});
    const uint32_t organsAfter = turtle.lastRoom().organs;
    draw::Frame blocking = renderer.render(expected.instances, expected.table, bounds, settings);

    // The tick, from the state after the step before: room for the string to grow fourfold.
    deriver.derive(before, false);
    turtle.interpret(deriver.lastString(), {});
    const turtle::TurtleRoom room{needed.levels * 2 + 8, needed.organs * 4};
    draw::FrameSetup setup = renderer.prepareWithin(room.organs, bounds, settings);
    const draw::RenderTarget& target = renderer.offscreenTarget(settings.width, settings.height);
    const uint64_t submissions = context().submissions();
    context().submitAndWait([&](VkCommandBuffer cmd) {
        stream::DeviceModules next = deriver.record(cmd, after, modulesBefore * 4);
        EXPECT_TRUE(next.countOnDevice);
        const turtle::DeviceOrgans& organs = turtle.record(cmd, next, {}, room);
        renderer.record(cmd, target, organs.instances, organs.table, setup);
    });
    EXPECT_EQ(context().submissions() - submissions, 1u);
    std::optional<stream::DeriveResult> derived = deriver.recorded(&stats);
    ASSERT_TRUE(derived.has_value());
    EXPECT_EQ(stats.modules, modulesAfter);
    EXPECT_EQ(derived->steps, 3);
    turtle::RecordedInterpretation interpreted = turtle.recorded();
    EXPECT_TRUE(interpreted.fit);
    EXPECT_EQ(interpreted.modules, modulesAfter);
    EXPECT_EQ(interpreted.organs, organsAfter);
    expectSameFrame(renderer.readBack(target, setup), blocking);
}

// Too little room: the derivation says its step did not fit and derives as before afterwards; the turtle says
// its organs or levels did not fit, and its table counts no organs, so that nothing wrong is drawn.
TEST_F(FieldTick, ARecordingWithTooLittleRoomSaysSo) {
    ir::Grammar g = ternaryTree();
    const stream::DeriveOptions options = field(100, 3);
    gpu::GpuDeriver deriver(context(), g);
    gpu::GpuDeriveStats stats;
    context().submitAndWait([&](VkCommandBuffer cmd) { deriver.record(cmd, options, 1); });
    EXPECT_THROW(deriver.derive(options, false), std::logic_error); // not before the recording is read
    EXPECT_FALSE(deriver.recorded().has_value());
    deriver.derive(options, false, &stats);
    EXPECT_GT(stats.modules, 10000u); // more than the smallest stream holds: the recording had to stop
    EXPECT_EQ(stats.modules, deriver.lastString().count);

    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    turtle.interpret(deriver.lastString(), {});
    const turtle::TurtleRoom needed = turtle.lastRoom();
    turtle::GpuTurtle fresh(context(), commands, {turtle::turtleSettings(g, g.alphabet)}); // its buffers small
    const turtle::DeviceOrgans* organs = nullptr;
    context().submitAndWait(
        [&](VkCommandBuffer cmd) { organs = &fresh.record(cmd, deriver.lastString(), {}, {needed.levels, 1}); });
    EXPECT_LT(organs->capacity, needed.organs);
    turtle::RecordedInterpretation interpreted = fresh.recorded();
    EXPECT_FALSE(interpreted.fit);
    EXPECT_EQ(interpreted.organs, needed.organs);
    shared::OrganTable table = vk::downloadVector<shared::OrganTable>(context(), organs->table, 1)[0];
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k) EXPECT_EQ(table.count[k], 0u) << k;

    // Too few levels: the organs of the deeper modules would be wrong, so none is counted either.
    ASSERT_GT(needed.levels, 0u);
    context().submitAndWait([&](VkCommandBuffer cmd) {
        organs = &turtle.record(cmd, deriver.lastString(), {}, {needed.levels - 1, needed.organs});
    });
    interpreted = turtle.recorded();
    EXPECT_FALSE(interpreted.fit);
    EXPECT_EQ(interpreted.levels, needed.levels);
    table = vk::downloadVector<shared::OrganTable>(context(), organs->table, 1)[0];
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k) EXPECT_EQ(table.count[k], 0u) << k;
    // A room without a mark the string has: the searches it needs were left out, so it does not fit either, and
    // its organs, which would be wrong, are not counted (nothing lights, splats or draws them).
    const uint32_t marks = turtle.lastMarks();
    ASSERT_NE(marks & shared::kMarkStem, 0u);
    context().submitAndWait([&](VkCommandBuffer cmd) {
        const turtle::TurtleRoom noStems{needed.levels, needed.organs, marks & ~shared::kMarkStem};
        organs = &turtle.record(cmd, deriver.lastString(), {}, noStems);
    });
    interpreted = turtle.recorded();
    EXPECT_FALSE(interpreted.fit);
    EXPECT_EQ(interpreted.marks, marks);
    table = vk::downloadVector<shared::OrganTable>(context(), organs->table, 1)[0];
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k) EXPECT_EQ(table.count[k], 0u) << k;
    // With the room it needs, the same turtle draws them all.
    context().submitAndWait(
        [&](VkCommandBuffer cmd) { organs = &turtle.record(cmd, deriver.lastString(), {}, needed); });
    EXPECT_TRUE(turtle.recorded().fit);
    table = vk::downloadVector<shared::OrganTable>(context(), organs->table, 1)[0];
    uint32_t counted = 0;
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k) counted += table.count[k];
    EXPECT_EQ(counted, needed.organs);
}

// Two ticks in flight, each drawn into its own target from a camera of its own: the second is submitted before
// the first is waited for, a third is refused while both are in flight, and each frame equals the blocking
// calls' frame from its camera.
TEST_F(FieldTick, TicksInFlightDrawTheirOwnFrames) {
    ir::Grammar g = ternaryTree();
    const stream::DeriveOptions options = field(100, 3);
    gpu::GpuDeriver deriver(context(), g);
    deriver.derive(options, false);
    stream::DeviceModules modules = deriver.lastString();
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    const turtle::DeviceOrgans& organs = turtle.interpret(modules, {});
    draw::Bounds bounds = draw::decodeBounds(vk::downloadVector<shared::OrganTable>(context(), organs.table, 1)[0]);
    draw::Renderer renderer(context());
    draw::RenderSettings settings[2] = {smallFrame(), smallFrame()};
    settings[1].camera = draw::Camera{};
    settings[1].camera->azimuthDegrees = 120.0f;
    settings[1].camera->elevationDegrees = 35.0f;
    draw::Frame blocking[2];
    draw::FrameSetup setups[2];
    for (int k = 0; k < 2; ++k) {
        blocking[k] = renderer.render(organs.instances, organs.table, bounds, settings[k]);
        setups[k] = renderer.prepare(organs.table, bounds, settings[k]);
    }
    std::unique_ptr<draw::RenderTarget> second = renderer.makeTarget(240, 180);
    const draw::RenderTarget* targets[2] = {&renderer.offscreenTarget(240, 180), second.get()};
    const turtle::TurtleRoom room = turtle.lastRoom();
    auto tick = [&](int k) {
        return context().submit([&, k](VkCommandBuffer cmd) {
            const turtle::DeviceOrgans& ticked = turtle.record(cmd, modules, {}, room);
            renderer.record(cmd, *targets[k], ticked.instances, ticked.table, setups[k]);
        });
    };

    vk::Submission inFlight[2] = {tick(0), tick(1)};
    EXPECT_THROW(tick(0), std::logic_error); // the turtle keeps two recordings in flight
    draw::Frame frames[2];
    for (int k = 0; k < 2; ++k) {
        inFlight[k].wait();
        EXPECT_TRUE(turtle.recorded().fit);
        frames[k] = renderer.readBack(*targets[k], setups[k]);
        expectSameFrame(frames[k], blocking[k]);
    }
    EXPECT_FALSE(frames[0].plant == frames[1].plant); // two cameras, two pictures
    EXPECT_THROW(turtle.recorded(), std::logic_error); // each recording is read once
}


// Two ticks that derive in flight: each derives a field of its own (the second a step further), interprets it and
// draws it into its own target; the second is recorded and submitted before the first is read, a third
// derivation is refused while both are in flight, and each frame equals the blocking calls' frame of its field.
TEST_F(FieldTick, DerivingTicksInFlightDrawTheirOwnFields) {
    ir::Grammar g = ternaryTree();
    const stream::DeriveOptions options[2] = {field(100, 2), field(100, 3)};
    gpu::GpuDeriver deriver(context(), g);
    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    turtle::GpuTurtle turtle(context(), commands, {turtle::turtleSettings(g, g.alphabet)});
    draw::Renderer renderer(context());
    const draw::RenderSettings settings = smallFrame();

    // The blocking calls: each field's frame, framed as its tick frames it; the larger field last, so that the
    // deriver's and the turtle's buffers hold what both ticks need.
    draw::Frame blocking[2];
    draw::Bounds bounds[2];
    uint64_t modules[2];
    uint32_t organs[2];
    for (int k = 0; k < 2; ++k) {
        gpu::GpuDeriveStats stats;
        deriver.derive(options[k], false, &stats);
        modules[k] = stats.modules;
        const turtle::DeviceOrgans& interpreted = turtle.interpret(deriver.lastString(), {});
        bounds[k] = draw::decodeBounds(vk::downloadVector<shared::OrganTable>(context(), interpreted.table, 1)[0]);
        organs[k] = turtle.lastRoom().organs;
        blocking[k] = renderer.render(interpreted.instances, interpreted.table, bounds[k], settings);
    }
    ASSERT_GT(modules[1], modules[0]);
    const turtle::TurtleRoom room = turtle.lastRoom();
    draw::FrameSetup setups[2];
    for (int k = 0; k < 2; ++k) setups[k] = renderer.prepareWithin(room.organs, bounds[k], settings);
    std::unique_ptr<draw::RenderTarget> second = renderer.makeTarget(240, 180);
    const draw::RenderTarget* targets[2] = {&renderer.offscreenTarget(240, 180), second.get()};
    auto tick = [&](int k) {
        return context().submit([&, k](VkCommandBuffer cmd) {
            stream::DeviceModules next = deriver.record(cmd, options[k], modules[1]);
            const turtle::DeviceOrgans& ticked = turtle.record(cmd, next, {}, room);
            renderer.record(cmd, *targets[k], ticked.instances, ticked.table, setups[k]);
        });
    };

    vk::Submission first = tick(0);
    // A second recording that would grow the streams the first one's submission uses is refused.
    EXPECT_THROW(deriver.record(VK_NULL_HANDLE, options[1], modules[1] * 64), std::logic_error);
    vk::Submission inFlight[2] = {std::move(first), tick(1)};
    EXPECT_THROW(deriver.record(VK_NULL_HANDLE, options[0], modules[1]), std::logic_error); // two in flight
    EXPECT_THROW(deriver.derive(options[0], false), std::logic_error);
    // Both ended before either is read: each one's sizes are its own.
    for (vk::Submission& submission : inFlight) submission.wait();
    for (int k = 0; k < 2; ++k) {
        gpu::GpuDeriveStats stats;
        std::optional<stream::DeriveResult> derived = deriver.recorded(&stats);
        ASSERT_TRUE(derived.has_value());
        EXPECT_EQ(derived->steps, options[k].steps);
        EXPECT_EQ(stats.modules, modules[k]);
        EXPECT_EQ(derived->string.plantStart.back(), modules[k]); // its own plant table
        turtle::RecordedInterpretation interpreted = turtle.recorded();
        EXPECT_TRUE(interpreted.fit);
        EXPECT_EQ(interpreted.modules, modules[k]);
        EXPECT_EQ(interpreted.organs, organs[k]);
        expectSameFrame(renderer.readBack(*targets[k], setups[k]), blocking[k]);
    }
    EXPECT_THROW(deriver.recorded(), std::logic_error); // each recording is read once
    // Read, the deriver derives as before.
    gpu::GpuDeriveStats stats;
    deriver.derive(options[1], false, &stats);
    EXPECT_EQ(stats.modules, modules[1]);
}

} // namespace
