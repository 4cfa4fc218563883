// The procedural organ meshes on the CPU: closed meshes wound outwards and watertight, hulls inside what is
// drawn, leaf blades flat in the heading-left plane.
#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <gtest/gtest.h>

#include "draw/organ_meshes.h"
#include "ir/leaf_model.h"

namespace simeco::test {
namespace {

using draw::MeshRange;
using draw::OrganMeshData;

glm::vec3 position(const OrganMeshData& d, const MeshRange& m, std::uint32_t i) {
    const shared::vec4& p = d.vertices[static_cast<std::size_t>(m.vertexOffset) + d.indices[m.firstIndex + i]].position;
    return {p.x, p.y, p.z};
}

// For a convex closed mesh around `centre`, every face's winding normal points away from the centre.
void expectWoundOutwards(const OrganMeshData& d, const MeshRange& m, glm::vec3 centre, const char* name) {
    ASSERT_GT(m.triangleCount(), 0u) << name;
    for (std::uint32_t t = 0; t < m.triangleCount(); ++t) {
        glm::vec3 a = position(d, m, 3 * t);
        glm::vec3 b = position(d, m, 3 * t + 1);
        glm::vec3 c = position(d, m, 3 * t + 2);
        glm::vec3 n = glm::cross(b - a, c - a);
        EXPECT_GT(glm::dot(n, (a + b + c) / 3.0f - centre), 1e-6f) << name << " triangle " << t;
    }
}

// Every edge (by position) is used once in each direction: no holes, no flipped faces.
void expectWatertight(const OrganMeshData& d, const MeshRange& m, const char* name) {
    auto key = [](glm::vec3 p) {
        return std::make_tuple(std::lround(p.x * 1e4f), std::lround(p.y * 1e4f), std::lround(p.z * 1e4f));
    };
    using Key = decltype(key(glm::vec3()));
    std::map<std::pair<Key, Key>, int> edges;
    for (std::uint32_t t = 0; t < m.triangleCount(); ++t) {
        for (int e = 0; e < 3; ++e) {
            edges[{key(position(d, m, 3 * t + e)), key(position(d, m, 3 * t + (e + 1) % 3))}] += 1;
        }
    }
    for (const auto& [edge, count] : edges) {
        EXPECT_EQ(count, 1) << name << ": an edge used twice in one direction";
        auto twin = edges.find({edge.second, edge.first});
        EXPECT_TRUE(twin != edges.end() && twin->second == 1) << name << ": an edge without its opposite";
    }
}

TEST(OrganMeshesTest, ClosedMeshesAreWatertightAndWoundOutwards) {
    OrganMeshData d = draw::buildOrganMeshes();
    using namespace shared;
    for (bool hull : {false, true}) {
        const auto& meshes = hull ? d.hulls : d.organs;
        expectWoundOutwards(d, meshes[kOrganStem], {0.5f, 0, 0}, hull ? "stem hull" : "stem");
        expectWoundOutwards(d, meshes[kOrganSphere], {0, 0, 0}, hull ? "sphere hull" : "sphere");
        expectWatertight(d, meshes[kOrganStem], hull ? "stem hull" : "stem");
        expectWatertight(d, meshes[kOrganSphere], hull ? "sphere hull" : "sphere");
    }
    EXPECT_TRUE(d.closedHull[kOrganStem]);
    EXPECT_TRUE(d.closedHull[kOrganSphere]);
    EXPECT_FALSE(d.closedHull[kOrganLeaf]);
}

TEST(OrganMeshesTest, StemRingsAndCapsAreFlagged) {
    OrganMeshData d = draw::buildOrganMeshes();
    const MeshRange& stem = d.organs[shared::kOrganStem];
    int caps = 0;
    for (std::uint32_t i = 0; i < stem.indexCount; ++i) {
        const shared::MeshVertex& v =
            d.vertices[static_cast<std::size_t>(stem.vertexOffset) + d.indices[stem.firstIndex + i]];
        EXPECT_TRUE(v.position.w == 0.0f || v.position.w == 1.0f);
        EXPECT_EQ(v.position.x, v.position.w) << "the ring flag matches the end the vertex sits on";
        if (v.normal.w == 1.0f) {
            ++caps;
            EXPECT_EQ(std::abs(v.normal.x), 1.0f);
        }
    }
    EXPECT_EQ(caps, static_cast<int>(2 * 3 * draw::kStemSides));
}

TEST(OrganMeshesTest, AFarStemIsABandAcrossTheUnitStemWoundToFaceMinusZAndEveryOtherKindItsHull) {
    OrganMeshData d = draw::buildOrganMeshes();
    const MeshRange& band = d.far[shared::kOrganStem];
    ASSERT_EQ(band.triangleCount(), 4u);
    std::set<std::uint32_t> corners;
    for (std::uint32_t i = 0; i < band.indexCount; ++i) {
        corners.insert(d.indices[band.firstIndex + i]);
        const shared::MeshVertex& v =
            d.vertices[static_cast<std::size_t>(band.vertexOffset) + d.indices[band.firstIndex + i]];
        EXPECT_EQ(v.normal.w, shared::kStemBandVertex);
        EXPECT_EQ(v.position.x, v.position.w) << "the ring flag matches the end the vertex sits on";
        EXPECT_EQ(v.position.z, 0.0f);
        EXPECT_LE(std::abs(v.position.y), 1.0f);
    }
    EXPECT_EQ(corners.size(), 6u);
    for (std::uint32_t t = 0; t < band.triangleCount(); ++t) {
        const glm::vec3 a = position(d, band, 3 * t), b = position(d, band, 3 * t + 1);
        const glm::vec3 c = position(d, band, 3 * t + 2);
        EXPECT_LT(glm::cross(b - a, c - a).z, 0.0f) << "triangle " << t;
    }
    for (std::uint32_t kind : {shared::kOrganSphere, shared::kOrganDisc, shared::kOrganLeaf, shared::kOrganTriangle})
        EXPECT_EQ(d.far[kind].firstIndex, d.hulls[kind].firstIndex) << "kind " << kind;
}

TEST(OrganMeshesTest, HullCornersAreCornersOfTheDrawnMesh) {
    OrganMeshData d = draw::buildOrganMeshes();
    for (std::uint32_t kind : {shared::kOrganStem, shared::kOrganSphere}) {
        std::set<std::tuple<long, long, long>> drawn;
        const MeshRange& organ = d.organs[kind];
        for (std::uint32_t i = 0; i < organ.indexCount; ++i) {
            glm::vec3 p = position(d, organ, i);
            drawn.insert({std::lround(p.x * 1e4f), std::lround(p.y * 1e4f), std::lround(p.z * 1e4f)});
        }
        const MeshRange& hull = d.hulls[kind];
        ASSERT_LT(hull.triangleCount(), organ.triangleCount());
        for (std::uint32_t i = 0; i < hull.indexCount; ++i) {
            glm::vec3 p = position(d, hull, i);
            EXPECT_TRUE(drawn.count({std::lround(p.x * 1e4f), std::lround(p.y * 1e4f), std::lround(p.z * 1e4f)}))
                << "kind " << kind << " hull vertex " << i;
        }
    }
}

TEST(OrganMeshesTest, LeafBladesLieInTheHeadingLeftPlaneFacingUp) {
    OrganMeshData d = draw::buildOrganMeshes();
    const MeshRange& leaf = d.organs[shared::kOrganLeaf];
    std::map<int, std::uint32_t> trianglesPerShape;
    for (std::uint32_t t = 0; t < leaf.triangleCount(); ++t) {
        glm::vec3 p[3];
        int shape = -1;
        const shared::MeshVertex& first =
            d.vertices[static_cast<std::size_t>(leaf.vertexOffset) + d.indices[leaf.firstIndex + 3 * t]];
        if (first.normal.w > static_cast<float>(shared::kLeafLastShape)) continue; // a blossom: not flat
        for (int k = 0; k < 3; ++k) {
            const shared::MeshVertex& v =
                d.vertices[static_cast<std::size_t>(leaf.vertexOffset) + d.indices[leaf.firstIndex + 3 * t + k]];
            p[k] = {v.position.x, v.position.y, v.position.z};
            EXPECT_EQ(v.position.z, 0.0f) << "out of the heading-left plane";
            EXPECT_EQ(v.normal.z, 1.0f);
            EXPECT_GE(v.position.x, -0.4f);
            EXPECT_LE(v.position.x, 1.0f);
            EXPECT_LE(std::abs(v.position.y), 0.5f + 1e-6f);
            if (k > 0) {
                EXPECT_EQ(static_cast<int>(v.normal.w), shape) << "a triangle mixes leaf shapes";
            }
            shape = static_cast<int>(v.normal.w);
        }
        EXPECT_GT(glm::cross(p[1] - p[0], p[2] - p[0]).z, 0.0f) << "triangle " << t << " faces down";
        ++trianglesPerShape[shape];
    }
    ASSERT_EQ(trianglesPerShape.size(), shared::kLeafLastShape + 1);
    for (std::uint32_t shape = 0; shape <= shared::kLeafLastShape; ++shape) {
        EXPECT_GT(trianglesPerShape[static_cast<int>(shape)], 8u) << "shape " << shape;
        EXPECT_EQ(trianglesPerShape[static_cast<int>(shape)], d.leafShapeTriangles[shape][1]) << "shape " << shape;
    }
}

// Each leaf shape casts its shadow from a coarser cut of itself in the leaf hull, and from a coarser one still when
// it is a few pixels across (its far cut): fewer triangles each, tagged with its shape, within the drawn shape's
// extent and covering most of its area (a flat blade's, in its plane).
TEST(OrganMeshesTest, LeafHullsAndFarCutsAreCoarserCutsOfTheDrawnShapes) {
    OrganMeshData d = draw::buildOrganMeshes();
    ASSERT_EQ(d.leafHullTriangles.size(), d.leafShapeTriangles.size());
    ASSERT_EQ(d.leafFarHullTriangles.size(), d.leafShapeTriangles.size());
    struct Extent {
        glm::vec3 min{1e9f}, max{-1e9f};
        float area = 0.0f; // in the heading-left plane
        std::uint32_t turned = 0; // triangles wound clockwise in it: a flat blade's cut must have none
    };
    auto extentOf = [&](const MeshRange& range, std::array<std::uint32_t, 2> triangles, std::uint32_t shape) {
        Extent e;
        for (std::uint32_t t = triangles[0]; t < triangles[0] + triangles[1]; ++t) {
            glm::vec3 p[3];
            for (int k = 0; k < 3; ++k) {
                const shared::MeshVertex& v =
                    d.vertices[static_cast<std::size_t>(range.vertexOffset) + d.indices[range.firstIndex + 3 * t + k]];
                EXPECT_EQ(std::lround(v.normal.w), shape);
                p[k] = {v.position.x, v.position.y, v.position.z};
                e.min = glm::min(e.min, p[k]);
                e.max = glm::max(e.max, p[k]);
            }
            const float area = 0.5f * glm::cross(p[1] - p[0], p[2] - p[0]).z;
            e.area += area;
            if (area < 0.0f) ++e.turned;
        }
        return e;
    };
    for (std::uint32_t shape = 0; shape <= shared::kSurfaceLastShape; ++shape) {
        const Extent drawn = extentOf(d.organs[shared::kOrganLeaf], d.leafShapeTriangles[shape], shape);
        const Extent hull = extentOf(d.hulls[shared::kOrganLeaf], d.leafHullTriangles[shape], shape);
        EXPECT_GT(d.leafHullTriangles[shape][1], 0u) << "shape " << shape;
        EXPECT_LT(d.leafHullTriangles[shape][1], d.leafShapeTriangles[shape][1]) << "shape " << shape;
        EXPECT_LE(d.leafHullTriangles[shape][1], d.castingTriangles[shared::kOrganLeaf]);
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(hull.min[axis], drawn.min[axis] - 1e-5f) << "shape " << shape;
            EXPECT_LE(hull.max[axis], drawn.max[axis] + 1e-5f) << "shape " << shape;
        }
        if (shape <= shared::kLeafLastShape) {
            EXPECT_GT(hull.area, 0.75f * drawn.area) << "shape " << shape;
        }

        const Extent far = extentOf(d.hulls[shared::kOrganLeaf], d.leafFarHullTriangles[shape], shape);
        EXPECT_GT(d.leafFarHullTriangles[shape][1], 0u) << "shape " << shape;
        EXPECT_LT(d.leafFarHullTriangles[shape][1], d.leafHullTriangles[shape][1]) << "shape " << shape;
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(far.min[axis], drawn.min[axis] - 1e-5f) << "shape " << shape;
            EXPECT_LE(far.max[axis], drawn.max[axis] + 1e-5f) << "shape " << shape;
        }
        if (shape <= shared::kLeafLastShape) {
            EXPECT_GT(far.area, 0.5f * drawn.area) << "shape " << shape;
            // Its volumes' sides inside the sheet cancel only between triangles wound alike.
            EXPECT_EQ(hull.turned, 0u) << "shape " << shape;
            EXPECT_EQ(far.turned, 0u) << "shape " << shape;
        }
    }
}

