// The light grid (grow/light_grid.h) as users see it: a layer of it as an image, and the whole grid in 3D as a
// cloud of shade among the plants. Also the grid of a field that is only drawn, not grown (`simeco render`).
#pragma once

#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "draw/bounds.h"
#include "draw/frame.h"
#include "draw/renderer.h"
#include "grow/light_grid.h"
#include "ir/eco_field.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_gpu.h"

namespace simeco::vk {
class Context;
}

namespace simeco::field {

// The light of every voxel of a grid (xyz: the direction most of it comes from; w: its amount), and the light in
// the open, which a voxel nothing shades receives; and which plant holds each voxel (compute/shared/light_layout.h:
// plant + 1, kVoxelShared or kVoxelEmpty), the space the plants compete for.
struct LightVolume {
    grow::LightGridSpec spec;
    std::vector<glm::vec4> light;
    float open = 0;
    std::vector<uint32_t> holders;
};

// One layer of the light grid: `rows` of `width` voxels' light, the first row the one an image shows at its top.
struct LightSlice {
    uint32_t width = 0, rows = 0;
    float at = 0; // the layer's centres' height (a slice) or depth (a section)
    float open = 0;
    std::vector<float> light;
};

// The horizontal layer at `height` (clamped to the grid) seen from above: x across, z down the image.
LightSlice lightSlice(const LightVolume& volume, float height);
// The vertical layer at z = `depth` seen from the front (-z): x across, the top layer first.
LightSlice lightSection(const LightVolume& volume, float depth);

// A layer as an image, each voxel a square of pixels: dark blue where no light comes, through green, to pale
// yellow for the light in the open.
draw::Frame lightSliceImage(const LightSlice& slice);

// One horizontal layer of which plant holds each voxel, as a lightSlice lays it out.
struct OccupancySlice {
    uint32_t width = 0, rows = 0;
    float at = 0;
    std::vector<uint32_t> holders;
};
OccupancySlice occupancySlice(const LightVolume& volume, float height);

// The layer as an image: each plant's voxels in a colour of its own, those several plants share dark grey, the
// empty ones pale.
draw::Frame occupancySliceImage(const OccupancySlice& slice);

// Light below this share of the open's counts as shade in the 3D view; lighter voxels are left out.
inline constexpr float kShadeShown = 0.9f;

// The grid's shade in 3D, as organs drawn with the plants: a sphere at the centre of each voxel darker than
// kShadeShown of the open's light, larger and of a deeper blue the deeper its shade (at most 0.3 of a voxel
// across, so that the plants stay visible through the cloud). The spheres are of plant `plant` (past the field's
// plants, as the obstacles are), the organ id of each its voxel's index.
turtle::Interpretation shadeOrgans(const LightVolume& volume, uint32_t plant);

// The field's organs (`parts`) drawn with the grid's shade among them (shadeOrgans, of plant `shadePlant`), framed
// on `bounds`, without shadow volumes: the shade drawn is the view's subject.
draw::Frame renderWithShade(const vk::Context& context, draw::Renderer& renderer,
                            const std::vector<const turtle::DeviceOrgans*>& parts, const LightVolume& volume,
                            uint32_t shadePlant, const draw::Bounds& bounds, draw::RenderSettings settings);

// The light sun and sky give the organs of a field that is only drawn: a grid over `bounds` sized for `plants`
// (grow::lightGridOver), the organs splatted into it (a leaf's area by `shapeAreas`) and `obstacles` filling their
// voxels, the light propagated from the sun and sky `light` sets (the defaults where it sets none).
LightVolume lightOfOrgans(const vk::Context& context, const std::vector<const turtle::DeviceOrgans*>& parts,
                          const draw::Bounds& bounds, uint32_t plants, const ir::EcoLight& light,
                          const std::vector<ir::EcoObstacle>& obstacles, const std::vector<float>& shapeAreas);

// Where the light of a scene's `light` comes from (the sun, then the sky: grow::lightDirections); `open` is set to
// their light in the open.
std::vector<shared::LightDirection> sceneLightDirections(const ir::EcoLight& light, float& open);

} // namespace simeco::field
