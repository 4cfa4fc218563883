// The light grid of the growth simulation (compute/shared/light_layout.h): a box of cubic voxels over the field,
// the organs' shading area splatted into it, light propagated from the sun and the sky, and each organ's particle
// given the light of its voxel and the direction most of it comes from. On the device (GpuLightGrid, recorded into
// the caller's command buffer) and in a CPU reference (LightGridCpu) the tests compare it with.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <vulkan/vulkan.h>

#include "compute/shared/light_layout.h"
#include "compute/shared/particle_layout.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_gpu.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::vk {
class Context;
}

namespace simeco::grow {

struct LightGridSpec {
    glm::vec3 origin{0.0f}; // the lowest corner
    float side = 1.0f;      // of a voxel
    std::array<uint32_t, 3> size{1, 1, 1};

    uint64_t voxels() const { return uint64_t(size[0]) * size[1] * size[2]; }
    glm::vec3 centre(uint64_t voxel) const;
    // What the shaders multiply by where they would divide by the side (compute/shared/light_layout.h).
    float inverseSide() const { return 1.0f / side; }
    // The grid coordinates of the voxel holding p, whole numbers, outside the grid or not.
    glm::vec3 cellAt(glm::vec3 p) const { return glm::floor((p - origin) * inverseSide()); }
    // The voxel of a cell, or -1 outside the grid.
    int64_t voxelOfCell(glm::vec3 cell) const;
    // The voxel holding p, or -1 outside (compute/grow/light_grid.glsl's voxelAt).
    int64_t voxelAt(glm::vec3 p) const { return voxelOfCell(cellAt(p)); }
    // The layers up to the highest where `filled` (per voxel) is not 0.
    uint32_t layersUpTo(const std::vector<uint32_t>& filled) const;
};

// Voxels the grid may have per plant, and at least and at most in all: the grid's cost stays proportional to the
// field's plants (each plant shades within a few voxels of its organs), bounded for a field of any size.
inline constexpr uint64_t kVoxelsPerPlant = 512;
inline constexpr uint64_t kLeastVoxels = 4096;
inline constexpr uint64_t kMostVoxels = uint64_t(1) << 24;

// A grid of cubic voxels over [low, high] (the field's extent as it grows), as many as the field's plants allow.
LightGridSpec lightGridOver(glm::vec3 low, glm::vec3 high, uint32_t plants);

// Where light comes from: the sun (towards it, `sunIntensity`; none below the horizon), then the sky as
// kSkyDirections directions over the upper hemisphere sharing `skyLight` (one at the zenith and rings at 60° and
// 30° of elevation), each its share of the light on a horizontal surface.
inline constexpr uint32_t kSkyDirections = 13;
std::vector<shared::LightDirection> lightDirections(glm::vec3 sunToward, float sunIntensity, float skyLight);

// The direction as light_gather.comp packs it into a particle (octahedral, packSnorm2x16), and back.
float packLightDirection(glm::vec3 unit);
glm::vec3 unpackLightDirection(float packed);

// The CPU reference: the same passes as plain loops.
class LightGridCpu {
public:
    // `obstacles`: per voxel, 1 where an obstacle fills it.
    LightGridCpu(const LightGridSpec& spec, std::vector<shared::LightDirection> directions,
                 std::vector<uint32_t> obstacles);

    void setDirections(std::vector<shared::LightDirection> directions) { directions_ = std::move(directions); }
    void clear(); // the splatted areas and the voxels' holders
    // `organs`' plants numbered as in the field.
    void splat(const turtle::Interpretation& organs, const std::vector<float>& shapeAreas);
    void propagate();
    // The light at point `p` of the field: xyz the direction most of it comes from, w its amount (the open's outside
    // the grid).
    glm::vec4 lightAt(glm::vec3 p) const;
    // Each organ's light and room to grow into `particles` (one state per module of the drawn string), and into the
    // particle `derivedOf` gives for its module (the derived string's it was drawn from), where it gives one.
    using DerivedParticle = std::function<shared::ParticleState*(uint32_t drawnModule)>;
    void gather(const turtle::Interpretation& organs, std::vector<shared::ParticleState>& particles,
                const DerivedParticle& derivedOf = {}) const;

