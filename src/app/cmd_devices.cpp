// `simeco devices`: the Vulkan devices simeco can see, and the one it would pick without --device.
#include <cstdio>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/error_report.h"
#include "vk/device_info.h"
#include "vk/instance.h"
#include "vk/vk_error.h"

namespace simeco::app {
namespace {

struct DevicesOptions {
    bool json = false;
    std::string device;
};

std::string subgroupOperationNames(VkSubgroupFeatureFlags flags) {
    static constexpr std::pair<VkSubgroupFeatureFlagBits, const char*> kNames[] = {
        {VK_SUBGROUP_FEATURE_BASIC_BIT, "basic"},
        {VK_SUBGROUP_FEATURE_VOTE_BIT, "vote"},
        {VK_SUBGROUP_FEATURE_ARITHMETIC_BIT, "arithmetic"},
        {VK_SUBGROUP_FEATURE_BALLOT_BIT, "ballot"},
        {VK_SUBGROUP_FEATURE_SHUFFLE_BIT, "shuffle"},
        {VK_SUBGROUP_FEATURE_SHUFFLE_RELATIVE_BIT, "shuffle-relative"},
        {VK_SUBGROUP_FEATURE_CLUSTERED_BIT, "clustered"},
        {VK_SUBGROUP_FEATURE_QUAD_BIT, "quad"},
    };
    std::string names;
    for (const auto& [bit, name] : kNames) {
        if ((flags & bit) != 0) {
            names += names.empty() ? name : std::string(",") + name;
        }
    }
    return names;
}

nlohmann::json toJson(const vk::PhysicalDeviceInfo& d, bool selected) {
    nlohmann::json heaps = nlohmann::json::array();
    for (const vk::MemoryHeapInfo& heap : d.heaps) {
        heaps.push_back({{"bytes", heap.size}, {"device_local", heap.deviceLocal}});
    }
    nlohmann::json entry = {
        {"index", d.index},
        {"name", d.name},
        {"type", std::string(vk::deviceTypeName(d.type))},
        {"driver", d.driverName},
        {"driver_info", d.driverInfo},
        {"vulkan", vk::versionString(d.apiVersion)},
        {"memory_heaps", heaps},
        {"subgroup_size", d.subgroupSize},
        {"subgroup_operations", subgroupOperationNames(d.subgroupOperations)},
        {"suitable", d.suitable()},
        {"selected", selected},
    };
    if (!d.suitable()) {
        entry["unsuitable_reason"] = d.unsuitableReason;
    }
    return entry;
}

void printText(const std::vector<vk::PhysicalDeviceInfo>& devices, std::size_t selected) {
    for (std::size_t i = 0; i < devices.size(); ++i) {
        const vk::PhysicalDeviceInfo& d = devices[i];
        std::string heaps;
        for (const vk::MemoryHeapInfo& heap : d.heaps) {
            heaps += fmt::format("{}{:.1f} GiB{}", heaps.empty() ? "" : ", ",
                                 static_cast<double>(heap.size) / (1024.0 * 1024.0 * 1024.0),
                                 heap.deviceLocal ? " device-local" : "");
        }
        std::fputs(fmt::format("{} {}: {} ({})\n", i == selected ? "*" : " ", d.index, d.name,
                               vk::deviceTypeName(d.type))
                       .c_str(),
                   stdout);
        std::fputs(fmt::format("    driver {} ({}), Vulkan {}\n", d.driverName, d.driverInfo,
                               vk::versionString(d.apiVersion))
                       .c_str(),
                   stdout);
        std::fputs(fmt::format("    memory heaps: {}\n", heaps).c_str(), stdout);
        std::fputs(fmt::format("    subgroup size {} ({})\n", d.subgroupSize, subgroupOperationNames(d.subgroupOperations))
                       .c_str(),
                   stdout);
        if (!d.suitable()) {
            std::fputs(fmt::format("    not usable: {}\n", d.unsuitableReason).c_str(), stdout);
        }
    }
    if (selected < devices.size()) {
        std::fputs("(* = the device simeco uses with these options)\n", stdout);
    }
}

void runDevices(const DevicesOptions& options) {
    vk::Instance instance(vk::validationRequestedByEnvironment());
    std::vector<vk::PhysicalDeviceInfo> devices = vk::listPhysicalDevices(instance.get());
    // Listing must work even when nothing is usable, so a failed selection only leaves no mark.
    std::size_t selected = devices.size();
    std::string selectionError;
    try {
        selected = vk::selectPhysicalDevice(devices, options.device);
    } catch (const vk::VulkanError& e) {
        selectionError = e.what();
    }

    if (options.json) {
        nlohmann::json list = nlohmann::json::array();
        for (std::size_t i = 0; i < devices.size(); ++i) {
            list.push_back(toJson(devices[i], i == selected));
        }
        nlohmann::json report = {{"devices", list}};
        if (!selectionError.empty()) {
            report["selection_error"] = selectionError;
        }
        std::fputs((report.dump(2) + "\n").c_str(), stdout);
    } else {
        printText(devices, selected);
    }
    if (!selectionError.empty()) {
        throw vk::VulkanError(selectionError);
    }
}

} // namespace

void registerDevicesCommand(CLI::App& app, CommandContext& ctx) {
    auto options = std::make_shared<DevicesOptions>();
    CLI::App* command = app.add_subcommand("devices", "List the Vulkan devices and mark the one simeco would use");
    command->add_flag("--json", options->json, "Print machine-readable JSON");
    command->add_option("--device", options->device, "Mark this device (index or name substring) instead of the default");
    command->callback([options, &ctx] { ctx.exitCode = runReportingErrors([&] { runDevices(*options); }); });
}

} // namespace simeco::app
