// Dear ImGui over the window's image: the panel, the figures and the plot drawn on top of the frame the presenter
// put there (a render pass that loads the image and leaves it ready to present).
#pragma once

#include <cstdint>
#include <vector>

#include <vulkan/vulkan.h>

#include "draw/vk_objects.h"
#include "vk/handle.h"

struct GLFWwindow;

namespace simeco::vk {
class Context;
}

namespace simeco::view {

class Swapchain;

class Overlay {
public:
    // Installs ImGui's GLFW callbacks on `window` (they pass input on to callbacks installed before).
    Overlay(const vk::Context& context, GLFWwindow* window, const Swapchain& swapchain);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    // After the swapchain was made again.
    void resize(const Swapchain& swapchain);
    // Begins ImGui's frame: the panel's widgets are made between this and record().
    void begin();
    // Ends the frame and draws it onto swapchain image `image` (in TRANSFER_DST_OPTIMAL; left PRESENT_SRC).
    void record(VkCommandBuffer cmd, std::uint32_t image);
    // Ends the frame begun without drawing it (the window had no image to draw into).
    void cancel();
    // Whether ImGui wants the mouse or the keyboard (the camera leaves them alone then).
    bool wantsMouse() const;
    bool wantsKeyboard() const;

private:
    void makeFramebuffers(const Swapchain& swapchain);

    using UniqueDescriptorPool = vk::DeviceHandle<VkDescriptorPool, vkDestroyDescriptorPool>;
    const vk::Context& context_;
    UniqueDescriptorPool pool_;
    draw::UniqueRenderPass renderPass_;
    std::vector<draw::UniqueFramebuffer> framebuffers_;
    VkExtent2D extent_{};
};

} // namespace simeco::view
