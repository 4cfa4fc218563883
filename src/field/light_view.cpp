#include "field/light_view.h"

#include <algorithm>
#include <cmath>

#include <glm/common.hpp>
#include <glm/vec3.hpp>

#include "compute/shared/light_layout.h"
#include "draw/render_settings.h"
#include "field/obstacles.h"
#include "field/simulation.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace simeco::field {

namespace {

// The sky's light in the light grid, as a share of the sun's: about a clear day's diffuse light.
constexpr float kSkyShare = 0.3f;

// The colour of light `share` of the open's (0 to 1): dark blue, through green, to pale yellow.
glm::vec3 lightColour(float share) {
    const glm::vec3 ramp[] = {{0.01f, 0.01f, 0.08f}, {0.02f, 0.25f, 0.08f}, {1.0f, 0.95f, 0.55f}};
    const float t = std::clamp(share, 0.0f, 1.0f);
    return t < 0.5f ? glm::mix(ramp[0], ramp[1], 2.0f * t) : glm::mix(ramp[1], ramp[2], 2.0f * t - 1.0f);
}

// The radius of the spheres of shadeOrgans in the deepest shade, in voxels.
constexpr float kShadeRadius = 0.3f;

float shareOfOpen(float light, float open) { return light / std::max(open, 1e-6f); }

// The voxels of the layer across `axis` (1: a horizontal slice, rows along z; 2: a vertical section, rows down y),
// row by row as an image shows them; its size and its centres' coordinate into `width`, `rows` and `at`.
std::vector<uint64_t> layerVoxels(const grow::LightGridSpec& spec, int axis, float coordinate, uint32_t& width,
                                  uint32_t& rows, float& at) {
    const auto k = size_t(axis);
    const auto layer = uint32_t(
        std::clamp(std::floor((coordinate - spec.origin[axis]) / spec.side), 0.0f, float(spec.size[k] - 1)));
    at = spec.origin[axis] + (float(layer) + 0.5f) * spec.side;
    width = spec.size[0];
    rows = axis == 1 ? spec.size[2] : spec.size[1];
    auto voxel = [&](uint32_t x, uint32_t y, uint32_t z) {
        return (uint64_t(z) * spec.size[1] + y) * spec.size[0] + x;
    };
    std::vector<uint64_t> voxels;
    for (uint32_t r = 0; r < rows; ++r)
        for (uint32_t x = 0; x < width; ++x)
            voxels.push_back(axis == 1 ? voxel(x, layer, r) : voxel(x, rows - 1 - r, layer));
    return voxels;
}

LightSlice lightLayer(const LightVolume& volume, int axis, float coordinate) {
    LightSlice slice;
    if (volume.light.empty()) return slice;
    slice.open = volume.open;
    for (uint64_t v : layerVoxels(volume.spec, axis, coordinate, slice.width, slice.rows, slice.at))
        slice.light.push_back(volume.light[v].w);
    return slice;
}

// An image of a layer's values, each voxel a square of pixels of the colour `colourOf` gives its value.
template <typename Value, typename Colour>
draw::Frame layerImage(uint32_t width, uint32_t rows, const std::vector<Value>& values, Colour colourOf) {
    const uint32_t scale = std::max(1u, std::min(16u, 1024u / std::max({width, rows, 1u})));
    draw::Frame frame;
    frame.width = width * scale;
    frame.height = rows * scale;
    frame.rgba.resize(frame.pixelCount() * 4);
    frame.depth.assign(frame.pixelCount(), 0.0f);
    frame.plant.assign(frame.pixelCount(), draw::Frame::kNoId);
    frame.organ.assign(frame.pixelCount(), draw::Frame::kNoId);
    for (uint32_t y = 0; y < frame.height; ++y)
        for (uint32_t x = 0; x < frame.width; ++x) {
            const glm::vec3 c = colourOf(values[size_t(y / scale) * width + x / scale]);
            float* p = &frame.rgba[frame.index(x, y) * 4];
            p[0] = c.r, p[1] = c.g, p[2] = c.b, p[3] = 1.0f;
        }
    return frame;
}

// A plant's colour in the occupancy view: hues spread by the golden angle, so that neighbours differ.
glm::vec3 plantColour(uint32_t plant) {
    const float hue = std::fmod(float(plant) * 0.618034f, 1.0f) * 6.0f;
    const glm::vec3 rgb = glm::clamp(glm::abs(glm::mod(hue + glm::vec3(0.0f, 4.0f, 2.0f), 6.0f) - 3.0f) - 1.0f, 0.0f,
                                     1.0f);
    return glm::mix(glm::vec3(0.15f), rgb, 0.75f);
}

} // namespace

LightSlice lightSlice(const LightVolume& volume, float height) { return lightLayer(volume, 1, height); }

LightSlice lightSection(const LightVolume& volume, float depth) { return lightLayer(volume, 2, depth); }

