// What simeco needs to know about each physical device, and which one it picks.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <vulkan/vulkan.h>

namespace simeco::vk {

struct MemoryHeapInfo {
    VkDeviceSize size = 0;
    bool deviceLocal = false;
};

struct PhysicalDeviceInfo {
    std::uint32_t index = 0;  // position in vkEnumeratePhysicalDevices order, as `--device N` names it
    VkPhysicalDevice handle = VK_NULL_HANDLE;
    std::string name;
    VkPhysicalDeviceType type = VK_PHYSICAL_DEVICE_TYPE_OTHER;
    std::string driverName;
    std::string driverInfo;
    std::uint32_t apiVersion = 0;
    std::vector<MemoryHeapInfo> heaps;
    std::uint32_t subgroupSize = 0;
    VkSubgroupFeatureFlags subgroupOperations = 0;
    // Empty when simeco can run on the device; otherwise why not (shown by `simeco devices`).
    std::string unsuitableReason;

    bool suitable() const { return unsuitableReason.empty(); }
};

// "discrete GPU", "integrated GPU", "virtual GPU", "CPU", "other".
std::string_view deviceTypeName(VkPhysicalDeviceType type);

// "1.3.230".
std::string versionString(std::uint32_t version);

std::vector<PhysicalDeviceInfo> listPhysicalDevices(VkInstance instance);

// The device to use: with an empty `selector`, the best suitable one (discrete GPU, then integrated, virtual,
// CPU such as lavapipe); otherwise the device whose index equals `selector` or whose name contains it
// (case-insensitive). Throws VulkanError when nothing matches or the match cannot run simeco.
std::size_t selectPhysicalDevice(const std::vector<PhysicalDeviceInfo>& devices, std::string_view selector);

} // namespace simeco::vk
