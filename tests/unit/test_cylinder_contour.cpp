// cpfg's generalized-cylinder contours and meshes: the contour files in each of their versions (lang/
// cpfg_cylinder_contour.h) and what a malformed one gets; rings sampled as cpfg samples them (turtle/
// contour_ring.h); and a mesh's rings around the curve, its contour's x along cpfg's up (ours reversed) and its y
// against left (turtle/cylinder_mesh.h).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "ir/source_loc.h"
#include "lang/cpfg_cylinder_contour.h"
#include "turtle/contour_ring.h"
#include "turtle/cylinder_mesh.h"

namespace simeco {
namespace {

constexpr const char* kOpenLeaf = "cver 1 3\nname: leaf\npoints: 4 8\ntype: or\nsamples: 5\n"
                                  "-1 0 0 3\n-0.5 1 0 1\n0.5 1 0 1\n1 0 0 3\n";

TEST(CylinderContour, EveryVersionIsReadWithItsPointsRepeatedByTheirMultiplicity) {
    const ir::CylinderContour open = lang::parseCylinderContour(kOpenLeaf, "leaf.con");
    EXPECT_FALSE(open.closed);
    EXPECT_EQ(open.dimension, 3);
    ASSERT_EQ(open.points.size(), 8u);
    EXPECT_EQ(open.points[2][0], -1.0f);
    EXPECT_EQ(open.points[3][1], 1.0f);
    EXPECT_EQ(open.points[7][0], 1.0f);
    const ir::CylinderContour v11 =
        lang::parseCylinderContour("cver 1 1\nname: a\npoints: 3 3\ntype: closed\n0 1 0 1\n1 0 0 1\n0 -1 0 1\n", "a");
    EXPECT_TRUE(v11.closed);
    EXPECT_EQ(v11.points.size(), 3u);
    const ir::CylinderContour v12 =
        lang::parseCylinderContour("cver 1 2\nname: a\npoints: 2 4\ntype: cr\n0 1 0 2\n1 0 0 2\n", "a");
    EXPECT_TRUE(v12.closed);
    EXPECT_EQ(v12.points.size(), 4u);
    const ir::CylinderContour older = lang::parseCylinderContour("4 2 closed\n1 0\n0 1\n-1 0\n0 -1\n", "a");
    EXPECT_TRUE(older.closed);
    EXPECT_EQ(older.dimension, 2);
    EXPECT_EQ(older.points[1][1], 1.0f);
}

TEST(CylinderContour, AMalformedFileIsRefusedAtItsLineAndColumn) {
    auto error = [](const std::string& text) {
        try {
            lang::parseCylinderContour(text, "bad.con");
        } catch (const ir::InputError& e) {
            return e.formatted();
        }
        return std::string("accepted");
    };
    EXPECT_NE(error("cver 1 3\nname: a\npoints: 2 5\ntype: or\nsamples: 4\n0 0 0 3\n1 0 0 3\n")
                  .find("bad.con:7:1: error: the points' multiplicities add up to more than the 5"),
              std::string::npos);
    EXPECT_NE(error("cver 1 3\nname: a\npoints: 2 6\ntype: or\nsamples: 4\n0 0 0 3\n1 x 0 3\n")
                  .find("bad.con:7:3: error: expected a finite number for y, found 'x'"),
              std::string::npos);
    EXPECT_NE(error("cver 1 2\nname: a\npoints: 3 3\ntype: or\n0 0 0 1\n1 0 0 1\n2 0 0 1\n")
                  .find("an open contour needs at least 4 points"),
              std::string::npos);
    EXPECT_NE(error("cver 2 0\n").find("bad.con:1:6: error: contour version 2.0"), std::string::npos);
    EXPECT_NE(error("cver 1 1\nname: a\npoints: 3 3\n").find("bad.con:4:1: error: expected 'type: ...', found the "
                                                              "end of the file"),
              std::string::npos);
}

TEST(ContourRing, TheCircleStartsOnXAndGoesCounterClockwise) {
    const std::vector<glm::vec3> ring = turtle::contourRing(nullptr, 8);
    ASSERT_EQ(ring.size(), 9u);
    EXPECT_NEAR(ring[0].x, 1.0f, 1e-6f);
    EXPECT_NEAR(ring[2].y, 1.0f, 1e-6f);
    EXPECT_EQ(ring[8], ring[0]);
}

TEST(ContourRing, AClosedContourIsTurnedOntoXAndSampledEvenlyAlongIt) {
    const ir::CylinderContour square =
        lang::parseCylinderContour("cver 1 2\nname: a\npoints: 4 4\ntype: cr\n0 2 0 1\n-2 0 0 1\n0 -2 0 1\n2 0 0 1\n",
                                   "a");
    const std::vector<glm::vec3> ring = turtle::contourRing(&square, 12);
    ASSERT_EQ(ring.size(), 13u);
    EXPECT_GT(ring[0].x, 0.0f);
    EXPECT_NEAR(ring[0].y, 0.0f, 1e-6f);
    EXPECT_EQ(ring[12], ring[0]);
    std::vector<float> chords;
    for (size_t i = 1; i < ring.size(); ++i) chords.push_back(glm::distance(ring[i - 1], ring[i]));
    const auto [shortest, longest] = std::minmax_element(chords.begin(), chords.end());
    EXPECT_LT(*longest / *shortest, 1.1f);
}

TEST(ContourRing, AnOpenContourRunsFromItsFirstPointToATenthShortOfItsLast) {
    const ir::CylinderContour open = lang::parseCylinderContour(kOpenLeaf, "leaf.con");
    const std::vector<glm::vec3> ring = turtle::contourRing(&open, 10);
    ASSERT_EQ(ring.size(), 11u);
    EXPECT_NEAR(glm::distance(ring[0], glm::vec3(-1, 0, 0)), 0.0f, 1e-6f);
    // cpfg's table leaves out the curve's last tenth of a span: its last point falls just short of the end.
    const float shortBy = glm::distance(ring[10], glm::vec3(1, 0, 0));
    EXPECT_GT(shortBy, 1e-5f);
    EXPECT_LT(shortBy, 1e-3f);
}

TEST(CylinderMesh, RingsOfTheContourGoAroundTheCurveInCpfgsFrame) {
    turtle::CylinderPoint a, b;
    a.width = b.width = 2.0f;
    b.position = {0, 3, 0};
    const std::vector<glm::vec3> circle = turtle::contourRing(nullptr, 6);
    std::vector<glm::vec3> corners;
    std::vector<glm::vec3> normals;
    using turtle::MeshCorner;
    turtle::cylinderMesh(a, b, 3, 0.0f, 6, circle, 1e-5f,
                         [&](const MeshCorner& p, const MeshCorner& q, const MeshCorner& r) {
                             for (const MeshCorner* c : {&p, &q, &r}) {
                                 corners.push_back(c->position);
                                 normals.push_back(c->normal);
                             }
                         });
    ASSERT_EQ(corners.size(), 3u * 3u * 6u * 2u);
    for (size_t k = 0; k < corners.size(); ++k) {
        const glm::vec3 c = corners[k];
        EXPECT_NEAR(std::hypot(c.x, c.z), 1.0f, 1e-5f); // radius: half the width
        // Smooth: each corner's normal points straight out from the axis.
        EXPECT_NEAR(glm::distance(normals[k], glm::vec3(c.x, 0.0f, c.z)), 0.0f, 1e-5f);
    }
    // The first triangle: the second ring's first two points, then the first ring's first, whose contour point
    // (1, 0) lies along cpfg's up, ours (+z at first) reversed.
    EXPECT_NEAR(glm::distance(corners[2], glm::vec3(0, 0, -1)), 0.0f, 1e-6f);
    // The second ring at a third of the Hermite curve whose tangents are 1.2 times the chord of 3.
    EXPECT_NEAR(corners[0].y, 3.0f * (4.0f / 27 * 1.2f + 7.0f / 27 - 2.0f / 27 * 1.2f), 1e-5f);
    // Closer than the shortest stretch: nothing.
    b.position = {0, 1e-6f, 0};
    size_t drawn = 0;
    turtle::cylinderMesh(a, b, 3, 0.0f, 6, circle, 1e-5f,
                         [&](const MeshCorner&, const MeshCorner&, const MeshCorner&) { ++drawn; });
    EXPECT_EQ(drawn, 0u);
}

TEST(CylinderMesh, RadiusTangentsShapeTheRadiusAlongTheCurve) {
    turtle::CylinderPoint p;
    turtle::setRadiusTangents(p, {0.5f});
    EXPECT_EQ(p.scaleRadius, 0.5f);
    EXPECT_EQ(p.radiusIn, glm::vec2(0.0f));
    turtle::setRadiusTangents(p, {90.0f, 2.0f});
    EXPECT_NEAR(p.radiusIn.y, 2.0f, 1e-6f);
    EXPECT_EQ(p.radiusIn, p.radiusOut);
    turtle::setRadiusTangents(p, {0.0f, 1.0f, -90.0f, 3.0f});
    EXPECT_NEAR(p.radiusIn.x, 1.0f, 1e-6f);
    EXPECT_NEAR(p.radiusOut.y, -3.0f, 1e-6f);
    // Zero width at both ends, the radius rising out of the first point and falling into the second: the middle
    // ring is wide, its ends closed.
    turtle::CylinderPoint a, b;
    b.position = {0, 1, 0};
    turtle::setRadiusTangents(a, {0.0f, 0.0f, 90.0f, 1.0f});
    turtle::setRadiusTangents(b, {-90.0f, 1.0f, 0.0f, 0.0f});
    float widest = 0.0f;
    turtle::cylinderMesh(a, b, 2, 0.0f, 6, turtle::contourRing(nullptr, 6), 1e-5f,
                         [&](const turtle::MeshCorner& p0, const turtle::MeshCorner& p1,
                             const turtle::MeshCorner& p2) {
                             for (const turtle::MeshCorner* c : {&p0, &p1, &p2})
                                 widest = std::max(widest, std::hypot(c->position.x, c->position.z));
                         });
    EXPECT_GT(widest, 0.2f);
}

} // namespace
} // namespace simeco
