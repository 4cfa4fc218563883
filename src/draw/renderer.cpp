#include "draw/renderer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <deque>
#include <limits>
#include <map>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>

#include "compute/shaders.h"
#include "draw/downsample.h"
#include "draw/draw_pipelines.h"
#include "draw/organ_meshes.h"
#include "draw/render_target.h"
#include "draw/texture_array.h"
#include "render/shared/draw_layout.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/pipeline.h"
#include "vk/vk_error.h"

namespace simeco::draw {
namespace {

using shared::kOrganKinds;

constexpr VkDeviceSize kDrawCommandSize = sizeof(VkDrawIndexedIndirectCommand);
static_assert(kDrawCommandSize == 20);
// Open surfaces cast from a copy pushed this fraction of their size away from the sun (see the kernel).
constexpr float kOpenSurfaceShift = 0.02f;
// Capped shadow volumes end this fraction of the ground's half side below it.
constexpr float kVolumeCapDepth = 0.01f;
// Organs smaller on screen than these (pixels: a stem's width, a leaf's length, a sphere's or disc's diameter) are
// drawn with their kind's coarser mesh (draw_lists.comp): below them the finer mesh's extra detail is under a pixel.
constexpr float kFarStemPixels = 2.0f;
constexpr float kFarLeafPixels = 12.0f;
constexpr float kFarRoundPixels = 8.0f;
// A shadow volume's triangles over its vertices (shadow_volume.vert): the near cap, the far cap, and two per side
// from the side's near corners to its own copies of the far ones.
constexpr std::array<std::uint32_t, shared::kVolumeCorners> kVolumeFaces = {
    0, 2, 1,  3, 4,  5,       // near cap (a, c, b), far cap (a', b', c')
    0, 1, 7,  0, 7,  6,       // side a b
    1, 2, 9,  1, 9,  8,       // side b c
    2, 0, 11, 2, 11, 10};     // side c a
static_assert(*std::max_element(kVolumeFaces.begin(), kVolumeFaces.end()) + 1 == shared::kVolumeVertices);

// Line half-width of toon outlines per 600 pixels of image height, and what counts as a depth edge.
constexpr float kOutlinePixelsPer600 = 1.0f;
constexpr float kOutlineThreshold = 0.02f;

std::uint32_t styleCode(Style style) {
    switch (style) {
    case Style::Lit: return shared::kStyleLit;
    case Style::Toon: return shared::kStyleToon;
    case Style::Outline: return shared::kStyleOutline;
    case Style::PaperCut: return shared::kStylePaperCut;
    }
    return shared::kStyleLit;
}

// The styles the outline kernel draws over: ink lines, or a paper cut's cuts.
bool hasOutlines(Style style) {
    return style == Style::Outline || style == Style::PaperCut;
}

shared::vec4 vec4Of(glm::vec3 v, float w = 0.0f) {
    return {v.x, v.y, v.z, w};
}

vk::ComputePipeline kernel(const vk::Context& context, const char* name) {
    return vk::ComputePipeline(context, shaders::spirv(name), name);
}

void requireFeatures(const vk::Context& context) {
    VkPhysicalDeviceFeatures features{};
    vkGetPhysicalDeviceFeatures(context.physicalDevice(), &features);
    std::string missing;
    if (!features.drawIndirectFirstInstance) {
        missing += " drawIndirectFirstInstance";
    }
    if (!features.independentBlend) {
        missing += " independentBlend";
    }
    if (!features.depthClamp) {
        missing += " depthClamp";
    }
    if (!missing.empty()) {
        throw vk::VulkanError(
            fmt::format("the device '{}' cannot render: it lacks{}", context.deviceInfo().name, missing),
            VK_ERROR_FEATURE_NOT_PRESENT);
    }
    checkRenderFormats(context);
}

} // namespace

struct Renderer::Resources {
    Resources(const vk::Context& context, const ir::DrawAssets& assets)
        : meshes(context, assets.models), textures(context, assets.textures),
          drawArgs(kernel(context, "organs/draw_args")), drawLists(kernel(context, "organs/draw_lists")),
          shadowVolumes(kernel(context, "shadows/shadow_volumes")),
          toonOutline(kernel(context, "styles/toon_outline")),
          frameConstants(context, sizeof(shared::DrawFrame), vk::MemoryUsage::DeviceLocal,
                         VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT),
          volumeDraw(context, sizeof(shared::VolumeDraw), vk::MemoryUsage::DeviceLocal,
                     VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT),
          volumeFaces(context, sizeof(kVolumeFaces), vk::MemoryUsage::DeviceLocal, VK_BUFFER_USAGE_INDEX_BUFFER_BIT) {
        vk::uploadSpan(context, volumeFaces, std::span<const std::uint32_t>(kVolumeFaces));
        passFor(context, 1);
        drawableSamples = drawableSampleCounts(context);
    }

