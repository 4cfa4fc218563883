// The light grid's CPU reference (grow/light_grid.h): its size, where light comes from, and how leaves and
// obstacles shade what lies beyond them; growth's responses to light and to the scene's climate and soil.
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "compute/shared/growth_layout.h"
#include "compute/shared/organ_layout.h"
#include "field/obstacles.h"
#include "field/plant_statistics.h"
#include "grow/environment.h"
#include "grow/light_grid.h"

namespace simeco {
namespace {

// A flat leaf blade of `length` and `width` centred at `centre`, along x, drawn by module `module`.
shared::OrganInstance leafAt(glm::vec3 centre, float length, float width, uint32_t module) {
    shared::OrganInstance o{};
    o.kind = shared::kOrganLeaf;
    o.shape = shared::kLeafOvate;
    o.module = module;
    o.position = {centre.x - 0.5f * length, centre.y, centre.z, length};
    o.heading = {1, 0, 0, width};
    o.up = {0, 1, 0, 0};
    return o;
}

turtle::Interpretation leaves(const std::vector<shared::OrganInstance>& organs) {
    turtle::Interpretation r;
    r.organs = organs;
    r.count[shared::kOrganLeaf] = uint32_t(organs.size());
    for (uint32_t k = shared::kOrganLeaf + 1; k < shared::kOrganKinds; ++k) r.first[k] = uint32_t(organs.size());
    return r;
}

// A 10 x 10 x 10 grid of unit voxels from the origin.
grow::LightGridSpec tenCubed() {
    grow::LightGridSpec spec;
    spec.size = {10, 10, 10};
    return spec;
}

TEST(LightGrid, TheGridCoversTheFieldWithinItsVoxelsPerPlant) {
    for (uint32_t plants : {1u, 10u, 1000u, 1000000u}) {
        const grow::LightGridSpec spec = grow::lightGridOver({-50, 0, -20}, {50, 30, 20}, plants);
        EXPECT_LE(spec.voxels(), std::clamp<uint64_t>(grow::kVoxelsPerPlant * plants, grow::kLeastVoxels,
                                                      grow::kMostVoxels));
        EXPECT_GT(spec.voxels(), grow::kLeastVoxels / 2);
        EXPECT_LE(spec.origin.x, -50.0f);
        EXPECT_GE(spec.origin.x + float(spec.size[0]) * spec.side, 50.0f);
        EXPECT_GE(spec.origin.y + float(spec.size[1]) * spec.side, 30.0f);
        EXPECT_GE(spec.origin.z + float(spec.size[2]) * spec.side, 20.0f);
        EXPECT_FLOAT_EQ(spec.origin.y, 0.0f);
    }
}

TEST(LightGrid, TheSkySharesItsLightAndTheSunSetsBelowTheHorizon) {
    const std::vector<shared::LightDirection> day = grow::lightDirections({0.3f, 1.0f, 0.2f}, 2.0f, 0.5f);
    ASSERT_EQ(day.size(), 1 + grow::kSkyDirections);
    EXPECT_FLOAT_EQ(day[0].towardAndIntensity.w, 2.0f);
    float sky = 0.0f;
    for (size_t d = 1; d < day.size(); ++d) {
        const glm::vec3 toward(day[d].towardAndIntensity.x, day[d].towardAndIntensity.y, day[d].towardAndIntensity.z);
        EXPECT_NEAR(glm::length(toward), 1.0f, 1e-5f);
        EXPECT_GT(toward.y, 0.4f);
        sky += day[d].towardAndIntensity.w;
    }
    EXPECT_NEAR(sky, 0.5f, 1e-5f);
    EXPECT_EQ(grow::lightDirections({0.3f, -0.1f, 0.2f}, 2.0f, 0.5f)[0].towardAndIntensity.w, 0.0f);
}

TEST(LightGrid, LeavesShadeWhatLiesBelowThemTheMoreTheDenser) {
    const std::vector<shared::LightDirection> overhead = grow::lightDirections({0, 1, 0}, 1.0f, 0.0f);
    auto lightBelow = [&](int leavesAbove) {
        grow::LightGridCpu grid(tenCubed(), overhead, {});
        std::vector<shared::OrganInstance> organs;
        for (int k = 0; k < leavesAbove; ++k) organs.push_back(leafAt({5.5f, 7.5f, 5.5f}, 1.0f, 1.0f, uint32_t(k)));
        grid.splat(leaves(organs), field::leafShapeAreas());
        grid.propagate();
        return grid.light()[size_t(tenCubed().voxelAt({5.5f, 2.5f, 5.5f}))].w;
    };
    EXPECT_FLOAT_EQ(lightBelow(0), 1.0f);
    const float one = lightBelow(1), four = lightBelow(4);
    EXPECT_LT(one, 1.0f);
    EXPECT_LT(four, one);
    EXPECT_GT(four, 0.0f);
    // Beer–Lambert: four leaves let through the fourth power of what one does.
    EXPECT_NEAR(four, std::pow(one, 4.0f), 1e-4f);
}

TEST(LightGrid, AnObstacleStopsTheLightFromItsSide) {
    // A wall of voxels at x = 6 from the ground to the top; the sun low in the +x sky.
    const grow::LightGridSpec spec = tenCubed();
    std::vector<uint32_t> wall(spec.voxels(), 0);
    for (uint32_t y = 0; y < 10; ++y)
        for (uint32_t z = 0; z < 10; ++z) wall[size_t(spec.voxelAt({6.5f, float(y) + 0.5f, float(z) + 0.5f}))] = 1;
    grow::LightGridCpu grid(spec, grow::lightDirections({1.0f, 0.3f, 0.0f}, 1.0f, 0.5f), wall);
    grid.propagate();
    const glm::vec4 shaded = grid.light()[size_t(spec.voxelAt({4.5f, 1.5f, 5.5f}))];
    const glm::vec4 sunlit = grid.light()[size_t(spec.voxelAt({8.5f, 1.5f, 5.5f}))];
    EXPECT_LT(shaded.w, 0.5f); // no sun, and only part of the sky
    EXPECT_GT(sunlit.w, 1.0f);
    // In the wall's shade most light comes from the open side (-x); beside the sun, from the sun's.
    EXPECT_LT(shaded.x, 0.0f);
    EXPECT_GT(sunlit.x, 0.5f);
    EXPECT_EQ(grid.light()[size_t(spec.voxelAt({6.5f, 1.5f, 5.5f}))].w, 0.0f);
}

TEST(LightGrid, AWallThinnerThanAVoxelFillsALayerOfThem) {
    // A wall 0.2 thick across the 1-unit voxels, between their centres at x = 5.5 and 6.5, 4 high, turned a little.
    const grow::LightGridSpec spec = tenCubed();
    ir::EcoObstacle wall;
    wall.center[0] = 6.1f, wall.center[1] = 2.0f, wall.center[2] = 5.0f;
    wall.halfSize[0] = 4.0f, wall.halfSize[1] = 2.0f, wall.halfSize[2] = 0.1f;
    wall.yaw = 1.5707963f + 0.05f; // its length along z
    const std::vector<uint32_t> mask = field::obstacleVoxels(spec, {wall});
    // Every row of voxels across it, below its top and within its length, meets one blocked voxel, the one whose
    // centre lies nearest its middle plane; none above it.
    for (uint32_t y = 0; y < 10; ++y)
        for (uint32_t z = 2; z < 8; ++z) {
            int blocked = 0;
            for (uint32_t x = 0; x < 10; ++x)
                blocked += int(mask[size_t(spec.voxelAt({float(x) + 0.5f, float(y) + 0.5f, float(z) + 0.5f}))]);
            EXPECT_EQ(blocked, y < 4 ? 1 : 0) << y << " " << z;
        }
    EXPECT_EQ(mask[size_t(spec.voxelAt({6.5f, 1.5f, 5.5f}))], 1u);
}

TEST(LightGrid, OrgansTakeTheLightOfTheirVoxelIntoTheirParticles) {
    const grow::LightGridSpec spec = tenCubed();
    grow::LightGridCpu grid(spec, grow::lightDirections({0.5f, 1.0f, 0.0f}, 1.0f, 0.4f), {});
    const turtle::Interpretation organs =
        leaves({leafAt({5.5f, 8.5f, 5.5f}, 1.0f, 1.0f, 0), leafAt({5.5f, 2.5f, 5.5f}, 1.0f, 1.0f, 2),
                leafAt({50.0f, 2.5f, 5.5f}, 1.0f, 1.0f, 1)});
    grid.splat(organs, field::leafShapeAreas());
    grid.propagate();
    std::vector<shared::ParticleState> particles(3);
    grid.gather(organs, particles);
    const float open = 1.4f;
    EXPECT_EQ(particles[1].value[shared::kParticleLight], open); // outside the grid: in the open
    EXPECT_LT(particles[2].value[shared::kParticleLight], particles[0].value[shared::kParticleLight]);
    EXPECT_LE(particles[0].value[shared::kParticleLight], open);
    const glm::vec3 most = grow::unpackLightDirection(particles[0].value[shared::kParticleLightDirection]);
    EXPECT_GT(most.x, 0.1f); // toward the sun's side
    EXPECT_GT(most.y, 0.5f);
    for (const glm::vec3 d : {glm::vec3(0, 1, 0), glm::normalize(glm::vec3(0.3f, -0.8f, 0.5f)), glm::vec3(-1, 0, 0)})
        EXPECT_GT(glm::dot(grow::unpackLightDirection(grow::packLightDirection(d)), d), 0.9999f);
}

TEST(LightGrid, GrowthFollowsLightSaturatingInTheOpen) {
    const float open = 1.3f;
    EXPECT_FLOAT_EQ(shared::lightResponse(open, open), 1.0f);
    EXPECT_FLOAT_EQ(shared::lightResponse(0.0f, open), 0.0f);
    EXPECT_FLOAT_EQ(shared::lightResponse(-1.0f, open), 0.0f);
    EXPECT_NEAR(shared::lightResponse(0.1f * open, open), 0.357f, 1e-3f);
    float previous = 0.0f;
    for (float light = 0.05f; light <= open; light += 0.05f) {
        EXPECT_GT(shared::lightResponse(light, open), previous);
        previous = shared::lightResponse(light, open);
    }
    // Without a light grid, organs grow at their stages' rates.
    EXPECT_EQ(shared::lightResponse(0.0f, 0.0f), 1.0f);
}

TEST(Environment, ClimateAndSoilScaleGrowthAroundTheThesisValues) {
    ir::EcoScene scene;
    scene.dayLight = ir::EcoNumber::constant(12.0f);
    scene.rainRate = ir::EcoNumber::constant(0.9f);
    scene.soilPH = ir::EcoNumber::constant(7.0f);
    EXPECT_FLOAT_EQ(grow::environmentGrowthFactor(scene), 1.0f);
    // Longer days, more rain: more growth, saturating; none without light or water.
    EXPECT_LT(grow::dayLightResponse(6.0f), 1.0f);
    EXPECT_GT(grow::dayLightResponse(16.0f), 1.0f);
    EXPECT_LT(grow::dayLightResponse(24.0f) - grow::dayLightResponse(18.0f),
              grow::dayLightResponse(12.0f) - grow::dayLightResponse(6.0f));
    EXPECT_EQ(grow::dayLightResponse(0.0f), 0.0f);
    EXPECT_EQ(grow::rainResponse(0.0f), 0.0f);
    EXPECT_GT(grow::rainResponse(2.0f), 1.0f);
    // Acid or alkaline soil slows growth alike.
    EXPECT_FLOAT_EQ(grow::soilResponse(6.5f), 1.0f);
    EXPECT_NEAR(grow::soilResponse(4.5f), std::exp(-1.0f), 1e-6f);
    EXPECT_NEAR(grow::soilResponse(9.0f), std::exp(-1.0f), 1e-6f);
    scene.soilPH = ir::EcoNumber::constant(4.5f);
    scene.dayLight = ir::EcoNumber::constant(16.0f);
    EXPECT_FLOAT_EQ(grow::environmentGrowthFactor(scene), grow::dayLightResponse(16.0f) * std::exp(-1.0f));
}

} // namespace
} // namespace simeco
