// Levels of detail and culling: organs a few pixels across are drawn with their kind's coarser mesh and look as they
// did; organs wholly outside the view are left out of the draws and the frame is the same, their shadows too.
#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "draw/renderer.h"
#include "test_scene.h"

namespace simeco::test {
namespace {

using draw::Frame;

class LevelOfDetailTest : public RenderTest {};

// A small plant: a stem, a serrate leaf on it and a fruit at its top.
std::vector<OrganInstance> smallPlant() {
    return {makeStem({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0f, 0.05f, 0, 1),
            makeLeaf({0, 0.5f, 0}, {1, 0, 0}, {0, 1, 0}, 0.8f, 0.45f, shared::kLeafSerrate, 0, 2),
            makeSphere({0, 1.05f, 0}, 0.2f, 0, 3)};
}

// A small frame from `camera`, with shadow volumes of the sun from `sun`.
draw::RenderSettings smallFrame(const draw::Camera& camera, glm::vec3 sun) {
    draw::RenderSettings s;
    s.width = 160;
    s.height = 120;
    s.sunDirection = sun;
    s.camera = camera;
    return s;
}

draw::RenderSettings viewFrom(float distance, bool levels) {
    draw::Camera camera;
    camera.distance = distance;
    camera.target = glm::vec3(0.2f, 0.5f, 0.0f);
    draw::RenderSettings s = smallFrame(camera, draw::RenderSettings{}.sunDirection);
    s.shadows = draw::Shadows::None;
    s.levelsOfDetail = levels;
    return s;
}

std::size_t organPixelCount(const Frame& frame, std::uint32_t organ) {
    return organPixels(frame, organ).pixels;
}

TEST_F(LevelOfDetailTest, NearOrgansAreDrawnWithTheFinestMeshesAndDistantOnesWithCoarserOnesThatLookAlike) {
    TestScene scene = uploadScene(context(), smallPlant());
    // Close (the leaf about 90 pixels long): every organ near.
    renderer().render(scene.instances, scene.table, scene.bounds, viewFrom(2.0f, true));
    draw::DrawnOrgans close = renderer().drawnOrgans();
    for (std::uint32_t kind : {shared::kOrganStem, shared::kOrganLeaf, shared::kOrganSphere}) {
        EXPECT_EQ(close.near[kind], 1u) << "kind " << kind;
        EXPECT_EQ(close.far[kind], 0u) << "kind " << kind;
    }

    // Far (the leaf about 8 pixels long, the stem under a pixel wide, the fruit 2 pixels across): every organ far.
    const Frame coarse = renderer().render(scene.instances, scene.table, scene.bounds, viewFrom(24.0f, true));
    draw::DrawnOrgans distant = renderer().drawnOrgans();
    for (std::uint32_t kind : {shared::kOrganStem, shared::kOrganLeaf, shared::kOrganSphere}) {
        EXPECT_EQ(distant.near[kind], 0u) << "kind " << kind;
        EXPECT_EQ(distant.far[kind], 1u) << "kind " << kind;
    }
    // Off, the same view draws them near, and they cover about the same pixels.
    const Frame fine = renderer().render(scene.instances, scene.table, scene.bounds, viewFrom(24.0f, false));
    EXPECT_EQ(renderer().drawnOrgans().near[shared::kOrganLeaf], 1u);
    maybeSavePreview(coarse, "lod_far");
    maybeSavePreview(fine, "lod_fine");
    for (std::uint32_t organ : {1u, 2u}) {
        const std::size_t coarsePixels = organPixelCount(coarse, organ), finePixels = organPixelCount(fine, organ);
        ASSERT_GT(finePixels, 0u) << "organ " << organ;
        EXPECT_GE(coarsePixels, finePixels * 6 / 10) << "organ " << organ;
        EXPECT_LE(coarsePixels, finePixels * 11 / 10 + 1) << "organ " << organ;
    }
}

// A scene drawn with one of the settings' switches on, then off, and what each frame drew.
struct OnAndOff {
    Frame on, off;
    draw::DrawnOrgans drawnOn, drawnOff;
};
OnAndOff renderOnAndOff(draw::Renderer& renderer, const TestScene& scene, draw::RenderSettings s,
                        bool draw::RenderSettings::*setting) {
    OnAndOff result;
    s.*setting = true;
    result.on = renderer.render(scene.instances, scene.table, scene.bounds, s);
    result.drawnOn = renderer.drawnOrgans();
    s.*setting = false;
    result.off = renderer.render(scene.instances, scene.table, scene.bounds, s);
    result.drawnOff = renderer.drawnOrgans();
    return result;
}

// The pixels of the ground (no organ there) darker than `share` of the frame's brightest ground pixel.
std::size_t shadedGround(const Frame& frame, float share) {
    float lit = 0.0f;
    for (std::uint32_t y = 0; y < frame.height; ++y)
        for (std::uint32_t x = 0; x < frame.width; ++x)
            if (frame.organ[y * frame.width + x] == Frame::kNoId && frame.rgba[4 * (y * frame.width + x) + 3] > 0.0f)
                lit = std::max(lit, luminance(frame, x, y));
    std::size_t shaded = 0;
    for (std::uint32_t y = 0; y < frame.height; ++y)
        for (std::uint32_t x = 0; x < frame.width; ++x)
            if (frame.organ[y * frame.width + x] == Frame::kNoId && frame.rgba[4 * (y * frame.width + x) + 3] > 0.0f &&
                luminance(frame, x, y) < share * lit)
                ++shaded;
    return shaded;
}

// The mean luminance of an organ's pixels (0 where it has none).
float meanLuminance(const Frame& frame, std::uint32_t organ) {
    double sum = 0.0;
    std::size_t count = 0;
    for (std::uint32_t y = 0; y < frame.height; ++y)
        for (std::uint32_t x = 0; x < frame.width; ++x)
            if (frame.organ[y * frame.width + x] == organ) {
                sum += luminance(frame, x, y);
                ++count;
            }
    return count ? static_cast<float>(sum / static_cast<double>(count)) : 0.0f;
}

TEST_F(LevelOfDetailTest, AStemAPixelOrTwoWideIsABandThatFacesTheViewerFromEverySideAndLooksAsTheRoundStem) {
    // A leaning stem about one and a half pixels wide and fifty long, seen from around it, low and from above (not
    // along it, where the round stem's end cap shows, which the band leaves out: a stem's ends are hidden in its
    // joints).
    const glm::vec3 heading = glm::normalize(glm::vec3(0.3f, 1.0f, 0.1f));
    const std::vector<OrganInstance> stem = {
        makeStem({0, 0, 0}, heading, glm::normalize(glm::cross(glm::vec3(1, 0, 0), heading)), 2.0f, 0.03f, 0, 1)};
    TestScene scene = uploadScene(context(), stem);
    for (const float azimuth : {0.0f, 70.0f, 160.0f, 250.0f}) {
        for (const float elevation : {10.0f, 35.0f}) {
            draw::Camera camera;
            camera.azimuthDegrees = azimuth;
            camera.elevationDegrees = elevation;
            camera.distance = 14.0f;
            camera.target = glm::vec3(0.3f, 0.95f, 0.1f);
            draw::RenderSettings s = smallFrame(camera, {0.4f, 1.0f, 0.3f});
            s.shadows = draw::Shadows::None;
            s.width = 320;
            s.height = 240;
            const OnAndOff frames = renderOnAndOff(renderer(), scene, s, &draw::RenderSettings::levelsOfDetail);
            SCOPED_TRACE(testing::Message() << "azimuth " << azimuth << ", elevation " << elevation);
            EXPECT_EQ(frames.drawnOn.far[shared::kOrganStem], 1u);
            EXPECT_EQ(frames.drawnOff.near[shared::kOrganStem], 1u);
            const std::size_t band = organPixelCount(frames.on, 1), round = organPixelCount(frames.off, 1);
            ASSERT_GT(round, 20u);
            EXPECT_GE(band, round * 8 / 10);
            EXPECT_LE(band, round * 13 / 10);
            const float bandLight = meanLuminance(frames.on, 1), roundLight = meanLuminance(frames.off, 1);
            EXPECT_NEAR(bandLight, roundLight, 0.1f * roundLight);
        }
    }
}

TEST_F(LevelOfDetailTest, DistantLeavesCastFromCoarserCutsAndTheirShadowsLookAlike) {
    // A row of serrate leaves held flat above the ground, the sun high: seen from afar each is a few pixels long.
    std::vector<OrganInstance> leaves;
    for (std::uint32_t i = 0; i < 6; ++i)
        leaves.push_back(makeLeaf({1.2f * static_cast<float>(i), 1.0f, 0}, {1, 0, 0}, {0, 1, 0}, 1.0f, 0.6f,
                                  shared::kLeafSerrate, i, i));
    TestScene scene = uploadScene(context(), leaves);
    draw::Camera camera;
    camera.elevationDegrees = 50.0f;
    camera.distance = 30.0f;
    camera.target = glm::vec3(3.0f, 0.5f, 0.0f);
    const draw::RenderSettings s = smallFrame(camera, {0.3f, 1.0f, 0.2f});

    const OnAndOff frames = renderOnAndOff(renderer(), scene, s, &draw::RenderSettings::levelsOfDetail);
    const Frame &coarse = frames.on, &fine = frames.off;
    const draw::DrawnOrgans &coarseDrawn = frames.drawnOn, &fineDrawn = frames.drawnOff;
    maybeSavePreview(coarse, "lod_far_leaf_shadows");

    EXPECT_EQ(coarseDrawn.far[shared::kOrganLeaf], 6u);
    EXPECT_GT(fineDrawn.shadowVolumes, 0u);
    EXPECT_LT(coarseDrawn.shadowVolumes, fineDrawn.shadowVolumes * 3 / 4);
    const std::size_t coarseShade = shadedGround(coarse, 0.7f), fineShade = shadedGround(fine, 0.7f);
    ASSERT_GT(fineShade, 30u);
    EXPECT_GE(coarseShade, fineShade * 6 / 10);
    EXPECT_LE(coarseShade, fineShade * 12 / 10);
}

TEST_F(LevelOfDetailTest, OrgansOutsideTheViewAreLeftOutAndTheFrameAndItsShadowsStayTheSame) {
    // A row of fruits on stems along x, the camera on the ground beside it (to -x) and the sun low from +x: no organ
    // is in the frame, but their shadows stretch into it. Four more far beyond the frame's other side (at x = -12 and
    // on), whose shadows fall away from it: their volumes are left out too.
    std::vector<OrganInstance> row;
    for (std::uint32_t i = 0; i < 16; ++i) {
        const float x = i < 12 ? 0.6f * static_cast<float>(i) : -12.0f - 0.6f * static_cast<float>(i - 12);
        const glm::vec3 base(x, 0, 0);
        row.push_back(makeStem(base, {0, 1, 0}, {0, 0, 1}, 1.0f, 0.08f, i, 2 * i));
        row.push_back(makeSphere(base + glm::vec3(0, 1.2f, 0), 0.25f, i, 2 * i + 1));
    }
    TestScene scene = uploadScene(context(), row);
    draw::Camera camera;
    camera.azimuthDegrees = 0.0f;
    camera.elevationDegrees = 15.0f;
    camera.distance = 3.0f;
    camera.target = glm::vec3(-1.7f, 0.3f, 0.0f);
    const draw::RenderSettings s = smallFrame(camera, {1.0f, 0.35f, 0.0f});

    const OnAndOff frames = renderOnAndOff(renderer(), scene, s, &draw::RenderSettings::cullOutsideView);
    const Frame &culled = frames.on, &all = frames.off;
    const draw::DrawnOrgans &drawn = frames.drawnOn, &allDrawn = frames.drawnOff;
    maybeSavePreview(culled, "culled_row");

    // The bounds are generous (a stem's reach past its ends where it is mitred): the first stems may be drawn.
    EXPECT_EQ(drawn.near[shared::kOrganSphere] + drawn.far[shared::kOrganSphere], 0u);
    EXPECT_LE(drawn.near[shared::kOrganStem] + drawn.far[shared::kOrganStem], 2u);
    for (std::uint32_t kind : {shared::kOrganStem, shared::kOrganSphere})
        EXPECT_EQ(allDrawn.near[kind] + allDrawn.far[kind], 16u) << "kind " << kind;
    EXPECT_GT(drawn.shadowVolumes, 0u);
    EXPECT_LT(drawn.shadowVolumes, allDrawn.shadowVolumes);
    // The frame is the same, pixel for pixel, with the row's shadows on the ground (cast from every organ).
    ASSERT_EQ(culled.rgba.size(), all.rgba.size());
    EXPECT_EQ(culled.rgba, all.rgba);
    EXPECT_EQ(culled.organ, all.organ);
    EXPECT_TRUE(organPixels(culled).empty());
    std::size_t shaded = 0, lit = 0;
    for (std::uint32_t y = 0; y < culled.height; ++y)
        for (std::uint32_t x = 0; x < culled.width; ++x) {
            if (culled.rgba[4 * (y * culled.width + x) + 3] == 0.0f) continue; // the sky
            (luminance(culled, x, y) < 0.7f * luminance(culled, 0, culled.height - 1) ? shaded : lit) += 1;
        }
    EXPECT_GT(shaded, 100u);
    EXPECT_GT(lit, shaded);
}

} // namespace
} // namespace simeco::test
