#include "vk/device_info.h"

#include <algorithm>
#include <cctype>
#include <charconv>

#include <fmt/format.h>

#include "vk/instance.h"
#include "vk/vk_error.h"

namespace simeco::vk {
namespace {

constexpr VkSubgroupFeatureFlags kRequiredSubgroupOperations =
    VK_SUBGROUP_FEATURE_BASIC_BIT | VK_SUBGROUP_FEATURE_ARITHMETIC_BIT;

bool hasDeviceExtension(VkPhysicalDevice device, std::string_view name) {
    std::uint32_t count = 0;
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, nullptr));
    std::vector<VkExtensionProperties> extensions(count);
    VK_CHECK(vkEnumerateDeviceExtensionProperties(device, nullptr, &count, extensions.data()));
    return std::any_of(extensions.begin(), extensions.end(),
                       [&](const VkExtensionProperties& e) { return name == e.extensionName; });
}

bool hasComputeQueue(VkPhysicalDevice device) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    return std::any_of(families.begin(), families.end(),
                       [](const VkQueueFamilyProperties& f) { return (f.queueFlags & VK_QUEUE_COMPUTE_BIT) != 0; });
}

// `keepsNonFinite`: shaderSignedZeroInfNanPreserveFloat64, which the derivation kernels ask for so that their
// double arithmetic keeps infinities and NaN as the CPU reference does (codegen::kernelPrelude).
std::string whyUnsuitable(const PhysicalDeviceInfo& info, VkShaderStageFlags subgroupStages, bool keepsNonFinite) {
    if (info.apiVersion < Instance::kApiVersion) {
        return "needs Vulkan 1.2";
    }
    if (!hasComputeQueue(info.handle)) {
        return "no compute queue";
    }
    if ((subgroupStages & VK_SHADER_STAGE_COMPUTE_BIT) == 0 ||
        (info.subgroupOperations & kRequiredSubgroupOperations) != kRequiredSubgroupOperations) {
        return "no subgroup arithmetic in compute shaders";
    }
    if (!hasDeviceExtension(info.handle, VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME)) {
        return "no VK_KHR_push_descriptor";
    }
    if (!keepsNonFinite) {
        return "double arithmetic does not keep infinities and NaN";
    }
    return {};
}

int typeRank(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return 3;
    default:
        return 4;
    }
}

std::string lower(std::string_view text) {
    std::string result(text);
    std::transform(result.begin(), result.end(), result.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return result;
}

std::string describe(const std::vector<PhysicalDeviceInfo>& devices) {
    std::string list;
    for (const PhysicalDeviceInfo& d : devices) {
        list += fmt::format("\n  {}: {}{}", d.index, d.name, d.suitable() ? "" : " (unsuitable: " + d.unsuitableReason + ")");
    }
    return list.empty() ? " none" : list;
}

} // namespace

std::string_view deviceTypeName(VkPhysicalDeviceType type) {
    switch (type) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU:
        return "discrete GPU";
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU:
        return "integrated GPU";
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU:
        return "virtual GPU";
    case VK_PHYSICAL_DEVICE_TYPE_CPU:
        return "CPU";
    default:
        return "other";
    }
}

std::string versionString(std::uint32_t version) {
    return fmt::format("{}.{}.{}", VK_API_VERSION_MAJOR(version), VK_API_VERSION_MINOR(version),
                       VK_API_VERSION_PATCH(version));
}

std::vector<PhysicalDeviceInfo> listPhysicalDevices(VkInstance instance) {
    std::uint32_t count = 0;
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, nullptr));
    std::vector<VkPhysicalDevice> handles(count);
    VK_CHECK(vkEnumeratePhysicalDevices(instance, &count, handles.data()));

    std::vector<PhysicalDeviceInfo> devices;
    for (std::uint32_t i = 0; i < count; ++i) {
        VkPhysicalDeviceSubgroupProperties subgroup{};
        subgroup.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SUBGROUP_PROPERTIES;
        VkPhysicalDeviceDriverProperties driver{};
        driver.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES;
        VkPhysicalDeviceFloatControlsProperties floats{};
        floats.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FLOAT_CONTROLS_PROPERTIES;
        VkPhysicalDeviceProperties2 properties{};
        properties.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2;
        VkPhysicalDeviceProperties basic{};
        vkGetPhysicalDeviceProperties(handles[i], &basic);
        // The chained structures are Vulkan 1.1/1.2 core; on an older device only the basic properties are valid.
        bool modern = basic.apiVersion >= VK_API_VERSION_1_2;
        if (modern) {
            properties.pNext = &subgroup;
            subgroup.pNext = &driver;
            driver.pNext = &floats;
            vkGetPhysicalDeviceProperties2(handles[i], &properties);
        } else {
            properties.properties = basic;
        }

        PhysicalDeviceInfo info;
        info.index = i;
        info.handle = handles[i];
        info.name = properties.properties.deviceName;
        info.type = properties.properties.deviceType;
        info.apiVersion = properties.properties.apiVersion;
        if (modern) {
            info.driverName = driver.driverName;
            info.driverInfo = driver.driverInfo;
            info.subgroupSize = subgroup.subgroupSize;
            info.subgroupOperations = subgroup.supportedOperations;
        }
        VkPhysicalDeviceMemoryProperties memory{};
        vkGetPhysicalDeviceMemoryProperties(handles[i], &memory);
        for (std::uint32_t h = 0; h < memory.memoryHeapCount; ++h) {
            info.heaps.push_back({memory.memoryHeaps[h].size,
                                  (memory.memoryHeaps[h].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) != 0});
        }
        info.unsuitableReason =
            whyUnsuitable(info, modern ? subgroup.supportedStages : 0,
                          modern && floats.shaderSignedZeroInfNanPreserveFloat64);
        devices.push_back(std::move(info));
    }
    return devices;
}

std::size_t selectPhysicalDevice(const std::vector<PhysicalDeviceInfo>& devices, std::string_view selector) {
    if (selector.empty()) {
        const PhysicalDeviceInfo* best = nullptr;
        for (const PhysicalDeviceInfo& d : devices) {
            if (d.suitable() && (best == nullptr || typeRank(d.type) < typeRank(best->type))) {
                best = &d;
            }
        }
        if (best == nullptr) {
            throw VulkanError("no Vulkan device can run simeco; devices:" + describe(devices) +
                                  "\n(without a GPU, install mesa-vulkan-drivers for lavapipe)",
                              VK_ERROR_INCOMPATIBLE_DRIVER);
        }
        return static_cast<std::size_t>(best - devices.data());
    }

    std::size_t index = 0;
    const char* end = selector.data() + selector.size();
    auto [parsedEnd, error] = std::from_chars(selector.data(), end, index);
    bool isIndex = error == std::errc() && parsedEnd == end;
    const PhysicalDeviceInfo* match = nullptr;
    for (const PhysicalDeviceInfo& d : devices) {
        bool matches = isIndex ? d.index == index : lower(d.name).find(lower(selector)) != std::string::npos;
        if (matches) {
            match = &d;
            break;
        }
    }
    if (match == nullptr) {
        throw VulkanError(fmt::format("no Vulkan device matches --device '{}'; devices:{}", selector, describe(devices)),
                          VK_ERROR_INITIALIZATION_FAILED);
    }
    if (!match->suitable()) {
        throw VulkanError(fmt::format("device {} ({}) cannot run simeco: {}", match->index, match->name,
                                      match->unsuitableReason),
                          VK_ERROR_FEATURE_NOT_PRESENT);
    }
    return static_cast<std::size_t>(match - devices.data());
}

} // namespace simeco::vk