// A leaf or blossom a few pixels across casts its shadow from a silhouette quadrilateral (its far cut's many
// triangles cast as many volumes, each with its long sides): two triangles of its shape sharing a flagged edge, a
// flat leaf's in its plane with the drawn leaf's area, a blossom's across its heading within its depth.
TEST(OrganMeshesTest, LeavesAndBlossomsAFewPixelsAcrossCastFromASilhouetteQuadrilateral) {
    OrganMeshData d = draw::buildOrganMeshes();
    ASSERT_EQ(d.leafFarShadowTriangles.size(), d.leafShapeTriangles.size());
    const MeshRange& hull = d.hulls[shared::kOrganLeaf];
    for (std::uint32_t shape = 0; shape <= shared::kSurfaceLastShape; ++shape) {
        const std::array<std::uint32_t, 2> far = d.leafFarHullTriangles[shape], cast = d.leafFarShadowTriangles[shape];
        if (far[1] <= 2) {
            EXPECT_EQ(cast, far) << "shape " << shape;
            continue;
        }
        ASSERT_EQ(cast[1], 2u) << "shape " << shape;
        ASSERT_LE(3 * (cast[0] + 2), hull.indexCount);
        glm::vec3 low(1e9f), high(-1e9f);
        float drawnArea = 0.0f;
        const MeshRange& drawn = d.organs[shared::kOrganLeaf];
        for (std::uint32_t t = d.leafShapeTriangles[shape][0];
             t < d.leafShapeTriangles[shape][0] + d.leafShapeTriangles[shape][1]; ++t) {
            const glm::vec3 a = position(d, drawn, 3 * t), b = position(d, drawn, 3 * t + 1),
                            c = position(d, drawn, 3 * t + 2);
            drawnArea += 0.5f * glm::cross(b - a, c - a).z;
            low = glm::min(low, glm::min(a, glm::min(b, c)));
            high = glm::max(high, glm::max(a, glm::max(b, c)));
        }
        std::array<glm::vec3, 6> corner;
        glm::vec3 middle(0.0f);
        for (std::uint32_t k = 0; k < 6; ++k) {
            corner[k] = position(d, hull, 3 * cast[0] + k);
            middle += corner[k] / 6.0f;
            const std::uint32_t index = d.indices[hull.firstIndex + 3 * cast[0] + k];
            EXPECT_EQ(std::lround(d.vertices[static_cast<std::size_t>(hull.vertexOffset) + index].normal.w), shape);
        }
        for (int axis = 0; axis < 3; ++axis) {
            EXPECT_GE(middle[axis], low[axis]) << "shape " << shape;
            EXPECT_LE(middle[axis], high[axis]) << "shape " << shape;
        }
        // The two triangles share their first corner and the second's first edge is the first's last, flagged in
        // both, so that their volumes' sides there cancel.
        const std::uint32_t first = hull.firstIndex / 3 + cast[0];
        EXPECT_EQ(d.indices[3 * first], d.indices[3 * first + 3]);
        EXPECT_EQ(d.indices[3 * first + 2], d.indices[3 * first + 4]);
        EXPECT_EQ(d.interiorEdges[first], 4u) << "shape " << shape;
        EXPECT_EQ(d.interiorEdges[first + 1], 1u) << "shape " << shape;
        const glm::vec3 n0 = glm::cross(corner[1] - corner[0], corner[2] - corner[0]);
        const glm::vec3 n1 = glm::cross(corner[4] - corner[3], corner[5] - corner[3]);
        if (shape <= shared::kLeafLastShape) {
            for (const glm::vec3& p : corner)
                EXPECT_EQ(p.z, 0.0f) << "shape " << shape;
            EXPECT_GT(n0.z, 0.0f) << "shape " << shape;
            EXPECT_GT(n1.z, 0.0f) << "shape " << shape;
            // The drawn triangles' sum counts where leaflets overlap twice; the quadrilateral has their union's area.
            EXPECT_LE(0.5f * (n0.z + n1.z), 1.01f * drawnArea) << "shape " << shape;
            EXPECT_GE(0.5f * (n0.z + n1.z), 0.85f * drawnArea) << "shape " << shape;
        } else {
            for (const glm::vec3& p : corner)
                EXPECT_EQ(p.x, corner[0].x) << "shape " << shape;
            EXPECT_GT(n0.x, 0.0f) << "shape " << shape;
            EXPECT_GT(n1.x, 0.0f) << "shape " << shape;
            const float face = 0.5f * (n0.x + n1.x);
            EXPECT_GT(face, 0.2f * (high.y - low.y) * (high.z - low.z)) << "shape " << shape;
            EXPECT_LT(face, (high.y - low.y) * (high.z - low.z)) << "shape " << shape;
        }
    }
}

