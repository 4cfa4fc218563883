#include "grow/light_grid.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <span>
#include <utility>

#include <glm/geometric.hpp>
#include <glm/packing.hpp>
#include <glm/vec2.hpp>

#include "turtle/turtle_cpu.h"
#include "vk/barriers.h"
#include "vk/context.h"

namespace simeco::grow {

namespace {

constexpr float kPi = 3.14159265358979f;

// compute/grow/light_grid.glsl's organCentre, organTip and organShadingArea.
glm::vec3 xyz(const shared::vec4& v) {
    return {v.x, v.y, v.z};
}

glm::vec3 organCentre(const shared::OrganInstance& o) {
    if (o.kind == shared::kOrganStem || o.kind == shared::kOrganLeaf)
        return xyz(o.position) + 0.5f * o.position.w * xyz(o.heading);
    if (o.kind == shared::kOrganTriangle) return (xyz(o.position) + xyz(o.heading) + xyz(o.up)) * shared::kOneThird;
    return xyz(o.position);
}

glm::vec3 organTip(const shared::OrganInstance& o) {
    if (o.kind == shared::kOrganStem || o.kind == shared::kOrganLeaf)
        return xyz(o.position) + o.position.w * xyz(o.heading);
    return organCentre(o);
}

float organShadingArea(const shared::OrganInstance& o, float shapeArea) {
    if (o.kind == shared::kOrganLeaf) return o.position.w * o.heading.w * shapeArea;
    if (o.kind == shared::kOrganStem) return o.position.w * (o.heading.w + o.up.w);
    if (o.kind == shared::kOrganTriangle)
        return 0.5f * glm::length(glm::cross(xyz(o.heading) - xyz(o.position), xyz(o.up) - xyz(o.position)));
    return kPi * o.heading.w * o.heading.w;
}

} // namespace

glm::vec3 LightGridSpec::centre(uint64_t voxel) const {
    const uint64_t x = voxel % size[0], y = (voxel / size[0]) % size[1], z = voxel / (uint64_t(size[0]) * size[1]);
    return origin + (glm::vec3(float(x), float(y), float(z)) + 0.5f) * side;
}

int64_t LightGridSpec::voxelOfCell(glm::vec3 cell) const {
    if (cell.x < 0.0f || cell.y < 0.0f || cell.z < 0.0f || cell.x >= float(size[0]) || cell.y >= float(size[1]) ||
        cell.z >= float(size[2]))
        return -1;
    return int64_t((uint64_t(cell.z) * size[1] + uint64_t(cell.y)) * size[0] + uint64_t(cell.x));
}

uint32_t LightGridSpec::layersUpTo(const std::vector<uint32_t>& filled) const {
    uint32_t layers = 0;
    for (uint64_t v = 0; v < std::min<uint64_t>(filled.size(), voxels()); ++v)
        if (filled[v] != 0) layers = std::max(layers, uint32_t((v / size[0]) % size[1]) + 1);
    return layers;
}

LightGridSpec lightGridOver(glm::vec3 low, glm::vec3 high, uint32_t plants) {
    const glm::vec3 extent = glm::max(high - low, glm::vec3(1e-3f));
    const uint64_t most = std::clamp<uint64_t>(kVoxelsPerPlant * std::max(plants, 1u), kLeastVoxels, kMostVoxels);
    LightGridSpec spec;
    spec.side = std::cbrt(extent.x * extent.y * extent.z / float(most));
    // Rounding each side up may add a layer: grow the voxels until the grid is within its count.
    for (;;) {
        for (int k = 0; k < 3; ++k) spec.size[size_t(k)] = std::max(1u, uint32_t(std::ceil(extent[k] / spec.side)));
        if (spec.voxels() <= most) break;
        spec.side *= 1.02f;
    }
    // Centred on the extent.
    const glm::vec3 grid = glm::vec3(float(spec.size[0]), float(spec.size[1]), float(spec.size[2])) * spec.side;
    spec.origin = low - 0.5f * (grid - extent);
    spec.origin.y = low.y;
    return spec;
}

std::vector<shared::LightDirection> lightDirections(glm::vec3 sunToward, float sunIntensity, float skyLight) {
    std::vector<shared::LightDirection> directions;
    const float length = glm::length(sunToward);
    const glm::vec3 sun = length > 0.0f ? sunToward / length : glm::vec3(0, 1, 0);
    directions.push_back({{sun.x, sun.y, sun.z, sun.y > 0.0f ? std::max(sunIntensity, 0.0f) : 0.0f}});
    // The zenith, then rings of six at 60° and 30° of elevation (the second turned half a step).
    std::vector<glm::vec3> sky = {{0, 1, 0}};
    for (int ring = 0; ring < 2; ++ring) {
        const float elevation = ring == 0 ? kPi / 3.0f : kPi / 6.0f;
        for (int k = 0; k < 6; ++k) {
            const float azimuth = 2.0f * kPi * (float(k) + 0.5f * float(ring)) / 6.0f;
            sky.push_back({std::cos(elevation) * std::cos(azimuth), std::sin(elevation),
                           std::cos(elevation) * std::sin(azimuth)});
        }
    }
    float weights = 0.0f;
    for (const glm::vec3& d : sky) weights += d.y;
    for (const glm::vec3& d : sky)
        directions.push_back({{d.x, d.y, d.z, std::max(skyLight, 0.0f) * d.y / weights}});
    return directions;
}

float packLightDirection(glm::vec3 n) {
    n /= std::abs(n.x) + std::abs(n.y) + std::abs(n.z);
    glm::vec2 e(n.x, n.z);
    if (n.y < 0.0f)
        e = (1.0f - glm::abs(glm::vec2(e.y, e.x))) * glm::vec2(e.x >= 0.0f ? 1.0f : -1.0f, e.y >= 0.0f ? 1.0f : -1.0f);
    const uint32_t bits = glm::packSnorm2x16(e);
    float packed;
    std::memcpy(&packed, &bits, sizeof packed);
    return packed;
}

glm::vec3 unpackLightDirection(float packed) {
    uint32_t bits;
    std::memcpy(&bits, &packed, sizeof bits);
    const glm::vec2 e = glm::unpackSnorm2x16(bits);
    glm::vec3 n(e.x, 1.0f - std::abs(e.x) - std::abs(e.y), e.y);
    if (n.y < 0.0f) {
        const glm::vec2 folded = (1.0f - glm::abs(glm::vec2(e.y, e.x))) *
                                 glm::vec2(e.x >= 0.0f ? 1.0f : -1.0f, e.y >= 0.0f ? 1.0f : -1.0f);
        n.x = folded.x;
        n.z = folded.y;
    }
    return glm::normalize(n);
}

LightGridCpu::LightGridCpu(const LightGridSpec& spec, std::vector<shared::LightDirection> directions,
                           std::vector<uint32_t> obstacles)
    : spec_(spec), directions_(std::move(directions)), obstacles_(std::move(obstacles)),
      occupancy_(spec.voxels(), 0), holders_(spec.voxels(), shared::kVoxelEmpty),
      light_(spec.voxels(), glm::vec4(0, 1, 0, 0)), room_(spec.voxels(), glm::uvec2(0)) {
    obstacles_.resize(spec.voxels(), 0);
    propagate(); // the light of an empty field until the first organs are splatted
}

void LightGridCpu::clear() {
    std::fill(occupancy_.begin(), occupancy_.end(), 0u);
    std::fill(holders_.begin(), holders_.end(), shared::kVoxelEmpty);
}

void LightGridCpu::splat(const turtle::Interpretation& organs, const std::vector<float>& shapeAreas) {
    for (const shared::OrganInstance& o : organs.organs) {
        const int64_t v = spec_.voxelAt(organCentre(o));
        if (v < 0) continue;
        const float shape = o.kind == shared::kOrganLeaf && o.shape < shapeAreas.size() ? shapeAreas[o.shape] : 0.0f;
        const auto units =
            uint32_t(std::clamp(organShadingArea(o, shape), 0.0f, 256.0f) * shared::kAreaFixedPoint + 0.5f);
        if (units == 0) continue;
        occupancy_[size_t(v)] += units;
        uint32_t& holder = holders_[size_t(v)];
        holder = holder == shared::kVoxelEmpty || holder == o.plant + 1 ? o.plant + 1 : shared::kVoxelShared;
    }
}

void LightGridCpu::propagate() {
    const float side = spec_.side;
    const float perUnit = shared::kLeafExtinction / (shared::kAreaFixedPoint * side * side * side);
    // Layers at or above it are empty (light_layout.h).
    const auto filled = float(std::max(spec_.layersUpTo(occupancy_), spec_.layersUpTo(obstacles_)));
    for (uint64_t v = 0; v < spec_.voxels(); ++v) {
        room_[v] = glm::uvec2(holders_[v], occupancy_[v]);
        if (obstacles_[v] != 0) {
            light_[v] = glm::vec4(0, 1, 0, 0);
            continue;
        }
        const glm::vec3 centre = glm::vec3(float(v % spec_.size[0]), float((v / spec_.size[0]) % spec_.size[1]),
                                           float(v / (uint64_t(spec_.size[0]) * spec_.size[1]))) +
                                 0.5f; // in voxels
        float total = 0.0f;
        glm::vec3 most(0.0f);
        for (const shared::LightDirection& d : directions_) {
            const glm::vec3 toward = xyz(d.towardAndIntensity);
            if (d.towardAndIntensity.w <= 0.0f) continue;
            float depth = 0.0f;
            bool blocked = false;
            for (uint32_t step = 1; step < 4096; ++step) {
                const glm::vec3 landed = glm::floor(centre + toward * float(step));
                if (toward.y > 0.0f && landed.y >= filled) break;
                const int64_t u = spec_.voxelOfCell(landed);
                if (u < 0) break;
                if (obstacles_[size_t(u)] != 0) {
                    blocked = true;
                    break;
                }
                depth += side * perUnit * float(occupancy_[size_t(u)]);
            }
            const float reaching = blocked ? 0.0f : d.towardAndIntensity.w * std::exp(-depth);
            total += reaching;
            most += reaching * toward;
        }
        light_[v] = glm::vec4(glm::dot(most, most) > 0.0f ? glm::normalize(most) : glm::vec3(0, 1, 0), total);
    }
}

float LightGridCpu::openLight() const {
    float open = 0.0f;
    for (const shared::LightDirection& d : directions_) open += std::max(d.towardAndIntensity.w, 0.0f);
    return open;
}

glm::vec4 LightGridCpu::lightAt(glm::vec3 p) const {
    const int64_t v = spec_.voxelAt(p);
    return v >= 0 ? light_[size_t(v)] : glm::vec4(0.0f, 1.0f, 0.0f, openLight());
}

void LightGridCpu::gather(const turtle::Interpretation& organs, std::vector<shared::ParticleState>& particles,
                          const DerivedParticle& derivedOf) const {
    const float open = openLight();
    for (uint32_t kind = 0; kind < shared::kOrganKinds; ++kind)
        for (uint32_t i = organs.first[kind]; i < organs.first[kind] + organs.count[kind]; ++i) {
            const shared::OrganInstance& o = organs.organs[i];
            if (i > organs.first[kind] && organs.organs[i - 1].module == o.module) continue;
            if (o.module >= particles.size()) continue;
            const int64_t v = spec_.voxelAt(organCentre(o));
            const glm::vec4 l = v >= 0 ? light_[size_t(v)] : glm::vec4(0, 1, 0, open);
            const float direction = packLightDirection(glm::vec3(l));
            // Its room to grow: none where its tip reaches into an obstacle's or (beyond its own voxel) another
            // plant's.
            const int64_t t = spec_.voxelAt(organTip(o));
            const bool blocked = t >= 0 && (obstacles_[size_t(t)] != 0 ||
                                            (t != v && room_[size_t(t)].x != shared::kVoxelEmpty &&
                                             room_[size_t(t)].x != o.plant + 1));
            const bool crowded = v >= 0 && room_[size_t(v)].x == shared::kVoxelShared;
            const float space = shared::roomToGrow(blocked, crowded, v >= 0 ? room_[size_t(v)].y : 0u, spec_.side);
            for (shared::ParticleState* p : {&particles[o.module], derivedOf ? derivedOf(o.module) : nullptr}) {
                if (!p) continue;
                p->value[shared::kParticleLight] = l.w;
                p->value[shared::kParticleLightDirection] = direction;
                p->value[shared::kParticleSpace] = space;
            }
        }
}

GpuLightGrid::GpuLightGrid(const vk::Context& context, const LightGridSpec& spec,
                           const std::vector<shared::LightDirection>& directions,
                           const std::vector<uint32_t>& obstacles, const std::vector<float>& shapeAreas)
    : context_(context), spec_(spec), directionCount_(uint32_t(directions.size())),
      splat_(vk::ComputePipeline::embedded(context, "grow/light_splat")),
      propagate_(vk::ComputePipeline::embedded(context, "grow/light_propagate")),
      gather_(vk::ComputePipeline::embedded(context, "grow/light_gather")),
      queries_(vk::ComputePipeline::embedded(context, "grow/light_queries")) {
    directions_ = vk::deviceBufferWith(context, std::span<const shared::LightDirection>(directions));
    std::vector<uint32_t> mask = obstacles;
    mask.resize(spec.voxels(), 0);
    obstacles_ = vk::deviceBufferWith(context, std::span<const uint32_t>(mask));
    obstacleTop_ = spec.layersUpTo(mask);
    top_ = vk::Buffer(context, 4, vk::MemoryUsage::DeviceLocal);
    shapeAreas_ = vk::deviceBufferWith(context, std::span<const float>(shapeAreas));
    occupancy_ = vk::Buffer(context, spec.voxels() * 4, vk::MemoryUsage::DeviceLocal);
    holders_ = vk::Buffer(context, spec.voxels() * 4, vk::MemoryUsage::DeviceLocal);
    for (uint32_t k = 0; k < 2; ++k) {
        light_[k] = vk::Buffer(context, spec.voxels() * sizeof(glm::vec4), vk::MemoryUsage::DeviceLocal);
        room_[k] = vk::Buffer(context, spec.voxels() * sizeof(glm::uvec2), vk::MemoryUsage::DeviceLocal);
    }
    none_ = vk::Buffer(context, sizeof(shared::ParticleState), vk::MemoryUsage::DeviceLocal);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        recordClear(cmd);
        recordPropagate(cmd); // the light of an empty field until the first organs are splatted
    });
    turn();
}

