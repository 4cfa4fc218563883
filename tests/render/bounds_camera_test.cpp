// Bounds keys as the turtle kernels write them, and the camera framing a box.
#include <algorithm>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>
#include <gtest/gtest.h>

#include "draw/bounds.h"
#include "draw/camera.h"

namespace simeco::test {
namespace {

TEST(BoundsKeyTest, RoundTripsAndOrdersLikeFloats) {
    std::vector<float> values{-1e30f, -3.5f, -1.0f, -1e-20f, -0.0f, 0.0f, 1e-20f, 0.25f, 1.0f, 7.0f, 1e30f};
    for (std::size_t i = 0; i < values.size(); ++i) {
        EXPECT_EQ(draw::boundsValue(draw::boundsKey(values[i])), values[i]);
        if (i > 0 && values[i - 1] < values[i]) {
            EXPECT_LT(draw::boundsKey(values[i - 1]), draw::boundsKey(values[i])) << values[i - 1] << " " << values[i];
        }
    }
}

TEST(BoundsKeyTest, TableDecodesWhatWasEncoded) {
    draw::Bounds b{{-1.5f, 0.0f, -2.0f}, {3.0f, 4.5f, 0.5f}};
    shared::OrganTable table{};
    draw::encodeBounds(b, table);
    draw::Bounds decoded = draw::decodeBounds(table);
    EXPECT_EQ(decoded.min, b.min);
    EXPECT_EQ(decoded.max, b.max);
    EXPECT_FALSE(decoded.empty());
}

// Every corner of the box lands inside the frame, and the box is not tiny in it either.
void expectFramed(const draw::Camera& camera, const draw::Bounds& box, float aspect) {
    draw::CameraView view = draw::cameraView(camera, box, aspect);
    float largest = 0.0f;
    for (int corner = 0; corner < 8; ++corner) {
        glm::vec3 c((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                    (corner & 4) ? box.max.z : box.min.z);
        glm::vec4 clip = view.viewProj * glm::vec4(c, 1.0f);
        ASSERT_GT(clip.w, 0.0f);
        glm::vec3 ndc = glm::vec3(clip) / clip.w;
        EXPECT_LE(std::abs(ndc.x), 0.95f) << "corner " << corner;
        EXPECT_LE(std::abs(ndc.y), 0.95f) << "corner " << corner;
        EXPECT_GT(ndc.z, 0.0f);
        EXPECT_LT(ndc.z, 1.0f);
        largest = std::max({largest, std::abs(ndc.x), std::abs(ndc.y)});
    }
    EXPECT_GT(largest, 0.85f) << "the box should fill the frame up to the margin";
}

TEST(CameraTest, FramesTheWholeBoxWithAMargin) {
    expectFramed({}, {{-0.05f, 0.0f, -0.05f}, {0.05f, 1.0f, 0.05f}}, 4.0f / 3.0f); // a thin stem
    expectFramed({}, {{-5.0f, 0.0f, -5.0f}, {5.0f, 0.5f, 5.0f}}, 16.0f / 9.0f);    // a wide flat field
    draw::Camera above;
    above.azimuthDegrees = 200.0f;
    above.elevationDegrees = 70.0f;
    expectFramed(above, {{10.0f, 2.0f, -3.0f}, {12.0f, 5.0f, 1.0f}}, 1.0f);
}

TEST(CameraTest, GivenDistanceAndTargetAreKept) {
    draw::Camera c;
    c.distance = 10.0f;
    c.target = glm::vec3(1, 2, 3);
    c.azimuthDegrees = 90.0f;
    c.elevationDegrees = 0.0f;
    draw::CameraView view = draw::cameraView(c, {{0, 0, 0}, {1, 1, 1}}, 1.0f);
    EXPECT_NEAR(glm::distance(view.position, glm::vec3(1, 2, 3)), 10.0f, 1e-4f);
    // Azimuth 90 degrees puts the camera on +x of the target, looking along -x.
    EXPECT_NEAR(view.position.x, 11.0f, 1e-4f);
    EXPECT_NEAR(view.right.z, -1.0f, 1e-5f);
    EXPECT_NEAR(view.up.y, 1.0f, 1e-5f);
}

TEST(CameraTest, EmptyBoundsStillGiveAFrame) {
    draw::Bounds empty{glm::vec3(1), glm::vec3(-1)};
    ASSERT_TRUE(empty.empty());
    draw::CameraView view = draw::cameraView({}, empty, 1.0f);
    EXPECT_TRUE(std::isfinite(view.viewProj[0][0]));
    EXPECT_GT(view.farPlane, view.nearPlane);
    EXPECT_GT(view.nearPlane, 0.0f);
}

} // namespace
} // namespace simeco::test
