#include "view/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <fmt/format.h>

#include "vk/vk_error.h"

namespace simeco::view {
namespace {

// GLFW keeps its last error; the message says why a window could not open.
std::string glfwMessage() {
    const char* description = nullptr;
    glfwGetError(&description);
    return description ? description : "no reason given";
}

} // namespace

Window::Window(std::uint32_t width, std::uint32_t height, const std::string& title) {
    if (glfwInit() != GLFW_TRUE)
        throw WindowError(fmt::format("cannot open a window: {} (no display? run under xvfb-run for a virtual one)",
                                      glfwMessage()));
    if (glfwVulkanSupported() != GLFW_TRUE) {
        glfwTerminate();
        throw WindowError("the window system has no Vulkan loader or surface extension");
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    window_ = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
    if (!window_) {
        const std::string why = glfwMessage();
        glfwTerminate();
        throw WindowError(fmt::format("cannot open a window: {}", why));
    }
}

Window::~Window() {
    glfwDestroyWindow(window_);
    glfwTerminate();
}

bool Window::closing() const { return glfwWindowShouldClose(window_) == GLFW_TRUE; }

VkExtent2D Window::framebufferSize() const {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_, &width, &height);
    return {std::uint32_t(std::max(width, 0)), std::uint32_t(std::max(height, 0))};
}

void Window::setTitle(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

std::vector<std::string> Window::instanceExtensions() {
    std::uint32_t count = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&count);
    return std::vector<std::string>(names, names + count);
}

bool Window::presentsFrom(VkInstance instance, VkPhysicalDevice device, std::uint32_t queueFamily) {
    return glfwGetPhysicalDevicePresentationSupport(instance, device, queueFamily) == GLFW_TRUE;
}

Surface::Surface(VkInstance instance, const Window& window) : instance_(instance) {
    VK_CHECK(glfwCreateWindowSurface(instance, window.handle(), nullptr, &surface_));
}

Surface::~Surface() { vkDestroySurfaceKHR(instance_, surface_, nullptr); }

} // namespace simeco::view