shared::LightGridPush GpuLightGrid::push() const {
    shared::LightGridPush p{};
    p.origin = {spec_.origin.x, spec_.origin.y, spec_.origin.z, spec_.side};
    p.sizeX = spec_.size[0];
    p.sizeY = spec_.size[1];
    p.sizeZ = spec_.size[2];
    p.directions = directionCount_;
    p.obstacleTop = obstacleTop_;
    p.inverseSide = spec_.inverseSide();
    return p;
}

void GpuLightGrid::setDirections(const std::vector<shared::LightDirection>& directions) {
    directions_ = vk::deviceBufferWith(context_, std::span<const shared::LightDirection>(directions));
    directionCount_ = uint32_t(directions.size());
}

void GpuLightGrid::recordClear(VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
    vkCmdFillBuffer(cmd, occupancy_.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, holders_.handle(), 0, VK_WHOLE_SIZE, shared::kVoxelEmpty);
    vkCmdFillBuffer(cmd, top_.handle(), 0, VK_WHOLE_SIZE, 0);
    vk::memoryBarrier(cmd, vk::Hazard::TransferToAny);
}

void GpuLightGrid::recordSplat(VkCommandBuffer cmd, const turtle::DeviceOrgans& organs, uint32_t firstPlant) {
    if (organs.capacity == 0) return;
    shared::LightGridPush p = push();
    p.firstPlant = firstPlant;
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
    splat_.dispatch(cmd, {organs.instances, organs.table, shapeAreas_, occupancy_, holders_, top_}, p,
                    splat_.groupsFor(organs.capacity));
}

