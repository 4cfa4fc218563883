// Multisampled frames (RenderSettings::samples): a thin stem stays a line where one sample a pixel breaks it into
// dashes, its coverage as a supersampled frame's; fully covered pixels keep the colour, ids and depth of one
// sample; shadows' edges are smooth; a count the device lacks is refused.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "draw/render_pass.h"
#include "draw/renderer.h"
#include "gpu_fixture.h"
#include "test_scene.h"

namespace simeco::test {
namespace {

using draw::Frame;

class MultisampleTest : public RenderTest {
protected:
    // The smallest count of several samples the device draws (Vulkan requires 4 of every device that draws
    // colour and depth; lavapipe draws 1 and 4).
    std::uint32_t samples() {
        const VkSampleCountFlags counts = draw::drawableSampleCounts(context());
        for (std::uint32_t count = 2; count <= 64; count *= 2)
            if (counts & count) return count;
        ADD_FAILURE() << "the device draws no count of several samples";
        return 1;
    }
};

draw::RenderSettings settingsOf(std::uint32_t samples, draw::Shadows shadows, bool ground) {
    draw::RenderSettings s;
    s.width = 160;
    s.height = 120;
    s.samples = samples;
    s.shadows = shadows;
    s.ground = ground;
    // Every stem with its finest mesh, as drawn: the coarser ones differ by under a pixel.
    s.levelsOfDetail = false;
    return s;
}

// The rows from `top` to `bottom` in which no pixel shows `organ`.
int rowsWithout(const Frame& frame, std::uint32_t organ, int top, int bottom) {
    int missing = 0;
    for (int y = top; y <= bottom; ++y) {
        bool shown = false;
        for (std::uint32_t x = 0; x < frame.width && !shown; ++x)
            shown = frame.organ[frame.index(x, y)] == organ;
        missing += shown ? 0 : 1;
    }
    return missing;
}

double alphaSum(const Frame& frame) {
    double sum = 0;
    for (std::size_t i = 0; i < frame.pixelCount(); ++i)
        sum += frame.rgba[4 * i + 3];
    return sum;
}

TEST_F(MultisampleTest, AThinStemIsALineNotDashesWithTheCoverageOfASupersampledOne) {
    // A stem about 0.6 pixels wide, leaning a few pixels over its height, beside a thick one that frames it.
    const std::uint32_t thin = 3;
    TestScene scene = uploadScene(
        context(), {makeStem({0, 0, 0}, glm::normalize(glm::vec3{0.05f, 1, 0}), {0, 0, 1}, 1.0f, 0.003f, 0, thin),
                    makeStem({0.4f, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0f, 0.05f, 0, 4)});
    const draw::RenderSettings one = settingsOf(1, draw::Shadows::None, false);
    const draw::RenderSettings several = settingsOf(samples(), draw::Shadows::None, false);
    const Frame single = renderer().render(scene.instances, scene.table, scene.bounds, one);
    const Frame multi = renderer().render(scene.instances, scene.table, scene.bounds, several);
    maybeSavePreview(single, "thin_stem_one_sample");
    maybeSavePreview(multi, "thin_stem_multisampled");

    // The rows the stem spans, but for its ends.
    const draw::CameraView camera = draw::frameCamera(scene.bounds, one);
    const glm::vec2 base = projectToPixel(camera, {0, 0, 0}, one.width, one.height);
    const glm::vec2 tip = projectToPixel(camera, glm::normalize(glm::vec3{0.05f, 1, 0}), one.width, one.height);
    const int top = static_cast<int>(std::ceil(std::min(base.y, tip.y))) + 2;
    const int bottom = static_cast<int>(std::floor(std::max(base.y, tip.y))) - 2;
    ASSERT_GT(bottom - top, 60) << "the stem spans most of the frame's height";
    // One sample a pixel: the stem misses every sample of some rows (this is what the test is about).
    EXPECT_GT(rowsWithout(single, thin, top, bottom), 5);
    // Several: some sample of every row is within it, and the pixel shows it (the nearest sample's id).
    EXPECT_EQ(rowsWithout(multi, thin, top, bottom), 0);

    // Partly covered pixels are partly opaque, and the frame's coverage is a supersampled frame's (16 samples a
    // pixel on a grid, averaged on the host).
    int partial = 0;
    for (std::size_t i = 0; i < multi.pixelCount(); ++i) {
        const float alpha = multi.rgba[4 * i + 3];
        partial += alpha > 0.05f && alpha < 0.95f ? 1 : 0;
    }
    EXPECT_GT(partial, bottom - top);
    draw::RenderSettings supersampled = one;
    supersampled.antialias = 4;
    const Frame reference = renderer().render(scene.instances, scene.table, scene.bounds, supersampled);
    EXPECT_NEAR(alphaSum(multi), alphaSum(reference), 0.05 * alphaSum(reference));
}

TEST_F(MultisampleTest, CoveredPixelsKeepTheColourIdsAndDepthOfOneSampleAndTheBackgroundHasNone) {
    TestScene scene =
        uploadScene(context(), {makeSphere({0, 0.5f, 0}, 0.5f, 1, 10), makeSphere({0.6f, 0.4f, 0.3f}, 0.4f, 2, 20),
                                makeStem({-0.6f, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.2f, 0.08f, 3, 30)});
    for (const draw::Shadows shadows : {draw::Shadows::None, draw::Shadows::Volume}) {
        const Frame single =
            renderer().render(scene.instances, scene.table, scene.bounds, settingsOf(1, shadows, true));
        const Frame multi =
            renderer().render(scene.instances, scene.table, scene.bounds, settingsOf(samples(), shadows, true));
        maybeSavePreview(multi, shadows == draw::Shadows::None ? "covered_multisampled" : "covered_shadows");
        int interior = 0, organs = 0, background = 0;
        for (std::uint32_t y = 1; y + 1 < single.height; ++y) {
            for (std::uint32_t x = 1; x + 1 < single.width; ++x) {
                // Within one organ, the ground or the sky, with one sample a pixel: its neighbours too.
                const std::size_t i = single.index(x, y);
                bool alike = true;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const std::size_t j = single.index(x + dx, y + dy);
                        alike = alike && single.organ[j] == single.organ[i] && single.plant[j] == single.plant[i] &&
                                std::isinf(single.depth[j]) == std::isinf(single.depth[i]);
                    }
                if (!alike) continue;
                ++interior;
                ASSERT_EQ(multi.organ[i], single.organ[i]) << x << "," << y;
                ASSERT_EQ(multi.plant[i], single.plant[i]) << x << "," << y;
                if (std::isinf(single.depth[i])) {
                    ASSERT_TRUE(std::isinf(multi.depth[i])) << x << "," << y;
                    ++background;
                } else {
                    // The nearest sample's surface, at the pixel's centre: within the depths about it (to a thousandth:
                    // its plane reaches the centre from the sample).
                    float lo = single.depth[i], hi = single.depth[i];
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx) {
                            lo = std::min(lo, single.depth[single.index(x + dx, y + dy)]);
                            hi = std::max(hi, single.depth[single.index(x + dx, y + dy)]);
                        }
                    ASSERT_GE(multi.depth[i], lo - 1e-3f * lo) << x << "," << y;
                    ASSERT_LE(multi.depth[i], hi + 1e-3f * hi) << x << "," << y;
                }
                if (single.organ[i] != Frame::kNoId) ++organs;
                // Without shadows, whose edges cross covered pixels, a covered pixel's colour is within its
                // neighbourhood's: its samples may lie on the facets beside the one at its centre.
                if (shadows == draw::Shadows::None) {
                    for (int c = 0; c < 4; ++c) {
                        float lo = single.rgba[4 * i + c], hi = lo;
                        for (int dy = -1; dy <= 1; ++dy)
                            for (int dx = -1; dx <= 1; ++dx) {
                                lo = std::min(lo, single.rgba[4 * single.index(x + dx, y + dy) + c]);
                                hi = std::max(hi, single.rgba[4 * single.index(x + dx, y + dy) + c]);
                            }
                        ASSERT_GE(multi.rgba[4 * i + c], lo - 1e-4f) << x << "," << y;
                        ASSERT_LE(multi.rgba[4 * i + c], hi + 1e-4f) << x << "," << y;
                    }
                }
            }
        }
        EXPECT_GT(organs, 1000);
        EXPECT_GT(background, 1000);
        EXPECT_GT(interior, static_cast<int>(single.pixelCount() * 3 / 4));
    }
}

TEST_F(MultisampleTest, AShadowsEdgeOnTheGroundIsSmooth) {
    // A sphere above the ground in a high sun: its shadow a disc on it.
    TestScene scene = uploadScene(context(), {makeSphere({0, 0.8f, 0}, 0.3f, 1, 10),
                                              makeStem({1.2f, 0, 0}, {0, 1, 0}, {0, 0, 1}, 0.1f, 0.02f, 1, 11)});
    auto groundLevels = [&](std::uint32_t samples, int& lit, int& shadowed, int& between) {
        draw::RenderSettings s = settingsOf(samples, draw::Shadows::Volume, true);
        s.sunDirection = {0.2f, 1.0f, 0.1f};
        draw::Camera camera;
        camera.elevationDegrees = 60.0f;
        s.camera = camera;
        const Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
        maybeSavePreview(frame, samples == 1 ? "shadow_one_sample" : "shadow_multisampled");
        // The ground is flat: one colour in the sun and one in the shadow, and ids of none.
        float brightest = 0, darkest = 1e9f;
        for (std::size_t i = 0; i < frame.pixelCount(); ++i) {
            if (frame.organ[i] != Frame::kNoId || std::isinf(frame.depth[i])) continue;
            const float l = frame.rgba[4 * i + 1];
            brightest = std::max(brightest, l);
            darkest = std::min(darkest, l);
        }
        lit = shadowed = between = 0;
        const float margin = 0.05f * (brightest - darkest);
        for (std::uint32_t y = 1; y + 1 < frame.height; ++y) {
            for (std::uint32_t x = 1; x + 1 < frame.width; ++x) {
                // Ground pixels among ground pixels, away from the organs' and the sky's edges.
                bool ground = true;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx) {
                        const std::size_t j = frame.index(x + dx, y + dy);
                        ground = ground && frame.organ[j] == Frame::kNoId && !std::isinf(frame.depth[j]);
                    }
                if (!ground) continue;
                const float l = frame.rgba[4 * frame.index(x, y) + 1];
                if (l > brightest - margin)
                    ++lit;
                else if (l < darkest + margin)
                    ++shadowed;
                else
                    ++between;
            }
        }
    };
    int lit1 = 0, shadowed1 = 0, between1 = 0, litN = 0, shadowedN = 0, betweenN = 0;
    groundLevels(1, lit1, shadowed1, between1);
    groundLevels(samples(), litN, shadowedN, betweenN);
    ASSERT_GT(shadowed1, 100) << "the shadow falls on the ground in view";
    ASSERT_GT(lit1, 1000);
    // One sample a pixel: in the sun or not. Several: the edge's pixels in between, all round the shadow.
    EXPECT_EQ(between1, 0);
    EXPECT_GT(betweenN, 2 * static_cast<int>(std::sqrt(static_cast<double>(shadowed1))));
    EXPECT_NEAR(shadowedN, shadowed1, 0.2 * shadowed1);
}

TEST_F(MultisampleTest, ACountTheDeviceLacksIsRefusedNamingThoseItHas) {
    TestScene scene = uploadScene(context(), {makeSphere({0, 0.5f, 0}, 0.5f, 1, 10)});
    const VkSampleCountFlags counts = draw::drawableSampleCounts(context());
    ASSERT_TRUE(counts & VK_SAMPLE_COUNT_1_BIT);
    int refused = 0;
    for (const std::uint32_t lacking : {3u, 64u, 128u}) {
        if (lacking <= 64 && (counts & lacking)) continue;
        ++refused;
        try {
            renderer().render(scene.instances, scene.table, scene.bounds,
                              settingsOf(lacking, draw::Shadows::None, true));
            ADD_FAILURE() << lacking << " samples a pixel were drawn";
        } catch (const std::invalid_argument& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find(std::to_string(lacking) + " samples a pixel"), std::string::npos) << message;
            EXPECT_NE(message.find("draws 1"), std::string::npos) << message;
        }
    }
    EXPECT_GE(refused, 2);
}

} // namespace
} // namespace simeco::test
