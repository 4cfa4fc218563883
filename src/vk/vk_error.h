// Vulkan failures as exceptions: VK_CHECK turns a failing VkResult into a VulkanError naming the call.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

#include <vulkan/vulkan.h>

namespace simeco::vk {

// A Vulkan call failed or the device cannot do what was asked. Caught at the command level (exit code 1).
class VulkanError : public std::runtime_error {
public:
    explicit VulkanError(const std::string& message, VkResult result = VK_ERROR_UNKNOWN)
        : std::runtime_error(message), result_(result) {}

    VkResult result() const { return result_; }

private:
    VkResult result_;
};

// "VK_ERROR_OUT_OF_DEVICE_MEMORY" for VK_ERROR_OUT_OF_DEVICE_MEMORY, the number for unknown codes.
std::string resultName(VkResult result);

// Throws a VulkanError for a failed `call`; out-of-memory and device-lost results get a message a user can act on.
[[noreturn]] void throwVulkanError(VkResult result, std::string_view call, const char* file, int line);

} // namespace simeco::vk

// Evaluates `call` exactly once, in every build type, and throws if it did not return VK_SUCCESS.
// Calls that legitimately return other success codes (VK_TIMEOUT, VK_INCOMPLETE) check them by hand.
#define VK_CHECK(call)                                                              \
    do {                                                                            \
        VkResult vkCheckResult_ = (call);                                           \
        if (vkCheckResult_ != VK_SUCCESS) {                                         \
            ::simeco::vk::throwVulkanError(vkCheckResult_, #call, __FILE__, __LINE__); \
        }                                                                           \
    } while (false)