    // A render pass and its pipelines, for frames of a number of samples a pixel.
    struct SampledPass {
        SampledPass(const vk::Context& context, std::uint32_t samples)
            : renderPass(createRenderPass(context, samples)), pipelines(context, renderPass.get(), samples) {}
        UniqueRenderPass renderPass;
        DrawPipelines pipelines;
    };
    // Made as frames of another number of samples first need them.
    const SampledPass& passFor(const vk::Context& context, std::uint32_t samples) {
        std::unique_ptr<SampledPass>& pass = passes[samples];
        if (!pass) pass = std::make_unique<SampledPass>(context, samples);
        return *pass;
    }

    OrganMeshes meshes;
    TextureArray textures;
    std::map<std::uint32_t, std::unique_ptr<SampledPass>> passes;
    VkSampleCountFlags drawableSamples = VK_SAMPLE_COUNT_1_BIT; // drawableSampleCounts()
    vk::ComputePipeline drawArgs;
    vk::ComputePipeline drawLists;
    vk::ComputePipeline shadowVolumes;
    vk::ComputePipeline toonOutline;
    // Written by each frame's own commands (vkCmdUpdateBuffer), so frames in flight each draw with theirs.
    vk::Buffer frameConstants;
    // One of each per part of the organs, added as frames need them: the indirect draws (a draw list's each),
    // each list's count and next place, and the instances' order by list (one word an instance).
    std::vector<vk::Buffer> drawCommands, drawBuckets, drawOrders;
    vk::Buffer volumeDraw;
    vk::Buffer volumeFaces; // kVolumeFaces
    vk::Buffer volumeVertices;
    std::uint32_t volumeCapacity = 0; // vertices
    std::uint32_t volumeWindow = 0;   // vertices a binding of the volume buffer holds
    std::uint32_t volumeLimit = 0;    // vertices the frame may write (its settings' bytes, its windows)
    // The vertices a frame writes: the buffer's, within the frame's limit (a buffer grown for a frame before may
    // hold more).
    std::uint32_t volumesWritten() const { return std::min(volumeCapacity, volumeLimit); }
    std::unique_ptr<RenderTarget> target;
    // Shadow volume buffers outgrown while frames that draw with them may be in flight: each is kept until
    // kFramesInFlight more frames have been prepared, by when the caller has waited for the frames before.
    std::uint64_t framesPrepared = 0;
    std::deque<std::pair<std::uint64_t, vk::Buffer>> retired;

    // A frame's commands: the shadow volumes and the indirect draws from the instances and their table; the
    // render pass (ground and organs; with shadow volumes, the organs' ambient colour and the sun's light beside it,
    // the volumes in the stencil, then the sunlit subpass adding the sun's light where the stencil is clear);
    // the toon style's outlines over the copied target.
    void recordDrawInputs(VkCommandBuffer cmd, const std::vector<OrganPart>& parts, const FrameSetup& setup);
    void recordScene(VkCommandBuffer cmd, const RenderTarget& target, const std::vector<OrganPart>& parts,
                     const FrameSetup& setup, const SampledPass& pass);
    void recordOutlines(VkCommandBuffer cmd, const RenderTarget& target, const FrameSetup& setup);

