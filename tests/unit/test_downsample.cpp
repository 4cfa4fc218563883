// Supersampled frames brought to their size (draw::downsample): colours averaged, ids and depth of the nearest
// sample.
#include <gtest/gtest.h>

#include "draw/downsample.h"

namespace simeco::draw {
namespace {

// A 4 x 2 frame of samples: the left 2 x 2 block half background (far, no ids), half an organ (near); the right
// block one organ in front of another.
Frame samples() {
    Frame f;
    f.width = 4;
    f.height = 2;
    f.rgba.assign(4 * 8, 0.0f);
    f.depth.assign(8, 1e30f);
    f.plant.assign(8, Frame::kNoId);
    f.organ.assign(8, Frame::kNoId);
    auto set = [&](std::uint32_t x, std::uint32_t y, float red, float depth, std::uint32_t plant, std::uint32_t organ) {
        const std::size_t i = f.index(x, y);
        f.rgba[4 * i] = red;
        f.rgba[4 * i + 3] = 1.0f;
        f.depth[i] = depth;
        f.plant[i] = plant;
        f.organ[i] = organ;
    };
    set(1, 0, 1.0f, 5.0f, 3, 30);
    set(1, 1, 1.0f, 5.0f, 3, 30);
    set(2, 0, 0.2f, 4.0f, 1, 10);
    set(3, 0, 0.2f, 4.0f, 1, 10);
    set(2, 1, 0.6f, 2.0f, 2, 20);
    set(3, 1, 0.6f, 4.5f, 1, 11);
    return f;
}

TEST(Downsample, ColoursAreTheSamplesMeanAndIdsTheNearestSamples) {
    const Frame out = downsample(samples(), 2);
    ASSERT_EQ(out.width, 2u);
    ASSERT_EQ(out.height, 1u);
    EXPECT_FLOAT_EQ(out.rgba[0], 0.5f); // half the samples red
    EXPECT_FLOAT_EQ(out.rgba[3], 0.5f); // half covered
    EXPECT_EQ(out.plant[0], 3u);
    EXPECT_EQ(out.organ[0], 30u);
    EXPECT_FLOAT_EQ(out.depth[0], 5.0f);
    EXPECT_FLOAT_EQ(out.rgba[4], 0.4f);
    EXPECT_EQ(out.plant[1], 2u); // the nearest of three organs
    EXPECT_EQ(out.organ[1], 20u);
    EXPECT_FLOAT_EQ(out.depth[1], 2.0f);
    EXPECT_EQ(downsample(samples(), 1).rgba, samples().rgba);
}

TEST(Downsample, AFrameNotAMultipleOfTheFactorIsRefused) {
    EXPECT_THROW(downsample(samples(), 3), std::invalid_argument);
    EXPECT_THROW(downsample(samples(), 0), std::invalid_argument);
}

} // namespace
} // namespace simeco::draw