// A model leaf that is not flat (a cpfg surface curves out of its plane) casts from a quadrilateral across its
// thinnest axis, out of its face, with the area it covers seen along it: not from its profile.
TEST(OrganMeshesTest, ACurvedModelLeafCastsFromAQuadrilateralAcrossItsFace) {
    // Unit length, 0.4 wide, bowed 0.1 out of its face along its midrib, in 8 x 2 cells.
    ir::LeafModel curved;
    auto at = [](int i, int j) {
        const float x = float(i) / 8.0f;
        return std::array<float, 3>{x, -0.2f + 0.2f * float(j), 0.1f * std::sin(3.14159265f * x)};
    };
    for (int i = 0; i < 8; ++i)
        for (int j = 0; j < 2; ++j) {
            for (const auto& corner :
                 {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)})
                curved.corners.push_back(corner);
            curved.normals.push_back({0, 0, 1});
            curved.normals.push_back({0, 0, 1});
        }
    OrganMeshData d = draw::buildOrganMeshes({curved});
    const std::uint32_t shape = shared::kSurfaceLastShape + 1;
    ASSERT_EQ(d.leafFarShadowTriangles.size(), shape + 1);
    ASSERT_EQ(d.leafFarShadowTriangles[shape][1], 2u);
    const MeshRange& hull = d.hulls[shared::kOrganLeaf];
    std::array<glm::vec3, 6> corner;
    for (std::uint32_t k = 0; k < 6; ++k) corner[k] = position(d, hull, 3 * d.leafFarShadowTriangles[shape][0] + k);
    for (const glm::vec3& p : corner) {
        EXPECT_NEAR(p.z, 0.05f, 1e-4f); // half way out of the face
        EXPECT_GE(p.x, -0.1f);
        EXPECT_LE(p.x, 1.1f);
    }
    const float area = 0.5f * (glm::cross(corner[1] - corner[0], corner[2] - corner[0]).z +
                               glm::cross(corner[4] - corner[3], corner[5] - corner[3]).z);
    EXPECT_NEAR(area, 0.4f, 0.02f);
}