    // Room for the shadow volumes of `triangles` casting triangles (at most settings.maxShadowVolumeBytes, in
    // windows of settings.shadowVolumeWindowBytes); returns the capacity.
    std::uint32_t volumeVerticesFor(const vk::Context& context, std::uint64_t triangles,
                                    const RenderSettings& settings);
};

CameraView frameCamera(const Bounds& bounds, const RenderSettings& settings) {
    float aspect = settings.height > 0 ? static_cast<float>(settings.width) / static_cast<float>(settings.height) : 1;
    return cameraView(settings.camera.value_or(Camera{}), bounds, aspect);
}

Renderer::Renderer(const vk::Context& context, const ir::DrawAssets& assets) : context_(context) {
    requireFeatures(context);
    resources_ = std::make_unique<Resources>(context, assets);
    if (resources_->meshes.data().leafShapeTriangles.size() > shared::kDrawMaxLeafShapes)
        throw std::invalid_argument(fmt::format("a frame draws at most {} leaf models",
                                                shared::kDrawMaxLeafShapes - shared::kSurfaceLastShape - 1));
}

Renderer::~Renderer() = default;

namespace {

// Volume vertices one storage binding holds (or the settings' smaller window), whole volumes only.
std::uint32_t volumeWindowFor(const vk::Context& context, const RenderSettings& settings) {
    std::uint64_t bytes = context.limits().maxStorageBufferRange;
    if (settings.shadowVolumeWindowBytes > 0) bytes = std::min(bytes, settings.shadowVolumeWindowBytes);
    const std::uint64_t vertices = std::max<std::uint64_t>(bytes / sizeof(shared::vec4),
                                                           shared::kVolumeVerticesPerTriangle);
    const std::uint64_t held = std::min<std::uint64_t>(vertices, std::numeric_limits<std::uint32_t>::max() / 8);
    return static_cast<std::uint32_t>(held / shared::kVolumeVerticesPerTriangle * shared::kVolumeVerticesPerTriangle);
}

} // namespace

std::uint32_t Renderer::Resources::volumeVerticesFor(const vk::Context& context, std::uint64_t triangles,
                                                     const RenderSettings& settings) {
    std::uint64_t needed = triangles * shared::kVolumeVerticesPerTriangle;
    // The shadow kernel writes the buffer through kVolumeWindows bindings of a window each: no more than they hold.
    volumeWindow = volumeWindowFor(context, settings);
    std::uint64_t affordable = std::min<std::uint64_t>(settings.maxShadowVolumeBytes / sizeof(shared::vec4),
                                                       std::uint64_t{volumeWindow} * shared::kVolumeWindows);
    std::uint64_t limit = std::min<std::uint64_t>(affordable, std::numeric_limits<std::uint32_t>::max());
    limit = std::max<std::uint64_t>(limit - limit % shared::kVolumeVerticesPerTriangle,
                                    shared::kVolumeVerticesPerTriangle);
    volumeLimit = static_cast<std::uint32_t>(limit);
    needed = std::clamp<std::uint64_t>(needed, shared::kVolumeVerticesPerTriangle, limit);
    needed -= needed % shared::kVolumeVerticesPerTriangle;
    if (needed > volumeCapacity) {
        retired.emplace_back(framesPrepared, std::move(volumeVertices));
        volumeVertices = vk::Buffer(context, needed * sizeof(shared::vec4), vk::MemoryUsage::DeviceLocal,
                                    VK_BUFFER_USAGE_VERTEX_BUFFER_BIT);
        volumeCapacity = static_cast<std::uint32_t>(needed);
    }
    return volumeCapacity;
}

std::unique_ptr<RenderTarget> Renderer::makeTarget(std::uint32_t width, std::uint32_t height,
                                                   std::uint32_t samples) {
    checkSamples(resources_->drawableSamples, samples, context_.deviceInfo().name);
    return std::make_unique<RenderTarget>(context_, resources_->passFor(context_, samples).renderPass.get(), width,
                                          height, samples);
}

RenderTarget& Renderer::offscreenTarget(std::uint32_t width, std::uint32_t height, std::uint32_t samples) {
    Resources& r = *resources_;
    if (!r.target || r.target->width() != width || r.target->height() != height || r.target->samples() != samples) {
        r.target.reset();
        r.target = makeTarget(width, height, samples);
    }
    return *r.target;
}

FrameSetup Renderer::prepare(const vk::Buffer& table, const Bounds& bounds, const RenderSettings& settings) {
    return prepare({OrganPart{nullptr, &table}}, bounds, settings);
}

FrameSetup Renderer::prepare(const std::vector<OrganPart>& parts, const Bounds& bounds,
                             const RenderSettings& settings) {
    FrameSetup setup = prepareView(bounds, settings);
    // The host reads the tables' counts (not the instances) to size the shadow volumes.
    if (settings.shadows == Shadows::Volume) {
        Resources& r = *resources_;
        for (const OrganPart& part : parts) {
            setup.partCounts.push_back(vk::downloadVector<shared::OrganTable>(context_, *part.table, 1)[0]);
            for (std::uint32_t kind = 0; kind < kOrganKinds; ++kind)
                setup.counts.count[kind] += setup.partCounts.back().count[kind];
        }
        std::uint64_t triangles = 0;
        for (std::uint32_t kind = 0; kind < kOrganKinds; ++kind)
            triangles += std::uint64_t{setup.counts.count[kind]} * r.meshes.data().castingTriangles[kind];
        r.volumeVerticesFor(context_, triangles, settings);
    }
    return setup;
}

FrameSetup Renderer::prepareWithin(std::uint32_t organs, const Bounds& bounds, const RenderSettings& settings) {
    FrameSetup setup = prepareView(bounds, settings);
    if (settings.shadows == Shadows::Volume) {
        Resources& r = *resources_;
        const OrganMeshData& data = r.meshes.data();
        std::uint64_t most = *std::max_element(data.castingTriangles.begin(), data.castingTriangles.end());
        for (std::uint32_t kind = 0; kind < kOrganKinds; ++kind) setup.counts.count[kind] = organs;
        r.volumeVerticesFor(context_, std::uint64_t{organs} * most, settings);
    }
    return setup;
}

FrameSetup Renderer::prepareView(const Bounds& bounds, const RenderSettings& settings) {
    const VkSampleCountFlags drawable = resources_->drawableSamples;
    const std::uint32_t pixelSamples = settings.samples == 0 ? defaultSamples(drawable) : settings.samples;
    checkSamples(drawable, pixelSamples, context_.deviceInfo().name);
    const VkPhysicalDeviceLimits& limits = context_.limits();
    const std::uint64_t samples = std::max(settings.antialias, 1u);
    if (settings.width == 0 || settings.height == 0 || settings.width * samples > limits.maxFramebufferWidth ||
        settings.height * samples > limits.maxFramebufferHeight) {
        throw std::invalid_argument(fmt::format("cannot render a {} x {} image: the device allows 1 to {} x {}",
                                                settings.width * samples, settings.height * samples,
                                                limits.maxFramebufferWidth, limits.maxFramebufferHeight));
    }
    float sunLength = glm::length(settings.sunDirection);
    if (!(sunLength > 0.0f) || !std::isfinite(sunLength)) {
        throw std::invalid_argument("the sun direction must be a nonzero finite vector");
    }
    Resources& r = *resources_;
    FrameSetup setup;
    setup.settings = settings;
    setup.settings.samples = pixelSamples;
    // A paper cut has no shadows: what the sun does not reach is cut out already.
    if (settings.style == Style::PaperCut) setup.settings.shadows = Shadows::None;
    setup.towardsSun = settings.sunDirection / sunLength;
    setup.camera = frameCamera(bounds, settings);
    Bounds box = framedBounds(bounds);
    float radius = 0.5f * glm::length(box.extent());

    shared::DrawFrame& frame = setup.constants;
    std::memcpy(&frame.viewProj, glm::value_ptr(setup.camera.viewProj), sizeof(frame.viewProj));
    // A pixel at unit distance: the image's height spans 2 / |P[1][1]| there (at any distance, in parallel).
    frame.cameraPosition = vec4Of(setup.camera.position,
                                  2.0f / (std::abs(setup.camera.projection[1][1]) * float(settings.height)));
    frame.cameraRight = vec4Of(setup.camera.right);
    frame.cameraUp = vec4Of(setup.camera.up);
    frame.sunDirection = vec4Of(setup.towardsSun);
    frame.sunColor = vec4Of(settings.sunColor);
    frame.skyColor = vec4Of(settings.skyColor);
    frame.groundBounce = vec4Of(settings.groundBounce);
    frame.groundColor = vec4Of(settings.groundColor);
    glm::vec3 centre = box.centre();
    frame.groundPlane = {centre.x, box.min.y, centre.z,
                         settings.groundSize > 0.0f ? 0.5f * settings.groundSize : 2.5f * radius};
    frame.background = vec4Of(settings.background);
    frame.options = {styleCode(settings.style), settings.toonBands,
                     std::bit_cast<std::uint32_t>(settings.paperCutThreshold), setup.camera.parallel ? 1u : 0u};
    ++r.framesPrepared;
    while (!r.retired.empty() && r.retired.front().first + kFramesInFlight < r.framesPrepared) r.retired.pop_front();
    return setup;
}

void Renderer::Resources::recordDrawInputs(VkCommandBuffer cmd, const std::vector<OrganPart>& parts,
                                           const FrameSetup& setup) {
    Resources& r = *this;
    const OrganMeshData& mesh = r.meshes.data();
    const shared::DrawFrame& frame = setup.constants;
    const glm::vec3 towardsSun = setup.towardsSun;
    bool shadows = setup.settings.shadows == Shadows::Volume;
    shared::DrawArgsPush args{};
    for (std::uint32_t kind = 0; kind < kOrganKinds; ++kind) {
        args.indexCount[kind] = mesh.organs[kind].indexCount;
        args.firstIndex[kind] = mesh.organs[kind].firstIndex;
        args.vertexOffset[kind] = mesh.organs[kind].vertexOffset;
        args.farIndexCount[kind] = mesh.far[kind].indexCount;
        args.farFirstIndex[kind] = mesh.far[kind].firstIndex;
        args.farVertexOffset[kind] = mesh.far[kind].vertexOffset;
    }
    args.volumeCapacity = shadows ? r.volumesWritten() : 0;
    args.leafShapes = static_cast<std::uint32_t>(mesh.leafShapeTriangles.size());
    const RenderSettings& settings = setup.settings;
    shared::DrawListsPush lists{};
    lists.shapes = args.leafShapes;
    lists.levels = settings.levelsOfDetail ? 1u : 0u;
    lists.cull = settings.cullOutsideView ? 1u : 0u;
    // In the frame's own pixels: a supersampled frame's are smaller.
    const float samples = static_cast<float>(std::max(settings.antialias, 1u));
    lists.farStemPixels = kFarStemPixels * samples;
    lists.farLeafPixels = kFarLeafPixels * samples;
    lists.farRoundPixels = kFarRoundPixels * samples;
    // Each part's organs into their draw lists: counted, laid out by draw_args.comp, then written in their places.
    // Sized by the parts' instance buffers: the counts may be the device's alone.
    auto listPass = [&](std::uint32_t pass) {
        lists.pass = pass;
        for (size_t p = 0; p < parts.size(); ++p) {
            const std::uint64_t capacity = parts[p].instances->size() / sizeof(shared::OrganInstance);
            r.drawLists.dispatch(cmd,
                                 {*parts[p].instances, *parts[p].table, r.drawBuckets[p], r.drawOrders[p],
                                  r.frameConstants},
                                 lists, r.drawLists.groupsFor(capacity));
        }
    };

    // The instances and table come from earlier submissions of other passes.
    memoryDependency(cmd, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_TRANSFER_BIT |
                         VK_PIPELINE_STAGE_VERTEX_SHADER_BIT,
                     VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT);
    vk::cmdFill(cmd, r.volumeDraw, 0);
    for (size_t p = 0; p < parts.size(); ++p) vk::cmdFill(cmd, r.drawBuckets[p], 0);
    vkCmdUpdateBuffer(cmd, r.frameConstants.handle(), 0, sizeof(frame), &frame);
    memoryDependency(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_VERTEX_SHADER_BIT |
                         VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                     VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_UNIFORM_READ_BIT);
    listPass(shared::kDrawListsCount);
    if (shadows) {
        // Where the ground receives the shadows, below everything drawn above it, the volumes end a little under
        // it: far enough that their far caps stay behind it in depth, unless the camera looks from below.
        const float groundHeight = frame.groundPlane.y;
        const float capHeight = groundHeight - kVolumeCapDepth * frame.groundPlane.w;
        const bool capped = setup.settings.ground && setup.camera.position.y > groundHeight;
        // The volume buffer's windows; those past its end bind its first (nothing is written there).
        std::array<vk::BufferRange, shared::kVolumeWindows> volumeWindows{
            r.volumeVertices, r.volumeVertices, r.volumeVertices, r.volumeVertices};
        const VkDeviceSize windowBytes = VkDeviceSize{r.volumeWindow} * sizeof(shared::vec4);
        const VkDeviceSize volumeBytes = r.volumeVertices.size();
        for (std::uint32_t w = 0; w < shared::kVolumeWindows; ++w) {
            const VkDeviceSize first = std::min(w * windowBytes, volumeBytes);
            const VkDeviceSize bytes = std::min(windowBytes, volumeBytes - first);
            volumeWindows[w] = bytes > 0 ? vk::BufferRange(r.volumeVertices, first, bytes)
                                         : vk::BufferRange(r.volumeVertices, 0, std::min(windowBytes, volumeBytes));
        }
        for (size_t p = 0; p < parts.size(); ++p) {
            // The broad shadows first (leaves, polygons, spheres, discs, then stems): volumes past the buffer's
            // room are dropped.
            for (const std::uint32_t kind : {shared::kOrganLeaf, shared::kOrganTriangle, shared::kOrganSphere,
                                             shared::kOrganDisc, shared::kOrganStem}) {
                const shared::OrganTable& counts = setup.partCounts.empty() ? setup.counts : setup.partCounts[p];
                if (counts.count[kind] == 0) {
                    continue;
                }
                const MeshRange& hull = mesh.hulls[kind];
                shared::ShadowVolumePush push{};
                push.awayFromSun = vec4Of(-towardsSun, kOpenSurfaceShift);
                push.cameraRight = frame.cameraRight;
                push.cameraUp = frame.cameraUp;
                push.kind = kind;
                push.firstIndex = hull.firstIndex;
                push.triangleCount = hull.triangleCount();
                push.vertexOffset = hull.vertexOffset;
                push.capacity = r.volumesWritten();
                push.closedHull = mesh.closedHull[kind] ? 1u : 0u;
                push.capped = capped ? 1u : 0u;
                push.capHeight = capHeight;
                push.window = r.volumeWindow;
                push.pixelAtUnitDepth = frame.cameraPosition.w;
                push.farLeafPixels = settings.levelsOfDetail ? lists.farLeafPixels : 0.0f;
                push.cull = lists.cull;
                const shared::mat4& m = frame.viewProj;
                push.viewDepth = {m.columns[0].w, m.columns[1].w, m.columns[2].w, m.columns[3].w};
                r.shadowVolumes.dispatch(cmd,
                                         {*parts[p].instances, *parts[p].table, r.meshes.vertices(), r.meshes.indices(),
                                          r.volumeDraw, volumeWindows[0], r.meshes.leafHullTriangles(),
                                          r.meshes.interiorEdges(), volumeWindows[1], volumeWindows[2],
                                          volumeWindows[3], r.meshes.leafFarShadowTriangles(), r.frameConstants},
                                         push, r.shadowVolumes.groupsFor(counts.count[kind]));
            }
        }
        memoryDependency(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                         VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    }
    memoryDependency(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    for (size_t p = 0; p < parts.size(); ++p)
        r.drawArgs.dispatch(cmd,
                            {*parts[p].table, r.drawCommands[p], r.volumeDraw, r.drawBuckets[p],
                             r.meshes.leafShapeTriangles(), r.meshes.leafFarHullTriangles()},
                            args, 1);
    memoryDependency(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT);
    listPass(shared::kDrawListsScatter);
    memoryDependency(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT,
                     VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT | VK_PIPELINE_STAGE_VERTEX_INPUT_BIT |
                         VK_PIPELINE_STAGE_VERTEX_SHADER_BIT,
                     VK_ACCESS_INDIRECT_COMMAND_READ_BIT | VK_ACCESS_VERTEX_ATTRIBUTE_READ_BIT |
                         VK_ACCESS_SHADER_READ_BIT);
}

void Renderer::Resources::recordScene(VkCommandBuffer cmd, const RenderTarget& into,
                                      const std::vector<OrganPart>& parts, const FrameSetup& setup,
                                      const SampledPass& pass) {
    Resources& r = *this;
    const OrganMeshData& mesh = r.meshes.data();
    const DrawPipelines& pipelines = pass.pipelines;
    const RenderSettings& settings = setup.settings;
    bool shadows = settings.shadows == Shadows::Volume;
    const bool multisampled = into.samples() > 1;
    const VkClearColorValue background{{settings.background.r, settings.background.g, settings.background.b, 0}};
    std::vector<VkClearValue> clears(multisampled ? std::uint32_t{kSampledAttachments} : std::uint32_t{kAttachments});
    if (multisampled) {
        clears[kColorSamples].color = background;
        clears[kIdSamples].color = {{65535.0f, 65535.0f, 65535.0f, 65535.0f}}; // kNoId's halves
        clears[kSunSamples].color = {{0.0f, 0.0f, 0.0f, 1.0f}};                 // the far plane's depth
        clears[kDepthSamples].depthStencil = {1.0f, 0};
    } else {
        clears[kColorAttachment].color = background;
        clears[kPlantAttachment].color.uint32[0] = Frame::kNoId;
        clears[kOrganAttachment].color.uint32[0] = Frame::kNoId;
        clears[kDepthAttachment].depthStencil = {1.0f, 0};
    }
    VkRenderPassBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
    begin.renderPass = pass.renderPass.get();
    begin.framebuffer = into.framebuffer();
    begin.renderArea = {{0, 0}, {into.width(), into.height()}};
    begin.clearValueCount = static_cast<std::uint32_t>(clears.size());
    begin.pClearValues = clears.data();
    vkCmdBeginRenderPass(cmd, &begin, VK_SUBPASS_CONTENTS_INLINE);
    VkViewport viewport{0, 0, static_cast<float>(into.width()), static_cast<float>(into.height()), 0, 1};
    VkRect2D scissor{{0, 0}, {into.width(), into.height()}};
    vkCmdSetViewport(cmd, 0, 1, &viewport);
    vkCmdSetScissor(cmd, 0, 1, &scissor);
    auto drawScene = [&](std::uint32_t lighting) {
        VkDeviceSize zero = 0;
        VkBuffer meshVertices = r.meshes.vertices().handle();
        vkCmdBindVertexBuffers(cmd, 0, 1, &meshVertices, &zero);
        vkCmdBindIndexBuffer(cmd, r.meshes.indices().handle(), 0, VK_INDEX_TYPE_UINT32);
        auto push = [&](std::uint32_t kind) {
            shared::DrawPush constants{kind, lighting};
            vkCmdPushConstants(cmd, pipelines.layout(), VK_SHADER_STAGE_VERTEX_BIT | VK_SHADER_STAGE_FRAGMENT_BIT, 0,
                               sizeof(constants), &constants);
        };
        const auto shapes = static_cast<std::uint32_t>(mesh.leafShapeTriangles.size());
        auto drawKind = [&](std::uint32_t kind, size_t part) {
            push(kind);
            // Leaves by shape: the kind's own list is empty.
            const std::uint32_t first = kind == shared::kOrganLeaf ? kOrganKinds : kind;
            const std::uint32_t slots = kind == shared::kOrganLeaf ? shapes : 1;
            for (std::uint32_t level : {shared::kDrawLevelNear, shared::kDrawLevelFar})
                for (std::uint32_t slot = first; slot < first + slots; ++slot)
                    vkCmdDrawIndexedIndirect(cmd, r.drawCommands[part].handle(),
                                             (slot + level * shared::kDrawSlots) * kDrawCommandSize, 1,
                                             static_cast<std::uint32_t>(kDrawCommandSize));
        };
        for (Culling culling : {Culling::Back, Culling::None}) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.base(culling));
            for (size_t part = 0; part < parts.size(); ++part) {
                pipelines.pushDescriptors(cmd, *parts[part].instances, r.frameConstants,
                                            r.textures.descriptor(), r.drawOrders[part]);
                for (std::uint32_t kind = 0; kind < kOrganKinds; ++kind) {
                    if (mesh.closedHull[kind] == (culling == Culling::Back)) {
                        drawKind(kind, part);
                    }
                }
            }
        }
        if (settings.ground) {
            push(shared::kDrawGround);
            vkCmdDrawIndexed(cmd, mesh.ground.indexCount, 1, mesh.ground.firstIndex, mesh.ground.vertexOffset, 0);
        }
    };
    if (shadows) {
        drawScene(shared::kPassAmbient);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.volume());
        VkDeviceSize zero = 0;
        VkBuffer volumes = r.volumeVertices.handle();
        vkCmdBindVertexBuffers(cmd, 0, 1, &volumes, &zero);
        vkCmdBindIndexBuffer(cmd, r.volumeFaces.handle(), 0, VK_INDEX_TYPE_UINT32);
        vkCmdDrawIndexedIndirect(cmd, r.volumeDraw.handle(), offsetof(shared::VolumeDraw, indexCount), 1,
                                 sizeof(VkDrawIndexedIndirectCommand));
    } else {
        drawScene(shared::kPassFull);
    }
    vkCmdNextSubpass(cmd, VK_SUBPASS_CONTENTS_INLINE);
    if (shadows) {
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.sunlit());
        pipelines.pushSunLight(cmd, into);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }
    if (multisampled) {
        vkCmdNextSubpass(cmd, VK_SUBPASS_CONTENTS_INLINE);
        vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipelines.resolve());
        pipelines.pushSamples(cmd, into);
        vkCmdDraw(cmd, 3, 1, 0, 0);
    }
    vkCmdEndRenderPass(cmd);
}

