// Stencil shadow volumes of the sun: a tall stem lit from the side shadows the ground behind it, and an organ
// in its way; without shadows the same places are as bright as their surroundings.
#include <memory>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "draw/renderer.h"
#include "gpu_fixture.h"
#include "test_scene.h"

namespace simeco::test {
namespace {

using draw::Frame;

class ShadowTest : public RenderTest {};

// A 2-unit stem at the origin, the sun low in the -x sky: its shadow runs along +x on the ground.
draw::RenderSettings sideLitSettings(draw::Shadows shadows) {
    draw::RenderSettings s;
    s.width = 200;
    s.height = 150;
    s.shadows = shadows;
    s.sunDirection = glm::vec3(-1.0f, 0.7f, 0.0f);
    draw::Camera camera;
    camera.target = glm::vec3(0.8f, 0.0f, 0.0f);
    camera.distance = 7.0f;
    camera.azimuthDegrees = 0.0f;
    camera.elevationDegrees = 55.0f;
    s.camera = camera;
    return s;
}

float luminanceAt(const Frame& frame, const draw::CameraView& view, glm::vec3 world) {
    glm::vec2 p = projectToPixel(view, world, frame.width, frame.height);
    return luminance(frame, static_cast<std::uint32_t>(p.x), static_cast<std::uint32_t>(p.y));
}

std::uint32_t organAt(const Frame& frame, const draw::CameraView& view, glm::vec3 world) {
    glm::vec2 p = projectToPixel(view, world, frame.width, frame.height);
    return frame.organ[frame.index(static_cast<std::uint32_t>(p.x), static_cast<std::uint32_t>(p.y))];
}

TEST_F(ShadowTest, TallStemShadowsTheGroundOnTheFarSideOnly) {
    TestScene scene = uploadScene(context(), {makeStem({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 2.0f, 0.1f, 0, 1)});
    for (draw::Shadows shadows : {draw::Shadows::Volume, draw::Shadows::None}) {
        draw::RenderSettings s = sideLitSettings(shadows);
        Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
        maybeSavePreview(frame, shadows == draw::Shadows::Volume ? "stem_shadow" : "stem_no_shadow");
        draw::CameraView view = draw::frameCamera(scene.bounds, s);
        // On the shadow's line (away from the sun), beside it, and on the sunny side; on the ground, which lies
        // at the bottom of the bounds.
        float g = scene.bounds.min.y;
        glm::vec3 inShadow[] = {{0.8f, g, 0}, {1.5f, g, 0}, {2.2f, g, 0}};
        glm::vec3 lit[] = {{0.8f, g, 0.6f}, {1.5f, g, -0.6f}, {-1.0f, g, 0}};
        for (glm::vec3 p : inShadow) {
            ASSERT_EQ(organAt(frame, view, p), Frame::kNoId) << "the probe should see the ground";
        }
        for (glm::vec3 shade : inShadow) {
            for (glm::vec3 sun : lit) {
                float dark = luminanceAt(frame, view, shade);
                float bright = luminanceAt(frame, view, sun);
                if (shadows == draw::Shadows::Volume) {
                    EXPECT_LT(dark, 0.6f * bright) << "shadow at x=" << shade.x;
                } else {
                    EXPECT_NEAR(dark, bright, 0.05f * bright) << "no shadow expected at x=" << shade.x;
                }
            }
        }
    }
}

// A frame made ready for more shadow volumes than its storage bindings hold gets no more room than they do: the
// shadow kernel binds each window within the device's limit (any validation message fails the test), and the
// shadow still falls.
TEST_F(ShadowTest, ShadowVolumesNeverOutgrowTheirBindings) {
    TestScene scene = uploadScene(context(), {makeStem({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 2.0f, 0.1f, 0, 1)});
    draw::RenderSettings s = sideLitSettings(draw::Shadows::Volume);
    s.maxShadowVolumeBytes = uint64_t(context().limits().maxStorageBufferRange) * 4;
    draw::Renderer& r = renderer();
    const draw::FrameSetup setup = r.prepareWithin(400'000, scene.bounds, s);
    const draw::RenderTarget& target = r.offscreenTarget(s.width, s.height);
    context().submitAndWait([&](VkCommandBuffer cmd) { r.record(cmd, target, scene.instances, scene.table, setup); });
    const Frame frame = r.readBack(target, setup);
    const draw::CameraView view = draw::frameCamera(scene.bounds, s);
    const float g = scene.bounds.min.y;
    EXPECT_LT(luminanceAt(frame, view, {1.5f, g, 0}), 0.6f * luminanceAt(frame, view, {1.5f, g, -0.6f}));
}

// The volumes are written through several bindings (windows) of one buffer, so that a field may cast more than one
// binding holds: with windows of two volumes each, four stems' volumes fill four windows and shade exactly as when
// one window holds them all.
TEST_F(ShadowTest, VolumesWrittenThroughSeveralWindowsShadeAsThroughOne) {
    std::vector<shared::OrganInstance> stems;
    for (int k = 0; k < 4; ++k)
        stems.push_back(makeStem({-0.6f + 0.4f * float(k), 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.5f, 0.1f, 0, 1 + k));
    TestScene scene = uploadScene(context(), stems);
    draw::RenderSettings s = sideLitSettings(draw::Shadows::Volume);
    const Frame whole = renderer().render(scene.instances, scene.table, scene.bounds, s);
    // Each stem casts from its two-triangle ribbon: two volumes of six vertices.
    s.shadowVolumeWindowBytes = 2 * 6 * 16;
    const Frame windowed = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(windowed, "stems_windowed_shadows");
    EXPECT_EQ(windowed.rgba, whole.rgba);
    // And with room for three windows' volumes, the fourth stem's shadow is the one missing: the ground behind it
    // is lit.
    s.maxShadowVolumeBytes = 3 * 2 * 6 * 16;
    const Frame short3 = renderer().render(scene.instances, scene.table, scene.bounds, s);
    EXPECT_NE(short3.rgba, whole.rgba);
}

TEST_F(ShadowTest, StemShadowsAnOrganInItsWayAndTheSunSideOfItselfIsLit) {
    // A horizontal disc of another plant at half height on the shadow's side, and the stem itself.
    std::vector<OrganInstance> organs{makeStem({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 2.0f, 0.1f, 0, 1),
                                      makeDisc({1.5f, 0.5f, 0}, {1, 0, 0}, {0, 1, 0}, 0.7f, 1, 2)};
    TestScene scene = uploadScene(context(), organs);
    draw::RenderSettings s = sideLitSettings(draw::Shadows::Volume);
    Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(frame, "disc_in_shadow");
    draw::CameraView view = draw::frameCamera(scene.bounds, s);
    glm::vec3 shaded(1.5f, 0.5f, 0.0f);
    glm::vec3 litBeside(1.5f, 0.5f, 0.45f);
    ASSERT_EQ(organAt(frame, view, shaded), 2u);
    ASSERT_EQ(organAt(frame, view, litBeside), 2u);
    EXPECT_LT(luminanceAt(frame, view, shaded), 0.6f * luminanceAt(frame, view, litBeside));

    // The ground under the disc is in the disc's shadow, the ground beyond it is not.
    float g = scene.bounds.min.y;
    glm::vec3 underDisc(1.2f + (0.5f - g) / 0.7f, g, 0.3f);
    glm::vec3 open(-1.5f, g, 0.3f);
    ASSERT_EQ(organAt(frame, view, underDisc), Frame::kNoId);
    EXPECT_LT(luminanceAt(frame, view, underDisc), 0.6f * luminanceAt(frame, view, open));

    Frame unshadowed =
        renderer().render(scene.instances, scene.table, scene.bounds, sideLitSettings(draw::Shadows::None));
    // The stem's sunny side keeps its full light with shadows on (no self-shadowing acne).
    glm::vec3 stemSunSide(-0.1f, 1.0f, 0.0f);
    glm::vec3 stemFront(0.0f, 1.0f, 0.1f);
    for (glm::vec3 p : {stemSunSide, stemFront}) {
        if (organAt(frame, view, p) == 1u) {
            EXPECT_NEAR(luminanceAt(frame, view, p), luminanceAt(unshadowed, view, p), 1e-3f);
        }
    }
}

} // namespace
} // namespace simeco::test

namespace simeco::test {
namespace {

TEST_F(ShadowTest, CameraInsideAShadowVolumeStillCountsRight) {
    // A large sphere high above the ground with the sun straight overhead: its shadow is a disc of radius 1.5
    // around the origin. The camera stands in that shadow, inside the volume, where counting volume faces in
    // front of a surface (z-pass) would go wrong and counting those behind it (z-fail) does not.
    std::vector<OrganInstance> organs{makeSphere({0, 3.0f, 0}, 1.5f, 0, 1),
                                      makeSphere({2.5f, 0.02f, 2.5f}, 0.02f, 0, 2)};
    TestScene scene = uploadScene(context(), organs);
    ASSERT_NEAR(scene.bounds.min.y, 0.0f, 1e-6f);
    draw::RenderSettings s;
    s.width = 160;
    s.height = 120;
    s.sunDirection = glm::vec3(0, 1, 0);
    draw::Camera camera;
    camera.target = glm::vec3(0, 0, 0);
    camera.distance = 1.2f;
    camera.azimuthDegrees = 0.0f;
    camera.elevationDegrees = 25.0f;
    s.camera = camera;
    Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(frame, "camera_in_shadow");
    draw::CameraView view = draw::frameCamera(scene.bounds, s);
    ASSERT_LT(glm::length(glm::vec2(view.position.x, view.position.z)), 1.4f) << "the camera should be in the shadow";

    glm::vec3 shaded(0, 0, 0);
    glm::vec3 sunny(0, 0, -1.9f);
    ASSERT_EQ(organAt(frame, view, shaded), Frame::kNoId);
    ASSERT_EQ(organAt(frame, view, sunny), Frame::kNoId);
    EXPECT_LT(luminanceAt(frame, view, shaded), 0.6f * luminanceAt(frame, view, sunny));
}

} // namespace
} // namespace simeco::test
