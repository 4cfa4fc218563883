// Headless rendering of organ instances: the instance buffer and its OrganTable stay on the device (the turtle
// kernels wrote them); indirect draw records come from a kernel reading the table, one indexed instanced draw
// per organ kind. Optional stencil shadow volumes of the sun and a toon style; the frame is read back to the
// host (see frame.h) for the image writers.
//
// A frame, in order: [shadow volumes kernel] -> draw arguments kernel -> render pass { ground and organs with
// ambient light (or all light) -> [volumes into the stencil -> organs and ground again adding the sun where the
// stencil is 0] } -> copies to host-visible buffers -> [toon outlines kernel].
#pragma once

#include <cstdint>
#include <memory>

#include "draw/bounds.h"
#include "draw/camera.h"
#include "draw/frame.h"
#include "draw/render_settings.h"

namespace simeco::vk {
class Buffer;
class Context;
} // namespace simeco::vk

namespace simeco::draw {

// The camera a frame is rendered with: settings.camera, or the default angles framed on `bounds`.
CameraView frameCamera(const Bounds& bounds, const RenderSettings& settings);

class Renderer {
public:
    // Builds the meshes, pipelines and kernels once. Throws VulkanError when the device lacks what rendering
    // needs (the attachment formats, drawIndirectFirstInstance, independentBlend, depthClamp).
    explicit Renderer(const vk::Context& context);
    ~Renderer();

    Renderer(const Renderer&) = delete;
    Renderer& operator=(const Renderer&) = delete;

    // Renders the instances (an array of OrganInstance grouped by kind) as `table` (one OrganTable) describes
    // them, framing `bounds` (the table's bounds, decoded on the host) unless settings.camera says otherwise.
    // Waits for the device and returns the frame. Throws std::invalid_argument for a zero or too large size.
    // With shadow volumes the table's counts are read back to size the volume buffer.
    Frame render(const vk::Buffer& instances, const vk::Buffer& table, const Bounds& bounds,
                 const RenderSettings& settings);

private:
    struct Resources;
    const vk::Context& context_;
    std::unique_ptr<Resources> resources_;
};

} // namespace simeco::draw