void Renderer::Resources::recordOutlines(VkCommandBuffer cmd, const RenderTarget& into, const FrameSetup& setup) {
    Resources& r = *this;
    const RenderSettings& settings = setup.settings;
    const CameraView& camera = setup.camera;
    shared::OutlinePush outline{};
    // A paper cut's edges are cuts: the paper shows along them.
    outline.lineColor = vec4Of(settings.style == Style::PaperCut ? settings.background : settings.outlineColor, 1.0f);
    outline.width = into.width();
    outline.height = into.height();
    // Cuts are wider than ink lines, so that the paper shows between the pieces.
    const float widthScale = settings.style == Style::PaperCut ? 2.0f : 1.0f;
    outline.radius = static_cast<std::uint32_t>(
        std::max(1.0f, std::round(widthScale * kOutlinePixelsPer600 * static_cast<float>(into.height()) / 600.0f)));
    outline.threshold = kOutlineThreshold;
    outline.nearPlane = camera.nearPlane;
    outline.farPlane = camera.farPlane;
    outline.parallel = camera.parallel ? 1u : 0u;
    std::uint64_t pixels = std::uint64_t{into.width()} * into.height();
    r.toonOutline.dispatch(cmd, {into.color(), into.depth(), into.plant(), into.outlined()}, outline,
                           r.toonOutline.groupsFor(pixels));
    memoryDependency(cmd, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT,
                     VK_ACCESS_HOST_READ_BIT);
}

