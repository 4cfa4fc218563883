// The light grid of a field that is only drawn (field::lightOfOrgans, `simeco render --light-*`) against the CPU
// reference over the same organs, and its shade drawn among the plants.
#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "cpu/derive.h"
#include "field/light_view.h"
#include "field/obstacles.h"
#include "field/plant_statistics.h"
#include "lang/load_grammar.h"
#include "test_scene.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_gpu.h"
#include "turtle/turtle_settings.h"

namespace simeco::test {
namespace {

using LightViewTest = RenderTest;

TEST_F(LightViewTest, ADrawnFieldsLightIsTheReferencesAndItsShadeIsDrawnAmongThePlants) {
    // Four bushes of ABOP's figure 1.24d in a row along x, and a wall beyond them on the sun's side.
    ir::Grammar g = lang::loadGrammarFile(std::string(SIMECO_SOURCE_DIR) + "/grammars/abop/fig1.24d.l");
    stream::DeriveOptions options;
    options.plants = 4;
    options.steps = 3;
    const stream::ModuleString string = cpu::deriveCpu(g, options).string;
    const turtle::Interpretation organs = turtle::interpretCpu(string, turtle::turtleCommands(g.alphabet),
                                                               {turtle::turtleSettings(g, g.alphabet)}, {});
    ASSERT_GT(organs.count[shared::kOrganStem], 50u);
    const glm::vec3 size = organs.bounds.max - organs.bounds.min;
    ir::EcoObstacle wall;
    wall.center[0] = organs.bounds.max.x + 0.5f * size.y;
    wall.center[1] = 0.5f * size.y;
    wall.center[2] = 0.5f * (organs.bounds.min.z + organs.bounds.max.z);
    wall.halfSize[0] = 0.05f * size.y; // thin across x
    wall.halfSize[1] = 0.5f * size.y;
    wall.halfSize[2] = 0.5f * size.z; // as long as the row is deep
    const std::vector<ir::EcoObstacle> obstacles = {wall};
    draw::Bounds bounds{organs.bounds.min, organs.bounds.max};
    for (const glm::vec3& corner : field::obstacleCorners(wall)) {
        bounds.min = glm::min(bounds.min, corner);
        bounds.max = glm::max(bounds.max, corner);
    }
    bounds.max.x += 0.5f * size.y; // the ground beyond the wall, in the sun
    ir::EcoLight light;
    light.sunDirection = std::array<float, 3>{1.0f, 1.2f, 0.0f}; // low in the +x sky, behind the wall
    const std::vector<float> shapeAreas = field::leafShapeAreas();

    const turtle::DeviceOrgans uploaded = turtle::uploadOrgans(context(), organs);
    const field::LightVolume volume =
        field::lightOfOrgans(context(), {&uploaded}, bounds, 4, light, obstacles, shapeAreas);

    float open = 0.0f;
    const std::vector<shared::LightDirection> from = field::sceneLightDirections(light, open);
    const grow::LightGridSpec spec = grow::lightGridOver(bounds.min, bounds.max, 4);
    grow::LightGridCpu reference(spec, from, field::obstacleVoxels(spec, obstacles));
    reference.splat(organs, shapeAreas);
    reference.propagate();
    ASSERT_EQ(volume.spec.size, spec.size);
    EXPECT_EQ(volume.spec.origin, spec.origin);
    EXPECT_FLOAT_EQ(volume.open, open);
    ASSERT_EQ(volume.light.size(), reference.light().size());
    for (size_t v = 0; v < volume.light.size(); ++v)
        ASSERT_NEAR(volume.light[v].w, reference.light()[v].w, 1e-5f) << "voxel " << v;

    // The wall's shade falls on its far side from the sun, the bushes' side; its sunny side keeps the sun's light.
    const float wallX = wall.center[0], reach = 0.3f * size.y;
    float shadySide = 0.0f, sunnySide = 0.0f;
    int shadyVoxels = 0, sunnyVoxels = 0;
    for (uint64_t v = 0; v < spec.voxels(); ++v) {
        const glm::vec3 c = spec.centre(v);
        const float dx = c.x - wallX;
        if (c.y > reach || std::abs(dx) > reach || std::abs(dx) < wall.halfSize[0] + spec.side) continue;
        (dx < 0.0f ? shadySide : sunnySide) += volume.light[v].w / open;
        ++(dx < 0.0f ? shadyVoxels : sunnyVoxels);
    }
    ASSERT_GT(shadyVoxels, 0);
    ASSERT_GT(sunnyVoxels, 0);
    EXPECT_LT(shadySide / float(shadyVoxels), 0.5f * sunnySide / float(sunnyVoxels));
    // And its spheres stand there.
    const turtle::Interpretation shade = field::shadeOrgans(volume, 5);
    int besideTheWall = 0;
    for (const shared::OrganInstance& o : shade.organs) {
        const float dx = o.position.x - wallX;
        besideTheWall += o.position.y < reach && dx < 0.0f && dx > -reach ? 1 : 0;
    }
    EXPECT_GT(besideTheWall, 4);

    // Drawn: the bushes and the spheres of the shade.
    draw::RenderSettings settings;
    settings.width = 160;
    settings.height = 120;
    settings.shadows = draw::Shadows::Volume; // the view draws none whatever it is asked
    const draw::Frame frame = field::renderWithShade(context(), renderer(), {&uploaded}, volume, 5, bounds, settings);
    maybeSavePreview(frame, "light_volume");
    std::set<uint32_t> plants(frame.plant.begin(), frame.plant.end());
    EXPECT_TRUE(plants.count(5));
    EXPECT_TRUE(plants.count(0) && plants.count(3));
}

} // namespace
} // namespace simeco::test
