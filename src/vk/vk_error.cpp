#include "vk/vk_error.h"

#include <fmt/format.h>

namespace simeco::vk {

std::string resultName(VkResult result) {
    switch (result) {
#define SIMECO_RESULT_CASE(name) \
    case name:                   \
        return #name;
        SIMECO_RESULT_CASE(VK_SUCCESS)
        SIMECO_RESULT_CASE(VK_NOT_READY)
        SIMECO_RESULT_CASE(VK_TIMEOUT)
        SIMECO_RESULT_CASE(VK_EVENT_SET)
        SIMECO_RESULT_CASE(VK_EVENT_RESET)
        SIMECO_RESULT_CASE(VK_INCOMPLETE)
        SIMECO_RESULT_CASE(VK_ERROR_OUT_OF_HOST_MEMORY)
        SIMECO_RESULT_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        SIMECO_RESULT_CASE(VK_ERROR_INITIALIZATION_FAILED)
        SIMECO_RESULT_CASE(VK_ERROR_DEVICE_LOST)
        SIMECO_RESULT_CASE(VK_ERROR_MEMORY_MAP_FAILED)
        SIMECO_RESULT_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        SIMECO_RESULT_CASE(VK_ERROR_EXTENSION_NOT_PRESENT)
        SIMECO_RESULT_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        SIMECO_RESULT_CASE(VK_ERROR_INCOMPATIBLE_DRIVER)
        SIMECO_RESULT_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        SIMECO_RESULT_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED)
        SIMECO_RESULT_CASE(VK_ERROR_FRAGMENTED_POOL)
        SIMECO_RESULT_CASE(VK_ERROR_UNKNOWN)
        SIMECO_RESULT_CASE(VK_ERROR_OUT_OF_POOL_MEMORY)
        SIMECO_RESULT_CASE(VK_ERROR_INVALID_EXTERNAL_HANDLE)
        SIMECO_RESULT_CASE(VK_ERROR_FRAGMENTATION)
        SIMECO_RESULT_CASE(VK_ERROR_INVALID_OPAQUE_CAPTURE_ADDRESS)
        SIMECO_RESULT_CASE(VK_PIPELINE_COMPILE_REQUIRED)
        SIMECO_RESULT_CASE(VK_ERROR_SURFACE_LOST_KHR)
        SIMECO_RESULT_CASE(VK_ERROR_NATIVE_WINDOW_IN_USE_KHR)
        SIMECO_RESULT_CASE(VK_SUBOPTIMAL_KHR)
        SIMECO_RESULT_CASE(VK_ERROR_OUT_OF_DATE_KHR)
        SIMECO_RESULT_CASE(VK_ERROR_VALIDATION_FAILED_EXT)
#undef SIMECO_RESULT_CASE
    default:
        return fmt::format("VkResult({})", static_cast<int>(result));
    }
}

namespace {

// What a user can do about a result, when there is something to say beyond its name.
std::string_view hint(VkResult result) {
    switch (result) {
    case VK_ERROR_OUT_OF_DEVICE_MEMORY:
        return "out of device memory: the scene or field is too large for this GPU; reduce it or pick a device "
               "with more memory (--device)";
    case VK_ERROR_OUT_OF_HOST_MEMORY:
        return "out of host memory";
    case VK_ERROR_DEVICE_LOST:
        return "the GPU device was lost (driver reset or a kernel ran too long)";
    case VK_ERROR_INCOMPATIBLE_DRIVER:
        return "no compatible Vulkan driver: install a Vulkan driver (mesa-vulkan-drivers provides lavapipe)";
    case VK_ERROR_LAYER_NOT_PRESENT:
        return "a requested Vulkan layer is missing";
    case VK_ERROR_EXTENSION_NOT_PRESENT:
        return "a required Vulkan extension is missing";
    default:
        return {};
    }
}

} // namespace

void throwVulkanError(VkResult result, std::string_view call, const char* file, int line) {
    std::string_view advice = hint(result);
    std::string message = advice.empty()
                              ? fmt::format("{} failed with {} ({}:{})", call, resultName(result), file, line)
                              : fmt::format("{}; {} failed with {} ({}:{})", advice, call, resultName(result),
                                            file, line);
    throw VulkanError(message, result);
}

} // namespace simeco::vk
