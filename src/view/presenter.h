// A rendered frame into a window's image: the frame's final colours (linear floats in a buffer) mapped to bytes as
// the PNG writer maps them (render/present/display_bytes.comp), copied into an image of the frame's size and
// blitted, scaled, onto the swapchain image. The swapchain image ends in TRANSFER_DST_OPTIMAL for the overlay.
#pragma once

#include <cstdint>

#include <vulkan/vulkan.h>

#include "draw/vk_objects.h"
#include "vk/buffer.h"
#include "vk/pipeline.h"

namespace simeco::view {

class Swapchain;

class Presenter {
public:
    explicit Presenter(const vk::Context& context);

    // Records the frame `color` (width x height pixels) onto the swapchain's image `image`.
    void record(VkCommandBuffer cmd, const vk::Buffer& color, std::uint32_t width, std::uint32_t height,
                const Swapchain& swapchain, std::uint32_t image);

private:
    const vk::Context& context_;
    vk::ComputePipeline toBytes_;
    vk::Buffer bytes_;
    draw::DeviceImage staging_;
    VkExtent2D stagingSize_{};
};

} // namespace simeco::view
