// The quadrilateral a leaf a few pixels across casts its shadow from (draw::silhouetteQuad) and the area a shape's
// triangles cover (draw::coveredArea).
#include <cmath>
#include <numbers>
#include <vector>

#include <gtest/gtest.h>

#include "draw/leaf_silhouette.h"

namespace simeco::draw {
namespace {

float quadArea(const std::array<glm::vec2, 4>& q) {
    float twice = 0.0f;
    for (std::size_t i = 0; i < 4; ++i)
        twice += q[i].x * q[(i + 1) % 4].y - q[(i + 1) % 4].x * q[i].y;
    return 0.5f * twice;
}

// Points of a circle of radius 2 about (3, 1), with points inside it that are not on its hull.
std::vector<glm::vec2> circlePoints(std::size_t n) {
    std::vector<glm::vec2> points;
    for (std::size_t i = 0; i < n; ++i) {
        const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / float(n);
        points.push_back(glm::vec2(3, 1) + 2.0f * glm::vec2(std::cos(angle), std::sin(angle)));
        points.push_back(glm::vec2(3, 1) + 0.5f * glm::vec2(std::cos(angle), std::sin(angle)));
    }
    return points;
}

TEST(LeafSilhouette, ACircleCastsFromASquareAboutItsCentreOfTheAreaAskedForCounterClockwise) {
    for (std::size_t n : {8, 12, 40, 200}) { // 200 corners: the hull thinned before the search
        for (float area : {12.566f, 3.0f}) {
            const auto quad = silhouetteQuad(circlePoints(n), area);
            ASSERT_TRUE(quad) << n;
            EXPECT_NEAR(quadArea(*quad), area, 1e-3f * area) << n; // positive: counter-clockwise
            glm::vec2 middle(0.0f);
            for (glm::vec2 p : *quad)
                middle += 0.25f * p;
            EXPECT_NEAR(middle.x, 3.0f, 1e-3f);
            EXPECT_NEAR(middle.y, 1.0f, 1e-3f);
            // The largest quadrilateral in a circle is a square: its sides alike, its diagonals alike.
            const float side = glm::distance((*quad)[0], (*quad)[1]);
            for (std::size_t i = 1; i < 4; ++i)
                EXPECT_NEAR(glm::distance((*quad)[i], (*quad)[(i + 1) % 4]), side, 0.05f * side) << n;
            EXPECT_NEAR(glm::distance((*quad)[0], (*quad)[2]), glm::distance((*quad)[1], (*quad)[3]), 0.05f * side);
        }
    }
}

TEST(LeafSilhouette, AnElongatedOutlineCastsFromAQuadrilateralAlongIt) {
    // An ellipse 6 long and 1 wide: the quadrilateral reaches its tips and its flanks.
    std::vector<glm::vec2> points;
    for (int i = 0; i < 24; ++i) {
        const float angle = 2.0f * std::numbers::pi_v<float> * float(i) / 24.0f;
        points.emplace_back(3.0f * std::cos(angle), 0.5f * std::sin(angle));
    }
    const auto quad = silhouetteQuad(points, 2.0f);
    ASSERT_TRUE(quad);
    glm::vec2 low(1e9f), high(-1e9f);
    for (glm::vec2 p : *quad) {
        low = glm::min(low, p);
        high = glm::max(high, p);
    }
    EXPECT_GT(high.x - low.x, 4.0f * (high.y - low.y));
    EXPECT_NEAR(quadArea(*quad), 2.0f, 2e-3f);
}

TEST(LeafSilhouette, FewerThanFourHullCornersOrNoAreaCastNoQuadrilateral) {
    // A triangle with points inside it and on its edges.
    const std::vector<glm::vec2> triangle{{0, 0}, {4, 0}, {0, 4}, {1, 1}, {2, 0}, {2, 2}, {0, 2}};
    EXPECT_FALSE(silhouetteQuad(triangle, 1.0f));
    const std::vector<glm::vec2> line{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}};
    EXPECT_FALSE(silhouetteQuad(line, 1.0f));
    EXPECT_FALSE(silhouetteQuad(circlePoints(8), 0.0f));
    EXPECT_FALSE(silhouetteQuad({}, 1.0f));
}

TEST(LeafSilhouette, TheCoveredAreaCountsOverlapsOnceWhateverTheWinding) {
    // Two unit squares overlapping by half, each as two triangles, one of them wound clockwise.
    const std::vector<glm::vec2> corners{{0, 0},    {1, 0},    {1, 1},    {0, 0},    {1, 1},    {0, 1},
                                         {0.5f, 0}, {1.5f, 1}, {1.5f, 0}, {0.5f, 0}, {0.5f, 1}, {1.5f, 1}};
    EXPECT_NEAR(coveredArea(corners), 1.5f, 0.02f);
    // A fan of a circle of radius 1: its polygon's area.
    std::vector<glm::vec2> fan;
    const int n = 32;
    for (int i = 0; i < n; ++i) {
        const float a0 = 2.0f * std::numbers::pi_v<float> * float(i) / float(n);
        const float a1 = 2.0f * std::numbers::pi_v<float> * float(i + 1) / float(n);
        fan.insert(fan.end(),
                   {glm::vec2(0), glm::vec2(std::cos(a0), std::sin(a0)), glm::vec2(std::cos(a1), std::sin(a1))});
    }
    const float polygon = 0.5f * float(n) * std::sin(2.0f * std::numbers::pi_v<float> / float(n));
    EXPECT_NEAR(coveredArea(fan), polygon, 0.01f * polygon);
    EXPECT_EQ(coveredArea({}), 0.0f);
    const std::vector<glm::vec2> flat{{0, 0}, {1, 1}, {2, 2}};
    EXPECT_EQ(coveredArea(flat), 0.0f);
}

} // namespace
} // namespace simeco::draw
