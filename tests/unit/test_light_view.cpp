// The light grid as users see it (field/light_view.h): its layers as images, and its shade as spheres among the
// plants.
#include <cmath>
#include <set>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "compute/shared/light_layout.h"
#include "compute/shared/organ_layout.h"
#include "field/light_view.h"

namespace simeco {
namespace {

// A 3 x 4 x 5 grid of voxels of side 2 from (-3, 0, -5), each voxel's light its own index, the open's 100.
field::LightVolume numberedVolume() {
    field::LightVolume volume;
    volume.spec.origin = {-3.0f, 0.0f, -5.0f};
    volume.spec.side = 2.0f;
    volume.spec.size = {3, 4, 5};
    volume.open = 100.0f;
    for (uint64_t v = 0; v < volume.spec.voxels(); ++v) volume.light.push_back({0, 1, 0, float(v)});
    return volume;
}

float lightOfVoxel(uint32_t x, uint32_t y, uint32_t z) { return float((z * 4 + y) * 3 + x); }

TEST(LightView, ASliceIsTheLayerAtItsHeightSeenFromAbove) {
    const field::LightVolume volume = numberedVolume();
    // Height 5 lies in layer 2 (from 4 to 6).
    const field::LightSlice slice = field::lightSlice(volume, 5.0f);
    ASSERT_EQ(slice.width, 3u);
    ASSERT_EQ(slice.rows, 5u);
    EXPECT_FLOAT_EQ(slice.at, 5.0f);
    EXPECT_FLOAT_EQ(slice.open, 100.0f);
    for (uint32_t z = 0; z < 5; ++z)
        for (uint32_t x = 0; x < 3; ++x) EXPECT_FLOAT_EQ(slice.light[z * 3 + x], lightOfVoxel(x, 2, z));
    // Heights outside the grid show its nearest layer.
    EXPECT_FLOAT_EQ(field::lightSlice(volume, -10.0f).light[0], lightOfVoxel(0, 0, 0));
    EXPECT_FLOAT_EQ(field::lightSlice(volume, 100.0f).light[0], lightOfVoxel(0, 3, 0));
}

TEST(LightView, ASectionIsTheLayerAtItsDepthSeenFromTheFrontTopFirst) {
    const field::LightVolume volume = numberedVolume();
    // Depth 0 lies in layer 2 (z from -1 to 1).
    const field::LightSlice section = field::lightSection(volume, 0.0f);
    ASSERT_EQ(section.width, 3u);
    ASSERT_EQ(section.rows, 4u);
    EXPECT_FLOAT_EQ(section.at, 0.0f);
    for (uint32_t r = 0; r < 4; ++r)
        for (uint32_t x = 0; x < 3; ++x) EXPECT_FLOAT_EQ(section.light[r * 3 + x], lightOfVoxel(x, 3 - r, 2));
}

TEST(LightView, ALayersImageIsDarkWhereNoLightComesAndBrightInTheOpen) {
    field::LightSlice slice;
    slice.width = 2;
    slice.rows = 1;
    slice.open = 4.0f;
    slice.light = {0.0f, 4.0f};
    const draw::Frame image = field::lightSliceImage(slice);
    ASSERT_GT(image.width, 2u);
    ASSERT_EQ(image.width, 2 * image.height);
    auto brightness = [&](uint32_t x) {
        const float* p = &image.rgba[image.index(x, 0) * 4];
        return p[0] + p[1] + p[2];
    };
    EXPECT_LT(brightness(0), 0.2f);
    EXPECT_GT(brightness(image.width - 1), 2.0f);
}

TEST(LightView, OccupancyShowsEachPlantsVoxelsInItsOwnColourAndSharedOnesDark) {
    field::LightVolume volume = numberedVolume();
    // Layer 2 (heights 4 to 6): plant 0 holds column x = 0, plant 1 x = 1, several plants x = 2; the rest empty.
    volume.holders.assign(volume.spec.voxels(), shared::kVoxelEmpty);
    for (uint32_t z = 0; z < 5; ++z)
        for (uint32_t x = 0; x < 3; ++x)
            volume.holders[(z * 4 + 2) * 3 + x] = x == 2 ? shared::kVoxelShared : x + 1;
    const field::OccupancySlice slice = field::occupancySlice(volume, 5.0f);
    ASSERT_EQ(slice.width, 3u);
    ASSERT_EQ(slice.rows, 5u);
    EXPECT_EQ(slice.holders[0], 1u);
    EXPECT_EQ(slice.holders[4 * 3 + 2], shared::kVoxelShared);
    const draw::Frame image = field::occupancySliceImage(slice);
    const uint32_t scale = image.width / 3;
    auto colour = [&](uint32_t x) {
        const float* p = &image.rgba[image.index(x * scale, 0) * 4];
        return glm::vec3(p[0], p[1], p[2]);
    };
    EXPECT_GT(glm::distance(colour(0), colour(1)), 0.2f); // two plants, two colours
    EXPECT_LT(colour(2).r + colour(2).g + colour(2).b, 0.5f); // shared: dark
    // An empty layer is pale.
    const draw::Frame empty = field::occupancySliceImage(field::occupancySlice(volume, 1.0f));
    EXPECT_GT(empty.rgba[0] + empty.rgba[1] + empty.rgba[2], 2.0f);
}

TEST(LightView, ShadeIsDrawnWhereTheLightIsLowTheDeeperTheLarger) {
    field::LightVolume volume = numberedVolume();
    // Light from none in voxel 0 to the open's from voxel 20 on.
    for (uint64_t v = 0; v < volume.light.size(); ++v)
        volume.light[v].w = std::min(100.0f, 5.0f * float(v));
    const turtle::Interpretation shade = field::shadeOrgans(volume, 7);
    const uint32_t spheres = shade.count[shared::kOrganSphere];
    ASSERT_EQ(spheres, shade.organs.size());
    // Voxels 0 to 17 lie below kShadeShown (90) of the open's light.
    ASSERT_EQ(spheres, 18u);
    float lastRadius = 1e30f;
    std::set<uint32_t> voxels;
    for (const shared::OrganInstance& o : shade.organs) {
        EXPECT_EQ(o.kind, shared::kOrganSphere);
        EXPECT_EQ(o.plant, 7u);
        voxels.insert(o.module);
        const glm::vec3 centre = volume.spec.centre(o.module);
        EXPECT_FLOAT_EQ(o.position.x, centre.x);
        EXPECT_FLOAT_EQ(o.position.y, centre.y);
        EXPECT_FLOAT_EQ(o.position.z, centre.z);
        const float radius = o.heading.w;
        EXPECT_GT(radius, 0.0f);
        EXPECT_LT(radius, lastRadius) << "voxel " << o.module << " is lighter than the one before";
        EXPECT_LE(radius, 0.5f * volume.spec.side);
        lastRadius = radius;
    }
    EXPECT_EQ(voxels.size(), 18u);
    EXPECT_EQ(*voxels.rbegin(), 17u);
    // Deeper shade, deeper blue: the darkest voxel's sphere is darker than the lightest one's.
    const auto& deepest = shade.organs.front().color;
    const auto& mildest = shade.organs.back().color;
    EXPECT_LT(deepest.x + deepest.y + deepest.z, mildest.x + mildest.y + mildest.z);
    EXPECT_GT(deepest.z, deepest.x);
}

TEST(LightView, AGridInTheOpenDrawsNoShade) {
    field::LightVolume volume = numberedVolume();
    for (glm::vec4& l : volume.light) l.w = volume.open;
    EXPECT_TRUE(field::shadeOrgans(volume, 0).organs.empty());
    EXPECT_TRUE(field::shadeOrgans(field::LightVolume{}, 0).organs.empty());
}

} // namespace
} // namespace simeco
