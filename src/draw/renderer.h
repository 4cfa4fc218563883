// Headless rendering of organ instances: the instance buffer and its OrganTable stay on the device (the turtle
// kernels wrote them); indirect draw records come from a kernel reading the table, one indexed instanced draw
// per organ kind. Optional stencil shadow volumes of the sun and a toon style; the frame is read back to the
// host (see frame.h) for the image writers.
//
// A frame, in order: [shadow volumes kernel] -> draw arguments kernel -> render pass { ground and organs with
// ambient light (or all light) -> [volumes into the stencil -> the sun's light added where the stencil is 0] ->
// [with several samples a pixel, the pixels resolved from their samples] } -> copies to host-visible buffers ->
// [toon outlines kernel].
// Frames may be in flight (kFramesInFlight): nothing the host writes for a frame is shared with the next.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/vec3.hpp>
#include <vulkan/vulkan.h>

#include "draw/bounds.h"
#include "draw/camera.h"
#include "draw/frame.h"
#include "draw/render_settings.h"
#include "draw/render_target.h"
#include "ir/draw_assets.h"
#include "render/shared/draw_layout.h"

namespace simeco::vk {
class Buffer;
class Context;
} // namespace simeco::vk

namespace simeco::draw {

// The organs a frame draws come in parts, each an instance buffer and its OrganTable: a field whose organs need
// more than one storage binding holds (maxStorageBufferRange) is drawn from several.
struct OrganPart {
    const vk::Buffer* instances = nullptr;
    const vk::Buffer* table = nullptr;
};

// What the host prepared for a frame and the device's recording reads.
struct FrameSetup {
    RenderSettings settings;
    CameraView camera;
    glm::vec3 towardsSun{0, 1, 0};
    shared::DrawFrame constants{};
    // The tables' counts, read back only for shadow volumes: every part's together, and each part's (empty when
    // prepareWithin gave room for any count: then each part dispatches for `counts`).
    shared::OrganTable counts{};
    std::vector<shared::OrganTable> partCounts;
};

// The organs of a part a frame drew, by kind (kOrgan*), with the finer meshes and the coarser ones; those in neither
// were outside the view (RenderSettings::levelsOfDetail, cullOutsideView).
struct DrawnOrgans {
    std::array<std::uint32_t, shared::kOrganKinds> near{}, far{};
    std::uint32_t shadowVolumes = 0; // the frame's, of every part (0 without shadow volumes)
};

// The camera a frame is rendered with: settings.camera, or the default angles framed on `bounds`.
CameraView frameCamera(const Bounds& bounds, const RenderSettings& settings);

// Frames a caller may have in flight at once, each drawing into a target of its own: prepare() keeps what a
// frame before may still use until this many more frames are prepared.
inline constexpr std::uint64_t kFramesInFlight = 2;

class Renderer {
public:
    // Builds the meshes, pipelines and kernels once. Throws VulkanError when the device lacks what rendering
    // needs (the attachment formats, drawIndirectFirstInstance, independentBlend, depthClamp).
    // `assets`: the models, surface shapes after the built-in ones (draw::buildOrganMeshes), and the textures
    // (draw::TextureArray) a scene's organs are drawn with.
    explicit Renderer(const vk::Context& context, const ir::DrawAssets& assets = {});
    ~Renderer();

    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders the instances (an array of OrganInstance grouped by kind) as `table` (one OrganTable) describes
    // them, framing `bounds` (the table's bounds, decoded on the host) unless settings.camera says otherwise.
    // Waits for the device and returns the frame: prepare(), record() into the offscreen target, readBack().
    // Throws std::invalid_argument for a zero or too large size.
    Frame render(const vk::Buffer& instances, const vk::Buffer& table, const Bounds& bounds,
                 const RenderSettings& settings);
    // The same for organs in parts, drawn together.
    Frame render(const std::vector<OrganPart>& parts, const Bounds& bounds, const RenderSettings& settings);

    // The host's part of a frame: the camera and per-frame constants; with shadow volumes the table's counts are
    // read back to size the volume buffer. Throws std::invalid_argument for a zero or too large size.
    FrameSetup prepare(const vk::Buffer& table, const Bounds& bounds, const RenderSettings& settings);
    FrameSetup prepare(const std::vector<OrganPart>& parts, const Bounds& bounds, const RenderSettings& settings);
    // The same for organs only the device counts yet (a tick whose derivation and turtle are recorded before the
    // frame in its submission): nothing is read back, the shadow volumes get room for `organs` organs of any
    // kind (at most settings.maxShadowVolumeBytes).
    FrameSetup prepareWithin(std::uint32_t organs, const Bounds& bounds, const RenderSettings& settings);
    // Records the frame into `cmd`, drawing into `target` (one of this renderer's render pass), with explicit
    // barriers before (the instances and table may come from passes recorded earlier) and after (the target's
    // copies are ready for the host). The caller submits; the frame's constants travel in `cmd`, so up to
    // kFramesInFlight frames may be in flight, each into its own target (makeTarget).
    void record(VkCommandBuffer cmd, const RenderTarget& target, const vk::Buffer& instances, const vk::Buffer& table,
                const FrameSetup& setup);
    void record(VkCommandBuffer cmd, const RenderTarget& target, const std::vector<OrganPart>& parts,
                const FrameSetup& setup);
    // The buffer of `target` that holds the frame's last colours (linear RGBA floats, rows from the top), for
    // passes recorded after record(): the outlines' output in the styles that draw them.
    static const vk::Buffer& finalColor(const RenderTarget& target, const FrameSetup& setup);
    // The frame `record` drew into `target`, once its submission has completed.
    Frame readBack(const RenderTarget& target, const FrameSetup& setup) const;
    // What the last frame recorded drew of part `part`, once its submission has completed (reads the device).
    DrawnOrgans drawnOrgans(size_t part = 0) const;
    // The offscreen target of the given size and samples a pixel, made on first use and kept while they stay.
    // Throws std::invalid_argument where the device cannot draw that many samples (draw::checkSamples).
    RenderTarget& offscreenTarget(std::uint32_t width, std::uint32_t height, std::uint32_t samples = 1);
    // Another offscreen target, for a frame in flight beside the one drawing into the first.
    std::unique_ptr<RenderTarget> makeTarget(std::uint32_t width, std::uint32_t height, std::uint32_t samples = 1);

private:
    // The camera and constants, after checking the size and the sun.
    FrameSetup prepareView(const Bounds& bounds, const RenderSettings& settings);

    struct Resources;
    const vk::Context& context_;
    std::unique_ptr<Resources> resources_;
};

} // namespace simeco::draw