void Renderer::record(VkCommandBuffer cmd, const RenderTarget& target, const vk::Buffer& instances,
                      const vk::Buffer& table, const FrameSetup& setup) {
    record(cmd, target, {OrganPart{&instances, &table}}, setup);
}

void Renderer::record(VkCommandBuffer cmd, const RenderTarget& target, const std::vector<OrganPart>& parts,
                      const FrameSetup& setup) {
    Resources& r = *resources_;
    while (r.drawCommands.size() < parts.size()) {
        r.drawCommands.emplace_back(context_, shared::kDrawBuckets * kDrawCommandSize, vk::MemoryUsage::DeviceLocal,
                                    VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
        r.drawBuckets.emplace_back(context_, 2 * shared::kDrawBuckets * sizeof(std::uint32_t),
                                   vk::MemoryUsage::DeviceLocal);
        r.drawOrders.emplace_back();
    }
    // A part's order holds a word for each instance its buffer can hold.
    for (size_t p = 0; p < parts.size(); ++p) {
        const VkDeviceSize instances = parts[p].instances->size() / sizeof(shared::OrganInstance);
        const VkDeviceSize bytes = std::max<VkDeviceSize>(instances, 1) * sizeof(std::uint32_t);
        if (r.drawOrders[p] && r.drawOrders[p].size() >= bytes) continue;
        if (r.drawOrders[p]) r.retired.emplace_back(r.framesPrepared, std::move(r.drawOrders[p]));
        r.drawOrders[p] = vk::Buffer(context_, bytes, vk::MemoryUsage::DeviceLocal);
    }
    r.recordDrawInputs(cmd, parts, setup);
    r.recordScene(cmd, target, parts, setup, r.passFor(context_, target.samples()));
    target.cmdCopyToBuffers(cmd);
    memoryDependency(cmd, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_ACCESS_TRANSFER_WRITE_BIT,
                     VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT | VK_PIPELINE_STAGE_HOST_BIT,
                     VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_HOST_READ_BIT);
    if (hasOutlines(setup.settings.style)) r.recordOutlines(cmd, target, setup);
}

DrawnOrgans Renderer::drawnOrgans(size_t part) const {
    const Resources& r = *resources_;
    DrawnOrgans drawn;
    if (part >= r.drawBuckets.size()) return drawn;
    const std::vector<std::uint32_t> counts =
        vk::downloadVector<std::uint32_t>(context_, r.drawBuckets[part], shared::kDrawBuckets);
    for (std::uint32_t bucket = 0; bucket < shared::kDrawBuckets; ++bucket) {
        const std::uint32_t slot = bucket % shared::kDrawSlots;
        const std::uint32_t kind = slot < kOrganKinds ? slot : shared::kOrganLeaf;
        (bucket < shared::kDrawSlots ? drawn.near : drawn.far)[kind] += counts[bucket];
    }
    const shared::VolumeDraw volumes = vk::downloadVector<shared::VolumeDraw>(context_, r.volumeDraw, 1)[0];
    drawn.shadowVolumes = volumes.instanceCount;
    return drawn;
}

const vk::Buffer& Renderer::finalColor(const RenderTarget& target, const FrameSetup& setup) {
    return hasOutlines(setup.settings.style) ? target.outlined() : target.color();
}

Frame Renderer::readBack(const RenderTarget& target, const FrameSetup& setup) const {
    Frame result;
    result.width = target.width();
    result.height = target.height();
    std::size_t pixels = result.pixelCount();
    const vk::Buffer& color = finalColor(target, setup);
    result.rgba.resize(4 * pixels);
    std::memcpy(result.rgba.data(), color.mapped(), result.rgba.size() * sizeof(float));
    result.plant.resize(pixels);
    std::memcpy(result.plant.data(), target.plant().mapped(), pixels * sizeof(std::uint32_t));
    result.organ.resize(pixels);
    std::memcpy(result.organ.data(), target.organ().mapped(), pixels * sizeof(std::uint32_t));
    // Depth buffer values back to distances along the view axis (the inverse of the [0, 1] projection).
    result.depth.resize(pixels);
    const auto* depth = reinterpret_cast<const float*>(target.depth().mapped());
    float n = setup.camera.nearPlane;
    float f = setup.camera.farPlane;
    for (std::size_t i = 0; i < pixels; ++i) {
        float d = depth[i];
        if (d >= 1.0f) result.depth[i] = std::numeric_limits<float>::infinity();
        else result.depth[i] = setup.camera.parallel ? n + d * (f - n) : f * n / (f - d * (f - n));
    }
    return result;
}

Frame Renderer::render(const vk::Buffer& instances, const vk::Buffer& table, const Bounds& bounds,
                       const RenderSettings& settings) {
    return render({OrganPart{&instances, &table}}, bounds, settings);
}

Frame Renderer::render(const std::vector<OrganPart>& parts, const Bounds& bounds, const RenderSettings& settings) {
    const std::uint32_t samples = std::max(settings.antialias, 1u);
    FrameSetup setup = prepare(parts, bounds, settings);
    const RenderTarget& target =
        offscreenTarget(settings.width * samples, settings.height * samples, setup.settings.samples);
    context_.submitAndWait([&](VkCommandBuffer cmd) { record(cmd, target, parts, setup); });
    return samples > 1 ? downsample(readBack(target, setup), samples) : readBack(target, setup);
}

} // namespace simeco::draw