void GpuLightGrid::recordPropagate(VkCommandBuffer cmd) {
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
    propagate_.dispatch(cmd, {occupancy_, obstacles_, directions_, light_[1 - lit_], holders_, room_[1 - lit_], top_},
                        push(), propagate_.groupsFor(spec_.voxels()));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
}

void GpuLightGrid::recordGather(VkCommandBuffer cmd, const turtle::DeviceOrgans& organs,
                                const vk::Buffer& drawnParticles, const vk::Buffer* origins,
                                const vk::Buffer* derivedParticles, uint32_t firstPlant) {
    if (organs.capacity == 0) return;
    shared::LightGridPush p = push();
    p.firstPlant = firstPlant;
    const bool elsewhere = derivedParticles && derivedParticles->handle() != drawnParticles.handle();
    p.derived = !elsewhere ? shared::kLightToDrawnOnly : origins ? shared::kLightToOrigin : shared::kLightToSameModule;
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
    gather_.dispatch(cmd,
                     {organs.instances, organs.table, light_[lit_], directions_, drawnParticles,
                      origins && elsewhere ? *origins : none_, elsewhere ? *derivedParticles : none_, room_[lit_],
                      obstacles_},
                     p, gather_.groupsFor(organs.capacity));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
}

void GpuLightGrid::recordQueries(VkCommandBuffer cmd, const turtle::GpuTurtle::ModuleStates& states, uint32_t count,
                                 const vk::Buffer* origins, const vk::Buffer& derivedSymbols,
                                 const vk::Buffer& derivedParams, uint32_t stride) {
    if (count == 0 || !states.placements) return;
    shared::LightGridPush p = push();
    p.derived = origins ? shared::kLightToOrigin : shared::kLightToSameModule;
    p.count = count;
    p.stride = stride;
    vk::memoryBarrier(cmd, vk::Hazard::AnyToAny);
    queries_.dispatch(cmd,
                      {*states.states, *states.commands, *states.plants, *states.placements, light_[lit_], directions_,
                       origins ? *origins : none_, derivedSymbols, derivedParams},
                      p, queries_.groupsFor(count));
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
}

} // namespace simeco::grow
