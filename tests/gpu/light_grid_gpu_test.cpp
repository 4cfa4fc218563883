// The light grid's kernels (compute/grow/light_*.comp) against its CPU reference (grow/light_grid.h): the same
// splatted areas to the unit, the same light within float rounding, the same light in each organ's particle.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "cpu/derive.h"
#include "gpu_fixture.h"
#include "grow/light_grid.h"
#include "lang/load_grammar.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_gpu.h"
#include "turtle/turtle_settings.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace simeco::test {
namespace {

const std::filesystem::path kGrammars = std::filesystem::path(SIMECO_SOURCE_DIR) / "grammars";

class LightGridGpuTest : public GpuTest {};

TEST_F(LightGridGpuTest, TheDeviceLightsAFieldAsTheReference) {
    // Nine bushes of ABOP's figure 1.24d, scattered, and a canopy of leaves over some of them.
    ir::Grammar g = lang::loadGrammarFile((kGrammars / "abop" / "fig1.24d.l").string());
    stream::DeriveOptions options;
    options.plants = 9;
    options.steps = 4;
    const stream::ModuleString string = cpu::deriveCpu(g, options).string;
    turtle::FieldOptions field;
    field.scattered = true;
    turtle::Interpretation organs = turtle::interpretCpu(string, turtle::turtleCommands(g.alphabet),
                                                         {turtle::turtleSettings(g, g.alphabet)}, field);
    ASSERT_GT(organs.count[shared::kOrganStem], 100u);
    const float top = organs.bounds.max.y;
    std::vector<shared::OrganInstance> canopy;
    for (int k = 0; k < 40; ++k) {
        shared::OrganInstance o{};
        o.kind = shared::kOrganLeaf;
        o.shape = uint32_t(k % 6);
        o.module = uint32_t(k) % uint32_t(string.size());
        o.position = {organs.bounds.min.x + 0.7f * float(k % 8), 0.8f * top, organs.bounds.min.z + 0.9f * float(k / 8),
                      1.5f};
        o.heading = {0.6f, 0.0f, 0.8f, 0.8f};
        o.up = {0, 1, 0, 0};
        o.plant = uint32_t(k % 9);
        canopy.push_back(o);
        // A small leaf of the next plant beside it: the two plants share the voxel.
        o.plant = uint32_t(k + 1) % 9;
        o.position.w = 0.05f;
        canopy.push_back(o);
    }
    // The leaves go with the field's leaves (none here), in module order.
    organs.organs.insert(organs.organs.begin() + organs.first[shared::kOrganLeaf], canopy.begin(), canopy.end());
    organs.count[shared::kOrganLeaf] += uint32_t(canopy.size());
    for (uint32_t k = shared::kOrganLeaf + 1; k < shared::kOrganKinds; ++k) organs.first[k] += uint32_t(canopy.size());

    const grow::LightGridSpec spec = grow::lightGridOver(organs.bounds.min, organs.bounds.max, 9);
    const std::vector<shared::LightDirection> directions = grow::lightDirections({-0.45f, 0.8f, 0.4f}, 1.0f, 0.3f);
    std::vector<uint32_t> obstacles(spec.voxels(), 0);
    obstacles[spec.voxels() / 2] = 1;
    const std::vector<float> shapeAreas = {0.35f, 0.6f, 0.5f, 0.3f, 0.4f, 0.55f};

    grow::LightGridCpu cpu(spec, directions, obstacles);
    cpu.splat(organs, shapeAreas);
    cpu.propagate();
    std::vector<shared::ParticleState> want(string.size());
    cpu.gather(organs, want);

    grow::GpuLightGrid gpu(context(), spec, directions, obstacles, shapeAreas);
    const turtle::DeviceOrgans uploaded = turtle::uploadOrgans(context(), organs);
    const std::vector<shared::ParticleState> none(string.size());
    vk::Buffer particles = vk::deviceBufferWith(context(), std::span<const shared::ParticleState>(none));
    context().submitAndWait([&](VkCommandBuffer cmd) {
        gpu.recordClear(cmd);
        gpu.recordSplat(cmd, uploaded);
        gpu.recordPropagate(cmd);
        gpu.turn();
        gpu.recordGather(cmd, uploaded, particles);
    });
    EXPECT_EQ(vk::downloadVector<uint32_t>(context(), gpu.occupancy(), spec.voxels()), cpu.occupancy());
    // The voxels' holders: the bushes' own, shared where the canopy's leaves of two plants meet.
    const std::vector<uint32_t> holders = vk::downloadVector<uint32_t>(context(), gpu.holders(), spec.voxels());
    EXPECT_EQ(holders, cpu.holders());
    EXPECT_GT(std::count(holders.begin(), holders.end(), shared::kVoxelShared), 5);
    EXPECT_GT(std::count(holders.begin(), holders.end(), 9u), 5); // the last bush's alone
    const std::vector<glm::vec4> light = vk::downloadVector<glm::vec4>(context(), gpu.light(), spec.voxels());
    int shaded = 0;
    for (size_t v = 0; v < light.size(); ++v) {
        ASSERT_NEAR(light[v].w, cpu.light()[v].w, 1e-5f) << "voxel " << v;
        ASSERT_NEAR(glm::distance(glm::vec3(light[v]), glm::vec3(cpu.light()[v])), 0.0f, 1e-4f) << "voxel " << v;
        shaded += light[v].w < 1.25f ? 1 : 0;
    }
    EXPECT_GT(shaded, 10); // the canopy and the bushes shade something
    const std::vector<shared::ParticleState> got =
        vk::downloadVector<shared::ParticleState>(context(), particles, string.size());
    int lit = 0, blocked = 0, crowded = 0;
    for (size_t m = 0; m < got.size(); ++m) {
        ASSERT_NEAR(got[m].value[shared::kParticleLight], want[m].value[shared::kParticleLight], 1e-5f) << m;
        const float space = want[m].value[shared::kParticleSpace];
        ASSERT_NEAR(got[m].value[shared::kParticleSpace], space, 1e-5f) << m;
        blocked += space == 0.0f ? 1 : 0;
        crowded += space > 0.0f && space < 1.0f ? 1 : 0;
        const glm::vec3 a = grow::unpackLightDirection(got[m].value[shared::kParticleLightDirection]);
        const glm::vec3 b = grow::unpackLightDirection(want[m].value[shared::kParticleLightDirection]);
        if (want[m].value[shared::kParticleLight] > 0.0f) {
            EXPECT_GT(glm::dot(a, b), 0.999f) << m;
        }
        lit += want[m].value[shared::kParticleLight] > 0.0f ? 1 : 0;
    }
    EXPECT_GT(lit, 100);
    EXPECT_GT(blocked, 0); // organs reaching into a neighbour's voxels
    EXPECT_GT(crowded, 0); // organs in voxels they share
}

} // namespace
} // namespace simeco::test