// Blossoms: each of its own shape within a unit diameter about the heading, turned to face along it; the star's
// and the head's centres are tinted to the eye's yellow, the rose's petals keep the organ's colour.
TEST(OrganMeshesTest, BlossomsFaceAlongTheHeadingWithinAUnitDiameter) {
    OrganMeshData d = draw::buildOrganMeshes();
    const MeshRange& leaf = d.organs[shared::kOrganLeaf];
    struct Blossom {
        std::uint32_t triangles = 0, tinted = 0;
        float facing = 0.0f; // the sum of the triangles' areas along +x
    };
    std::map<std::uint32_t, Blossom> blossoms;
    for (std::uint32_t t = 0; t < leaf.triangleCount(); ++t) {
        const shared::MeshVertex* v[3];
        for (int k = 0; k < 3; ++k)
            v[k] = &d.vertices[static_cast<std::size_t>(leaf.vertexOffset) + d.indices[leaf.firstIndex + 3 * t + k]];
        const auto shape = static_cast<std::uint32_t>(std::lround(v[0]->normal.w));
        if (shape <= shared::kLeafLastShape) continue;
        glm::vec3 p[3];
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(std::lround(v[k]->normal.w), shape) << "a triangle mixes shapes";
            ASSERT_EQ(v[k]->position.w, v[0]->position.w) << "a triangle's tint varies";
            p[k] = {v[k]->position.x, v[k]->position.y, v[k]->position.z};
            EXPECT_LE(std::hypot(p[k].y, p[k].z), 0.5f + 1e-5f) << "shape " << shape;
            EXPECT_GE(p[k].x, 0.0f);
            EXPECT_LE(p[k].x, 0.6f);
        }
        const glm::vec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        // The face's stored normal is its winding's.
        EXPECT_GT(glm::dot(n, glm::vec3(v[0]->normal.x, v[0]->normal.y, v[0]->normal.z)), 0.0f);
        Blossom& b = blossoms[shape];
        ++b.triangles;
        b.tinted += v[0]->position.w == 1.0f ? 1 : 0;
        EXPECT_TRUE(v[0]->position.w == 0.0f || v[0]->position.w == 1.0f);
        b.facing += 0.5f * n.x;
    }
    ASSERT_EQ(blossoms.size(), std::size_t(shared::kSurfaceLastShape - shared::kLeafLastShape));
    for (const auto& [shape, b] : blossoms) {
        EXPECT_GT(b.triangles, 30u) << shape;
        EXPECT_EQ(b.triangles, d.leafShapeTriangles[shape][1]) << shape;
        EXPECT_GT(b.facing, 0.1f) << shape;
    }
    EXPECT_GT(blossoms[shared::kBlossomStar].tinted, 0u);
    EXPECT_LT(blossoms[shared::kBlossomStar].tinted, blossoms[shared::kBlossomStar].triangles);
    EXPECT_GT(blossoms[shared::kBlossomHead].tinted, 0u);
    EXPECT_LT(blossoms[shared::kBlossomHead].tinted, blossoms[shared::kBlossomHead].triangles);
    EXPECT_EQ(blossoms[shared::kBlossomRose].tinted, 0u);
}

TEST(OrganMeshesTest, TriangleAndGround) {
    OrganMeshData d = draw::buildOrganMeshes();
    EXPECT_EQ(d.organs[shared::kOrganTriangle].indexCount, 3u);
    EXPECT_EQ(d.ground.indexCount, 6u);
    for (std::uint32_t t = 0; t < 2; ++t) {
        glm::vec3 a = position(d, d.ground, 3 * t);
        glm::vec3 b = position(d, d.ground, 3 * t + 1);
        glm::vec3 c = position(d, d.ground, 3 * t + 2);
        EXPECT_GT(glm::cross(b - a, c - a).y, 0.0f) << "the ground faces up";
    }
}

} // namespace
} // namespace simeco::test
