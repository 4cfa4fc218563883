// Frames rendered from hand-made instance buffers: framing, where organs land, ids, the table's counts, and
// the toon style.
#include <algorithm>
#include <cmath>
#include <memory>
#include <set>
#include <string>
#include <stdexcept>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "draw/renderer.h"
#include "gpu_fixture.h"
#include "test_scene.h"

namespace simeco::test {
namespace {

using draw::Frame;

class RendererTest : public RenderTest {};

draw::RenderSettings smallSettings(std::uint32_t width = 160, std::uint32_t height = 120) {
    draw::RenderSettings s;
    s.width = width;
    s.height = height;
    s.shadows = draw::Shadows::None;
    return s;
}

TEST_F(RendererTest, VerticalStemIsFramedWhereItsBoundsProject) {
    TestScene scene = uploadScene(context(), {makeStem({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0f, 0.05f, 0, 7)});
    draw::RenderSettings s = smallSettings();
    Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(frame, "stem_framed");
    ASSERT_EQ(frame.width, s.width);
    ASSERT_EQ(frame.height, s.height);

    PixelBox stem = organPixels(frame, 7);
    ASSERT_FALSE(stem.empty());
    // A sane share of the frame: most of its height, a thin strip of its width, not touching the edges.
    float heightShare = static_cast<float>(stem.maxY - stem.minY + 1) / static_cast<float>(frame.height);
    EXPECT_GT(heightShare, 0.6f);
    EXPECT_LT(heightShare, 1.0f);
    EXPECT_GT(stem.minY, 0);
    EXPECT_LT(stem.maxY, static_cast<int>(frame.height) - 1);
    EXPECT_LT(stem.pixels, frame.pixelCount() / 4);

    // The silhouette lies within the projection of the stem's bounding box and spans nearly all of it.
    draw::CameraView camera = draw::frameCamera(scene.bounds, s);
    glm::vec2 lo(1e9f), hi(-1e9f);
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 c((corner & 1) ? scene.bounds.max.x : scene.bounds.min.x,
                    (corner & 2) ? scene.bounds.max.y : scene.bounds.min.y,
                    (corner & 4) ? scene.bounds.max.z : scene.bounds.min.z);
        glm::vec2 p = projectToPixel(camera, c, frame.width, frame.height);
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    EXPECT_GE(static_cast<float>(stem.minX), lo.x - 1.0f);
    EXPECT_LE(static_cast<float>(stem.maxX), hi.x + 1.0f);
    EXPECT_GE(static_cast<float>(stem.minY), lo.y - 1.0f);
    EXPECT_LE(static_cast<float>(stem.maxY), hi.y + 1.0f);
    EXPECT_GT(static_cast<float>(stem.maxY - stem.minY + 1), 0.9f * (hi.y - lo.y));
    // The axis of the stem projects onto the silhouette's middle.
    glm::vec2 base = projectToPixel(camera, {0, 0, 0}, frame.width, frame.height);
    glm::vec2 top = projectToPixel(camera, {0, 1, 0}, frame.width, frame.height);
    EXPECT_NEAR(0.5f * (stem.minX + stem.maxX + 1), 0.5f * (base.x + top.x), 1.5f);
}

// The widest row of an organ's pixels.
int widestRow(const Frame& frame, std::uint32_t organ) {
    int widest = 0;
    for (std::uint32_t y = 0; y < frame.height; ++y) {
        int row = 0;
        for (std::uint32_t x = 0; x < frame.width; ++x) row += frame.organ[frame.index(x, y)] == organ ? 1 : 0;
        widest = std::max(widest, row);
    }
    return widest;
}

TEST_F(RendererTest, CpfgsPixelLinesKeepTheirWidthInPixelsAndItsBandsTheirsInTheWorld) {
    // A vertical segment of radius 2 beside a taller one that sets the framing: as a cylinder or a flat band the
    // radius is world units (a fifth of the segment's length), as a pixel line 2 pixels at any framing.
    auto drawn = [&](std::uint32_t style, float frameHeight, bool parallel = false) {
        shared::OrganInstance line = makeStem({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 10.0f, 2.0f, 0, 7);
        line.shape = style;
        shared::OrganInstance mast = makeStem({30, 0, 0}, {0, 1, 0}, {0, 0, 1}, frameHeight, 0.01f, 0, 8);
        TestScene scene = uploadScene(context(), {line, mast});
        draw::RenderSettings s = smallSettings(320, 240);
        s.camera = draw::Camera{};
        s.camera->parallel = parallel;
        Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
        maybeSavePreview(frame, "line_style_" + std::to_string(style) + "_" + std::to_string(int(frameHeight)) +
                                    (parallel ? "_parallel" : ""));
        return widestRow(frame, 7);
    };
    const int pixelNear = drawn(shared::kLinePixel, 20.0f), pixelFar = drawn(shared::kLinePixel, 80.0f);
    EXPECT_GE(pixelNear, 3);
    EXPECT_LE(pixelNear, 6);
    EXPECT_LE(std::abs(pixelNear - pixelFar), 1);
    // So in a parallel projection too, where a pixel has one size at every depth.
    EXPECT_LE(std::abs(drawn(shared::kLinePixel, 20.0f, true) - pixelNear), 1);
    EXPECT_LE(std::abs(drawn(shared::kLinePixel, 80.0f, true) - pixelNear), 1);
    // World units: 4 wide against a frame about 20 or 80 high.
    const int bandNear = drawn(shared::kLinePolygon, 20.0f), bandFar = drawn(shared::kLinePolygon, 80.0f);
    const int cylinderNear = drawn(shared::kLineCylinder, 20.0f);
    EXPECT_GT(bandNear, 2 * pixelNear);
    EXPECT_GT(bandNear, 2 * bandFar);
    EXPECT_NEAR(cylinderNear, bandNear, 2);
}

TEST_F(RendererTest, SphereAppearsWhereTheCameraProjectsItWithItsFrontDepthInEitherProjection) {
    glm::vec3 centre(2.0f, 1.0f, -1.0f);
    float radius = 0.3f;
    TestScene scene = uploadScene(
        context(), {makeSphere(centre, radius, 3, 42), makeStem({0, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.5f, 0.05f, 0, 1)});
    for (bool parallel : {false, true}) {
        SCOPED_TRACE(parallel ? "parallel" : "perspective");
        draw::RenderSettings s = smallSettings(200, 150);
        draw::Camera camera;
        camera.azimuthDegrees = -40.0f;
        camera.elevationDegrees = 25.0f;
        camera.distance = 6.0f;
        camera.target = glm::vec3(1.0f, 0.5f, 0.0f);
        camera.parallel = parallel;
        s.camera = camera;
        Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
        maybeSavePreview(frame, parallel ? "sphere_projected_parallel" : "sphere_projected");

        draw::CameraView view = draw::frameCamera(scene.bounds, s);
        EXPECT_EQ(view.parallel, parallel);
        glm::vec2 p = projectToPixel(view, centre, frame.width, frame.height);
        auto x = static_cast<std::uint32_t>(p.x);
        auto y = static_cast<std::uint32_t>(p.y);
        ASSERT_LT(x, frame.width);
        ASSERT_LT(y, frame.height);
        EXPECT_EQ(frame.organ[frame.index(x, y)], 42u);
        EXPECT_EQ(frame.plant[frame.index(x, y)], 3u);
        // The surface seen is the near side of the sphere (back faces are culled, not front faces).
        glm::vec3 forward = glm::normalize(view.target - view.position);
        float centreDepth = glm::dot(centre - view.position, forward);
        EXPECT_NEAR(frame.depth[frame.index(x, y)], centreDepth - radius, 0.03f);
        // Its silhouette is centred on the projected centre, about as wide as the projected diameter.
        PixelBox sphere = organPixels(frame, 42);
        EXPECT_NEAR(0.5f * (sphere.minX + sphere.maxX + 1), p.x, 1.5f);
        EXPECT_NEAR(0.5f * (sphere.minY + sphere.maxY + 1), p.y, 1.5f);
        glm::vec2 edge = projectToPixel(view, centre + radius * view.right, frame.width, frame.height);
        EXPECT_NEAR(static_cast<float>(sphere.maxX - sphere.minX + 1), 2.0f * (edge.x - p.x), 2.5f);
    }
}

TEST_F(RendererTest, AParallelProjectionDrawsEqualSpheresAtAnyDepthAlike) {
    // Two equal spheres side by side, one far behind the other as the camera looks from +z: in perspective the
    // near one is larger, in parallel they are the same size.
    TestScene scene = uploadScene(
        context(), {makeSphere({-1.0f, 0.5f, 2.0f}, 0.5f, 0, 1), makeSphere({1.0f, 0.5f, -6.0f}, 0.5f, 0, 2)});
    auto widths = [&](bool parallel) {
        draw::RenderSettings s = smallSettings(240, 120);
        draw::Camera camera;
        camera.azimuthDegrees = 0.0f;
        camera.elevationDegrees = 0.0f;
        camera.parallel = parallel;
        s.camera = camera;
        s.ground = false;
        Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
        maybeSavePreview(frame, parallel ? "two_spheres_parallel" : "two_spheres_perspective");
        return std::pair<int, int>{widestRow(frame, 1), widestRow(frame, 2)};
    };
    const auto [nearPerspective, farPerspective] = widths(false);
    const auto [nearParallel, farParallel] = widths(true);
    EXPECT_GT(nearPerspective, farPerspective * 5 / 4);
    EXPECT_GT(farParallel, 4);
    EXPECT_LE(std::abs(nearParallel - farParallel), 1);
}

TEST_F(RendererTest, IdsAreThoseOfTheInstancesDrawnThereAndBackgroundHasNone) {
    std::vector<OrganInstance> organs{
        makeStem({-2, 0, 0}, {0, 1, 0}, {0, 0, 1}, 1.0f, 0.15f, 10, 100),
        makeSphere({-1, 0.5f, 0}, 0.3f, 11, 101),
        makeLeaf({0, 0.2f, 0}, {0, 1, 0}, {0, 0, 1}, 0.8f, 0.6f, shared::kLeafOvate, 12, 102),
        makeDisc({1, 0.5f, 0}, {0, 1, 0}, {0, 0, 1}, 0.35f, 13, 103),
        makeTriangle({1.7f, 0.1f, 0}, {2.3f, 0.1f, 0}, {2.0f, 0.9f, 0}, 14, 104),
    };
    TestScene scene = uploadScene(context(), organs);
    draw::RenderSettings s = smallSettings(240, 120);
    draw::Camera camera;
    camera.azimuthDegrees = 0.0f; // from +z, facing the leaf, disc and triangle
    camera.elevationDegrees = 10.0f;
    s.camera = camera;
    Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(frame, "ids");
    draw::CameraView view = draw::frameCamera(scene.bounds, s);

    const std::pair<glm::vec3, std::uint32_t> probes[] = {{{-2, 0.5f, 0.15f}, 100},
                                                          {{-1, 0.5f, 0.3f}, 101},
                                                          {{0, 0.5f, 0}, 102},
                                                          {{1, 0.5f, 0}, 103},
                                                          {{2, 0.4f, 0}, 104}};
    for (const auto& [point, module] : probes) {
        glm::vec2 p = projectToPixel(view, point, frame.width, frame.height);
        std::size_t i = frame.index(static_cast<std::uint32_t>(p.x), static_cast<std::uint32_t>(p.y));
        EXPECT_EQ(frame.organ[i], module) << "at " << p.x << "," << p.y;
        EXPECT_EQ(frame.plant[i], module - 90) << "at " << p.x << "," << p.y;
        EXPECT_TRUE(std::isfinite(frame.depth[i]));
        EXPECT_EQ(frame.rgba[4 * i + 3], 1.0f);
    }
    // Every id in the frame belongs to an instance, with its own plant; the sky has none and no depth.
    std::set<std::uint32_t> seen;
    for (std::size_t i = 0; i < frame.pixelCount(); ++i) {
        if (frame.organ[i] == Frame::kNoId) {
            EXPECT_EQ(frame.plant[i], Frame::kNoId);
            continue;
        }
        seen.insert(frame.organ[i]);
        EXPECT_EQ(frame.plant[i], frame.organ[i] - 90);
    }
    EXPECT_EQ(seen, (std::set<std::uint32_t>{100, 101, 102, 103, 104}));
    std::size_t sky = frame.index(0, 0);
    EXPECT_EQ(frame.organ[sky], Frame::kNoId);
    EXPECT_EQ(frame.plant[sky], Frame::kNoId);
    EXPECT_TRUE(std::isinf(frame.depth[sky]));
    EXPECT_EQ(frame.rgba[4 * sky + 3], 0.0f);
    // The ground has no ids but a depth.
    std::size_t ground = frame.index(frame.width / 2, frame.height - 1);
    EXPECT_EQ(frame.organ[ground], Frame::kNoId);
    EXPECT_TRUE(std::isfinite(frame.depth[ground]));
}

TEST_F(RendererTest, LeafLiesInTheHeadingLeftPlane) {
    // Heading +x and up +z: left = up x heading = +y, so the blade lies in the x-y plane.
    OrganInstance leaf = makeLeaf({-0.5f, 0.5f, 0}, {1, 0, 0}, {0, 0, 1}, 1.0f, 0.5f, shared::kLeafLanceolate, 0, 5);
    TestScene scene = uploadScene(context(), {leaf});
    draw::RenderSettings s = smallSettings(160, 160);
    s.ground = false;
    draw::Camera camera;
    camera.target = glm::vec3(0, 0.5f, 0);
    camera.distance = 4.0f;

    camera.azimuthDegrees = 0.0f; // looking along -z: the blade face on
    camera.elevationDegrees = 0.0f;
    s.camera = camera;
    Frame faceOn = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(faceOn, "leaf_face_on");
    PixelBox blade = organPixels(faceOn, 5);
    ASSERT_FALSE(blade.empty());
    draw::CameraView view = draw::frameCamera(scene.bounds, s);
    glm::vec2 base = projectToPixel(view, {-0.5f, 0.5f, 0}, s.width, s.height);
    glm::vec2 tip = projectToPixel(view, {0.5f, 0.5f, 0}, s.width, s.height);
    glm::vec2 side = projectToPixel(view, {-0.5f, 0.75f, 0}, s.width, s.height);
    // Length along image x (heading), width along image y (left): a lanceolate blade is as wide as `width`.
    EXPECT_NEAR(static_cast<float>(blade.maxX - blade.minX + 1), tip.x - base.x, 2.0f);
    float widthPixels = 2.0f * (base.y - side.y);
    EXPECT_NEAR(static_cast<float>(blade.maxY - blade.minY + 1), widthPixels, 2.5f);

    camera.azimuthDegrees = 90.0f; // looking along -x: edge on
    s.camera = camera;
    Frame edgeOn = renderer().render(scene.instances, scene.table, scene.bounds, s);
    PixelBox edge = organPixels(edgeOn, 5);
    EXPECT_LE(edge.maxX - edge.minX + 1, 2) << "seen along the heading, the blade is a line";

    camera.azimuthDegrees = 0.0f; // looking down -y: edge on across the width
    camera.elevationDegrees = 89.0f;
    s.camera = camera;
    Frame fromAbove = renderer().render(scene.instances, scene.table, scene.bounds, s);
    PixelBox above = organPixels(fromAbove, 5);
    EXPECT_LE(above.maxY - above.minY + 1, 3) << "seen along left, the blade is a line";
}

TEST_F(RendererTest, DrawsFollowTheTableCounts) {
    // Three spheres in the buffer, but the table says one: only the first is drawn.
    std::vector<OrganInstance> organs{makeSphere({-1, 0.5f, 0}, 0.3f, 0, 1), makeSphere({0, 0.5f, 0}, 0.3f, 0, 2),
                                      makeSphere({1, 0.5f, 0}, 0.3f, 0, 3)};
    TestScene scene = uploadScene(context(), organs, std::vector<std::uint32_t>{0, 1, 0, 0, 0});
    Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, smallSettings());
    EXPECT_FALSE(organPixels(frame, 1).empty());
    EXPECT_TRUE(organPixels(frame, 2).empty());
    EXPECT_TRUE(organPixels(frame, 3).empty());

    TestScene none = uploadScene(context(), organs, std::vector<std::uint32_t>{0, 0, 0, 0, 0});
    Frame empty = renderer().render(none.instances, none.table, none.bounds, smallSettings());
    EXPECT_TRUE(organPixels(empty).empty());
}

TEST_F(RendererTest, EmptySceneShowsGroundAndSky) {
    TestScene scene = uploadScene(context(), {});
    ASSERT_TRUE(scene.bounds.empty());
    for (draw::Shadows shadows : {draw::Shadows::None, draw::Shadows::Volume}) {
        draw::RenderSettings s = smallSettings();
        s.shadows = shadows;
        Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
        EXPECT_TRUE(organPixels(frame).empty());
        EXPECT_TRUE(std::isinf(frame.depth[frame.index(0, 0)]));
        EXPECT_TRUE(std::isfinite(frame.depth[frame.index(frame.width / 2, frame.height - 1)]));
    }
}

TEST_F(RendererTest, OutlineStyleInksTheSilhouetteOverTheToonStylesBands) {
    TestScene scene = uploadScene(context(), {makeSphere({0, 0.5f, 0}, 0.5f, 0, 9)});
    draw::RenderSettings s = smallSettings();
    Frame lit = renderer().render(scene.instances, scene.table, scene.bounds, s);
    s.style = draw::Style::Toon;
    Frame toon = renderer().render(scene.instances, scene.table, scene.bounds, s);
    s.style = draw::Style::Outline;
    Frame outline = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(outline, "outline_sphere");
    EXPECT_EQ(toon.organ, lit.organ);
    EXPECT_EQ(outline.organ, lit.organ);
    // Along the middle row, the sphere's outermost pixels carry the line colour in the outline style only.
    std::uint32_t y = (static_cast<std::uint32_t>(organPixels(lit, 9).minY) + organPixels(lit, 9).maxY) / 2;
    std::uint32_t left = 0;
    while (left < outline.width && outline.organ[outline.index(left, y)] != 9) {
        ++left;
    }
    ASSERT_LT(left, outline.width);
    EXPECT_LT(luminance(outline, left, y), 0.05f);
    EXPECT_GT(luminance(toon, left, y), 0.05f);
    EXPECT_GT(luminance(lit, left, y), 0.05f);
    // Inside, colours come in bands in both: few distinct values across the row, where lit has many.
    for (const Frame* banded : {&toon, &outline}) {
        std::set<float> shades;
        for (std::uint32_t x = left + 3; x < banded->width && banded->organ[banded->index(x + 3, y)] == 9; ++x) {
            shades.insert(luminance(*banded, x, y));
        }
        EXPECT_LE(shades.size(), 6u);
    }
}

TEST_F(RendererTest, RejectsZeroSize) {
    TestScene scene = uploadScene(context(), {});
    draw::RenderSettings s = smallSettings(0, 10);
    EXPECT_THROW(renderer().render(scene.instances, scene.table, scene.bounds, s), std::invalid_argument);
}

} // namespace
} // namespace simeco::test

namespace simeco::test {
namespace {

TEST_F(RendererTest, BentStemIsClosedOnTheOuterSideOfTheJoint) {
    // Two segments bending 45 degrees towards +x; their ends are cut on the bisecting plane. Flat ends would
    // leave a wedge open on the outer (-x) side of the joint.
    glm::vec3 lower(0, 1, 0);
    glm::vec3 upper = glm::normalize(glm::vec3(1, 1, 0));
    float radius = 0.1f;
    OrganInstance a = makeStem({0, 0, 0}, lower, {0, 0, 1}, 1.0f, radius, 0, 1);
    OrganInstance b = makeStem({0, 1, 0}, upper, {0, 0, 1}, 1.0f, radius, 0, 2);
    a.nextHeading = {upper.x, upper.y, upper.z, 0};
    b.previousHeading = {lower.x, lower.y, lower.z, 0};
    TestScene scene = uploadScene(context(), {a, b});
    draw::RenderSettings s = smallSettings(200, 200);
    s.ground = false;
    draw::Camera camera;
    camera.azimuthDegrees = 0.0f;
    camera.elevationDegrees = 0.0f;
    camera.distance = 3.0f;
    camera.target = glm::vec3(0.2f, 1.0f, 0.0f);
    s.camera = camera;
    Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(frame, "bent_stem");
    draw::CameraView view = draw::frameCamera(scene.bounds, s);

    glm::vec3 joint(0, 1, 0);
    glm::vec3 outward(-0.924f, 0.383f, 0.0f); // in the bisecting plane, away from the bend
    float outerCorner = radius / std::cos(glm::radians(22.5f));
    glm::vec2 inside = projectToPixel(view, joint + 0.85f * outerCorner * outward, s.width, s.height);
    glm::vec2 outside = projectToPixel(view, joint + 1.3f * outerCorner * outward, s.width, s.height);
    std::uint32_t covered =
        frame.organ[frame.index(static_cast<std::uint32_t>(inside.x), static_cast<std::uint32_t>(inside.y))];
    EXPECT_TRUE(covered == 1u || covered == 2u) << "the outer side of the joint is open";
    EXPECT_EQ(frame.organ[frame.index(static_cast<std::uint32_t>(outside.x), static_cast<std::uint32_t>(outside.y))],
              Frame::kNoId);
    // The segments meet on the bisecting plane: each covers only its own side of it.
    glm::vec3 n = glm::normalize(lower + upper);
    glm::vec2 belowPlane = projectToPixel(view, joint - 0.05f * n, s.width, s.height);
    glm::vec2 abovePlane = projectToPixel(view, joint + 0.05f * n, s.width, s.height);
    EXPECT_EQ(
        frame.organ[frame.index(static_cast<std::uint32_t>(belowPlane.x), static_cast<std::uint32_t>(belowPlane.y))],
        1u);
    EXPECT_EQ(
        frame.organ[frame.index(static_cast<std::uint32_t>(abovePlane.x), static_cast<std::uint32_t>(abovePlane.y))],
        2u);
}

// A small hand-made plant with every organ kind and leaf shape, rendered in both styles with shadows.
std::vector<OrganInstance> samplePlant() {
    std::vector<OrganInstance> organs;
    std::uint32_t module = 0;
    glm::vec3 position(0, 0, 0);
    glm::vec3 headings[] = {{0, 1, 0},
                            glm::normalize(glm::vec3(0.15f, 1, 0)),
                            glm::normalize(glm::vec3(0.3f, 1, 0.1f)),
                            glm::normalize(glm::vec3(0.3f, 1, 0.3f))};
    for (int i = 0; i < 4; ++i) {
        glm::vec3 h = headings[i];
        glm::vec3 up = glm::normalize(glm::cross(h, glm::vec3(1, 0, 0)));
        OrganInstance stem = makeStem(position, h, up, 0.6f, 0.05f - 0.008f * i, 0, module++);
        stem.up.w = 0.05f - 0.008f * (i + 1);
        if (i > 0) {
            stem.previousHeading = {headings[i - 1].x, headings[i - 1].y, headings[i - 1].z, 0};
        }
        if (i < 3) {
            stem.nextHeading = {headings[i + 1].x, headings[i + 1].y, headings[i + 1].z, 0};
        }
        organs.push_back(stem);
        // A leaf to alternating sides, each of a different shape, tilted up from horizontal.
        glm::vec3 side = (i % 2 == 0) ? glm::vec3(1, 0.4f, 0.3f) : glm::vec3(-1, 0.4f, -0.2f);
        glm::vec3 leafHeading = glm::normalize(side);
        glm::vec3 leafUp = glm::normalize(glm::cross(glm::cross(leafHeading, glm::vec3(0, 1, 0)), leafHeading));
        organs.push_back(makeLeaf(position + 0.3f * h, leafHeading, leafUp, 0.55f, 0.3f, static_cast<std::uint32_t>(i),
                                  0, module++));
        position += 0.6f * h;
    }
    organs.push_back(makeSphere(position, 0.09f, 0, module++));
    OrganInstance flower = makeDisc(position + glm::vec3(0, 0.1f, 0), {0, 0, 1}, {0, 1, 0}, 0.16f, 0, module++);
    flower.shape = shared::kDiscFacesViewer;
    organs.push_back(flower);
    organs.push_back(makeTriangle({0.5f, 0.02f, 0.4f}, {0.8f, 0.02f, 0.5f}, {0.6f, 0.3f, 0.6f}, 1, module++));
    return organs;
}

TEST_F(RendererTest, SmallPlantShowsEveryOrganInEveryStyle) {
    std::vector<OrganInstance> organs = samplePlant();
    TestScene scene = uploadScene(context(), organs);
    for (draw::Style style : {draw::Style::Lit, draw::Style::Toon, draw::Style::Outline, draw::Style::PaperCut}) {
        draw::RenderSettings s;
        s.width = 320;
        s.height = 320;
        s.style = style;
        Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
        maybeSavePreview(frame, "plant_style_" + std::to_string(static_cast<int>(style)));
        std::set<std::uint32_t> seen(frame.organ.begin(), frame.organ.end());
        for (const OrganInstance& o : organs) {
            EXPECT_TRUE(seen.count(o.module)) << "organ " << o.module << " (kind " << o.kind << ") not visible";
        }
    }
}

} // namespace
} // namespace simeco::test

namespace simeco::test {
namespace {

TEST_F(RendererTest, EachLeafShapeDrawsItsOwnOutline) {
    // The four shapes side by side, face on; each covers its own area, and a leaf shows nothing of the others.
    std::vector<OrganInstance> organs;
    for (std::uint32_t shape = 0; shape < 4; ++shape) {
        organs.push_back(makeLeaf({1.2f * static_cast<float>(shape), 0.2f, 0}, {0, 1, 0}, {0, 0, 1}, 1.0f, 0.8f, shape,
                                  shape, 20 + shape));
    }
    TestScene scene = uploadScene(context(), organs);
    draw::RenderSettings s = smallSettings(400, 160);
    draw::Camera camera;
    camera.azimuthDegrees = 0.0f;
    camera.elevationDegrees = 0.0f;
    s.camera = camera;
    Frame frame = renderer().render(scene.instances, scene.table, scene.bounds, s);
    maybeSavePreview(frame, "leaf_shapes");
    std::set<std::size_t> areas;
    for (std::uint32_t shape = 0; shape < 4; ++shape) {
        PixelBox leaf = organPixels(frame, 20 + shape);
        ASSERT_FALSE(leaf.empty()) << "shape " << shape;
        areas.insert(leaf.pixels);
        // Nothing of this leaf strays towards its neighbours (the other shapes' vertices collapse).
        glm::vec2 centre = projectToPixel(draw::frameCamera(scene.bounds, s),
                                          {1.2f * static_cast<float>(shape), 0.7f, 0}, s.width, s.height);
        EXPECT_LT(std::abs(0.5f * (leaf.minX + leaf.maxX + 1) - centre.x), 0.2f * static_cast<float>(s.width) / 4.0f);
    }
    EXPECT_EQ(areas.size(), 4u) << "the shapes should differ in area";
}

} // namespace
} // namespace simeco::test