draw::Frame lightSliceImage(const LightSlice& slice) {
    return layerImage(slice.width, slice.rows, slice.light,
                      [&](float light) { return lightColour(shareOfOpen(light, slice.open)); });
}

OccupancySlice occupancySlice(const LightVolume& volume, float height) {
    OccupancySlice slice;
    if (volume.holders.empty()) return slice;
    for (uint64_t v : layerVoxels(volume.spec, 1, height, slice.width, slice.rows, slice.at))
        slice.holders.push_back(volume.holders[v]);
    return slice;
}

draw::Frame occupancySliceImage(const OccupancySlice& slice) {
    return layerImage(slice.width, slice.rows, slice.holders, [](uint32_t holder) {
        if (holder == shared::kVoxelEmpty) return glm::vec3(0.85f, 0.83f, 0.78f);
        if (holder == shared::kVoxelShared) return glm::vec3(0.08f);
        return plantColour(holder - 1);
    });
}

turtle::Interpretation shadeOrgans(const LightVolume& volume, uint32_t plant) {
    turtle::Interpretation result;
    for (uint64_t v = 0; v < volume.light.size(); ++v) {
        const float share = std::clamp(shareOfOpen(volume.light[v].w, volume.open), 0.0f, 1.0f);
        if (share >= kShadeShown) continue;
        // From nothing at kShadeShown to all at no light. The radius by its square root, so that mild shade shows
        // as small spheres; in blues, which no plant's organs share.
        const float depth = (kShadeShown - share) / kShadeShown;
        const float radius = kShadeRadius * volume.spec.side * std::sqrt(depth);
        const glm::vec3 centre = volume.spec.centre(v);
        const glm::vec3 colour = glm::mix(glm::vec3(0.7f, 0.75f, 0.95f), glm::vec3(0.03f, 0.03f, 0.3f), depth);
        shared::OrganInstance o{};
        o.kind = shared::kOrganSphere;
        o.plant = plant;
        o.module = uint32_t(v);
        o.position = {centre.x, centre.y, centre.z, 0.0f};
        o.heading = {0.0f, 1.0f, 0.0f, radius};
        o.up = {0.0f, 0.0f, 1.0f, radius};
        o.color = {colour.r, colour.g, colour.b, 1.0f};
        result.organs.push_back(o);
        result.bounds.add(centre, radius);
    }
    result.count[shared::kOrganSphere] = uint32_t(result.organs.size());
    for (uint32_t kind = 1; kind < shared::kOrganKinds; ++kind)
        result.first[kind] = result.first[kind - 1] + result.count[kind - 1];
    return result;
}

draw::Frame renderWithShade(const vk::Context& context, draw::Renderer& renderer,
                            const std::vector<const turtle::DeviceOrgans*>& parts, const LightVolume& volume,
                            uint32_t shadePlant, const draw::Bounds& bounds, draw::RenderSettings settings) {
    const turtle::DeviceOrgans shade = turtle::uploadOrgans(context, shadeOrgans(volume, shadePlant));
    std::vector<draw::OrganPart> drawn = organParts(parts);
    drawn.push_back({&shade.instances, &shade.table});
    settings.shadows = draw::Shadows::None;
    return renderer.render(drawn, bounds, settings);
}

std::vector<shared::LightDirection> sceneLightDirections(const ir::EcoLight& light, float& open) {
    // The sun the renderer draws with where the scene sets none.
    const glm::vec3 sun = light.sunDirection ? glm::vec3((*light.sunDirection)[0], (*light.sunDirection)[1],
                                                         (*light.sunDirection)[2])
                                             : draw::RenderSettings{}.sunDirection;
    std::vector<shared::LightDirection> from =
        grow::lightDirections(sun, light.sunIntensity.value_or(1.0f), kSkyShare * light.skyLight.value_or(1.0f));
    open = 0.0f;
    for (const shared::LightDirection& d : from) open += d.towardAndIntensity.w;
    return from;
}

LightVolume lightOfOrgans(const vk::Context& context, const std::vector<const turtle::DeviceOrgans*>& parts,
                          const draw::Bounds& bounds, uint32_t plants, const ir::EcoLight& light,
                          const std::vector<ir::EcoObstacle>& obstacles, const std::vector<float>& shapeAreas) {
    LightVolume volume;
    const std::vector<shared::LightDirection> from = sceneLightDirections(light, volume.open);
    volume.spec = grow::lightGridOver(bounds.min, bounds.max, plants);
    grow::GpuLightGrid grid(context, volume.spec, from, obstacleVoxels(volume.spec, obstacles), shapeAreas);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        grid.recordClear(cmd);
        for (const turtle::DeviceOrgans* part : parts) grid.recordSplat(cmd, *part);
        grid.recordPropagate(cmd);
    });
    grid.turn();
    volume.light = vk::downloadVector<glm::vec4>(context, grid.light(), volume.spec.voxels());
    volume.holders = vk::downloadVector<uint32_t>(context, grid.holders(), volume.spec.voxels());
    return volume;
}

} // namespace simeco::field
