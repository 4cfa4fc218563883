// The viewer's growth clock: ticks follow its clock times the time scale, whatever the frames' rate.
#include <cstdint>

#include <gtest/gtest.h>

#include "view/growth_clock.h"

namespace simeco::view {
namespace {

TEST(GrowthClock, AFieldGrowsAsFastAtFiveFramesASecondAsAtSixty) {
    for (const double timeScale : {1.0, 4.0, 0.5}) {
        GrowthClock slow(1.0), fast(1.0);
        std::uint32_t slowTicks = 0, fastTicks = 0;
        for (int frame = 0; frame < 5 * 60; ++frame) slowTicks += slow.ticksAfter(1.0 / 5, timeScale);
        for (int frame = 0; frame < 60 * 60; ++frame) fastTicks += fast.ticksAfter(1.0 / 60, timeScale);
        // A minute of the viewer's clock.
        EXPECT_EQ(slowTicks, std::uint32_t(60 * timeScale)) << "time scale " << timeScale;
        EXPECT_EQ(fastTicks, std::uint32_t(60 * timeScale)) << "time scale " << timeScale;
    }
}

TEST(GrowthClock, FramesBetweenTicksRunNoneAndShortTicksRunSeveralAFrame) {
    GrowthClock clock(2.0); // a tick of two simulated seconds
    EXPECT_EQ(clock.ticksAfter(0.5, 1.0), 0u);
    EXPECT_EQ(clock.ticksAfter(0.5, 1.0), 0u);
    EXPECT_EQ(clock.ticksAfter(0.5, 1.0), 0u);
    EXPECT_EQ(clock.ticksAfter(0.5, 1.0), 1u);
    EXPECT_EQ(clock.ticksAfter(1.0, 8.0), 4u);
    EXPECT_EQ(clock.ticksAfter(1.0, 0.0), 0u);
}

TEST(GrowthClock, AFrameFarBehindRunsAtMostItsTicksAndLetsTheRestGo) {
    GrowthClock clock(1.0);
    EXPECT_EQ(clock.ticksAfter(10.0, 100.0), kMaxTicksAFrame);
    EXPECT_EQ(clock.ticksAfter(0.1, 1.0), 0u) << "nothing left owed after the hitch";
    clock.restart();
    EXPECT_EQ(clock.ticksAfter(0.95, 1.0), 0u);
    EXPECT_EQ(clock.ticksAfter(0.05, 1.0), 1u);
}

TEST(GrowthRate, IsTheSimulatedSecondsGrownASecondOverItsWindowNotTheLastFrames) {
    GrowthRate rate(2.0);
    EXPECT_EQ(rate.perSecond(), 0.0);
    // Ten frames a second, a tick of one simulated second every fifth frame: two simulated seconds a second.
    double simulated = 0.0;
    for (int frame = 0; frame <= 40; ++frame) {
        if (frame > 0 && frame % 5 == 0) simulated += 1.0;
        rate.add(0.1 * frame, simulated);
    }
    EXPECT_NEAR(rate.perSecond(), 2.0, 1e-9);
    // Paused for three seconds: the rate falls to none once the window has passed.
    for (int frame = 41; frame <= 70; ++frame) rate.add(0.1 * frame, simulated);
    EXPECT_EQ(rate.perSecond(), 0.0);
    rate.restart();
    rate.add(10.0, 0.0);
    EXPECT_EQ(rate.perSecond(), 0.0);
}

TEST(GrowthClock, ATickMustLastAPositiveTime) {
    EXPECT_THROW(GrowthClock(0.0), std::invalid_argument);
    EXPECT_THROW(GrowthClock(-1.0), std::invalid_argument);
}

} // namespace
} // namespace simeco::view