    const LightGridSpec& spec() const { return spec_; }
    const std::vector<uint32_t>& occupancy() const { return occupancy_; }
    const std::vector<uint32_t>& holders() const { return holders_; } // plant + 1, kVoxelEmpty or kVoxelShared
    const std::vector<glm::vec4>& light() const { return light_; }    // xyz: most light from; w: light

private:
    float openLight() const; // the light outside the grid: all its directions' in full

    LightGridSpec spec_;
    std::vector<shared::LightDirection> directions_;
    std::vector<uint32_t> obstacles_, occupancy_, holders_;
    std::vector<glm::vec4> light_;
    std::vector<glm::uvec2> room_; // the last propagation's holders and areas, which the gather reads
};

class GpuLightGrid {
public:
    GpuLightGrid(const vk::Context& context, const LightGridSpec& spec,
                 const std::vector<shared::LightDirection>& directions, const std::vector<uint32_t>& obstacles,
                 const std::vector<float>& shapeAreas);

    // The light to propagate from, for the drawings after (a viewer moving the sun); the caller's submissions
    // reading the old directions must have completed.
    void setDirections(const std::vector<shared::LightDirection>& directions);

    void recordClear(VkCommandBuffer cmd);
    // `firstPlant`: the field's number of the organs' plant 0 (a batch's first plant).
    void recordSplat(VkCommandBuffer cmd, const turtle::DeviceOrgans& organs, uint32_t firstPlant = 0);
    // The light of what is splatted, into the grid's other light and room: what the gathers and queries recorded
    // read stays the last turn()'s, so that one submission may splat a drawing's organs and propagate them while
    // organs drawn after it still gather the light before. Propagating again writes the same buffers anew.
    void recordPropagate(VkCommandBuffer cmd);
    // The light last propagated becomes the light the gathers and queries recorded after this read, and light().
    void turn() { lit_ = 1 - lit_; }
    // The organs' light and room to grow into the drawn string's particles, and into the derived string's it was
    // drawn from: by the drawn modules' `origins` where it was drawn under the homomorphism, else module for module
    // where `derivedParticles` is another buffer than the drawn ones (a copy drawn).
    void recordGather(VkCommandBuffer cmd, const turtle::DeviceOrgans& organs, const vk::Buffer& drawnParticles,
                      const vk::Buffer* origins = nullptr, const vk::Buffer* derivedParticles = nullptr,
                      uint32_t firstPlant = 0);

    // cpfg's `?E` queries among the `count` modules the turtle last interpreted (`states`), answered from the last
    // drawing's light into the derived string's modules (`derivedSymbols`, `derivedParams`, `stride` slots a
    // module): through `origins` where the string was drawn under the homomorphism, else module for module.
    void recordQueries(VkCommandBuffer cmd, const turtle::GpuTurtle::ModuleStates& states, uint32_t count,
                       const vk::Buffer* origins, const vk::Buffer& derivedSymbols, const vk::Buffer& derivedParams,
                       uint32_t stride);

    const vk::Buffer& occupancy() const { return occupancy_; }
    const vk::Buffer& holders() const { return holders_; }
    const vk::Buffer& light() const { return light_[lit_]; }
    const LightGridSpec& spec() const { return spec_; }

private:
    shared::LightGridPush push() const;

    const vk::Context& context_;
    LightGridSpec spec_;
    uint32_t directionCount_;
    vk::ComputePipeline splat_, propagate_, gather_, queries_;
    vk::Buffer directions_, obstacles_, shapeAreas_, occupancy_, holders_;
    vk::Buffer light_[2], room_[2]; // the light and room read ([lit_]) and the next propagation's
    uint32_t lit_ = 0;
    vk::Buffer top_;       // the layers up to the highest with leaf area (the splat's)
    uint32_t obstacleTop_ = 0; // the layers up to the highest an obstacle fills
    vk::Buffer none_; // bound where the gather has no origins or derived particles
};

} // namespace simeco::grow
