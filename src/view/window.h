// The viewer's window: GLFW with no client API (Vulkan draws into it), and the Vulkan surface on it.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

struct GLFWwindow;

namespace simeco::view {

// No display to open a window on, or a window system without Vulkan.
class WindowError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class Window {
public:
    // Throws WindowError where no window can open (no DISPLAY: run under xvfb-run for a virtual one).
    Window(std::uint32_t width, std::uint32_t height, const std::string& title);
    ~Window();
    Window(const Window&) = delete;
    Window& operator=(const Window&) = delete;

    GLFWwindow* handle() const { return window_; }
    bool closing() const;
    // The size in pixels of what the window shows; zero while it is minimised.
    VkExtent2D framebufferSize() const;
    void setTitle(const std::string& title);

    // What a Vulkan instance needs to make surfaces for this window system, and whether a device's queue family
    // can present to it (vk::ContextOptions).
    static std::vector<std::string> instanceExtensions();
    static bool presentsFrom(VkInstance instance, VkPhysicalDevice device, std::uint32_t queueFamily);

private:
    GLFWwindow* window_ = nullptr;
};

// The window's surface, destroyed before the instance it was made with.
class Surface {
public:
    Surface(VkInstance instance, const Window& window);
    ~Surface();
    Surface(const Surface&) = delete;
    Surface& operator=(const Surface&) = delete;

    VkSurfaceKHR get() const { return surface_; }

private:
    VkInstance instance_;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
};

} // namespace simeco::view
