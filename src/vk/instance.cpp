#include "vk/instance.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string_view>
#include <utility>

#include "vk/vk_error.h"

namespace simeco::vk {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

VKAPI_ATTR VkBool32 VKAPI_CALL onValidationMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                                   VkDebugUtilsMessageTypeFlagsEXT /*types*/,
                                                   const VkDebugUtilsMessengerCallbackDataEXT* data,
                                                   void* userData) {
    const char* level = (severity & VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT) ? "error" : "warning";
    std::string message = data->pMessage != nullptr ? data->pMessage : "(no message)";
    std::fprintf(stderr, "simeco: vulkan validation %s: %s\n", level, message.c_str());
    static_cast<ValidationLog*>(userData)->add(std::move(message));
    // Returning VK_FALSE lets the call proceed as the application made it, as the spec asks of applications.
    return VK_FALSE;
}

VkDebugUtilsMessengerCreateInfoEXT messengerInfo(ValidationLog* log) {
    VkDebugUtilsMessengerCreateInfoEXT info{};
    info.sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT;
    info.messageSeverity =
        VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT;
    info.messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT | VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT;
    info.pfnUserCallback = onValidationMessage;
    info.pUserData = log;
    return info;
}

bool layerAvailable(std::string_view name) {
    std::uint32_t count = 0;
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, nullptr));
    std::vector<VkLayerProperties> layers(count);
    VK_CHECK(vkEnumerateInstanceLayerProperties(&count, layers.data()));
    for (const VkLayerProperties& layer : layers) {
        if (name == layer.layerName) {
            return true;
        }
    }
    return false;
}

} // namespace

bool validationRequestedByEnvironment() {
    const char* value = std::getenv("SIMECO_VALIDATION");
    return value != nullptr && std::strcmp(value, "0") != 0 && value[0] != '\0';
}

void ValidationLog::add(std::string message) {
    std::lock_guard lock(mutex_);
    messages_.push_back(std::move(message));
}

std::size_t ValidationLog::count() const {
    std::lock_guard lock(mutex_);
    return messages_.size();
}

std::vector<std::string> ValidationLog::messages() const {
    std::lock_guard lock(mutex_);
    return messages_;
}

Instance::Instance(bool validation, ValidationLog* externalLog, const std::vector<std::string>& requested,
                   bool synchronization)
    : ownLog_(externalLog == nullptr ? std::make_unique<ValidationLog>() : nullptr),
      log_(externalLog == nullptr ? ownLog_.get() : externalLog) {
    std::uint32_t loaderVersion = VK_API_VERSION_1_0;
    VK_CHECK(vkEnumerateInstanceVersion(&loaderVersion));
    if (loaderVersion < kApiVersion) {
        throw VulkanError("the Vulkan loader supports only Vulkan " + std::to_string(VK_API_VERSION_MAJOR(loaderVersion)) +
                              "." + std::to_string(VK_API_VERSION_MINOR(loaderVersion)) + "; simeco needs 1.2",
                          VK_ERROR_INCOMPATIBLE_DRIVER);
    }
    if (validation && !layerAvailable(kValidationLayer)) {
        throw VulkanError(std::string("validation was requested but ") + kValidationLayer +
                              " is not installed (Debian: apt install vulkan-validationlayers)",
                          VK_ERROR_LAYER_NOT_PRESENT);
    }

    VkApplicationInfo app{};

    app.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO;
    app.pApplicationName = "simeco";
    app.applicationVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.pEngineName = "simeco";
    app.engineVersion = VK_MAKE_API_VERSION(0, 0, 1, 0);
    app.apiVersion = kApiVersion;

    std::vector<const char*> layers;
    std::vector<const char*> extensions;
    for (const std::string& name : requested) extensions.push_back(name.c_str());
    // Chained into instance creation too, so messages from vkCreateInstance/vkDestroyInstance are caught.
    VkDebugUtilsMessengerCreateInfoEXT debugInfo = messengerInfo(log_);
    VkInstanceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO;
    info.pApplicationInfo = &app;
    const VkValidationFeatureEnableEXT synchronizationChecks =
        VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT;
    VkValidationFeaturesEXT features{};
    features.sType = VK_STRUCTURE_TYPE_VALIDATION_FEATURES_EXT;
    features.enabledValidationFeatureCount = 1;
    features.pEnabledValidationFeatures = &synchronizationChecks;
    if (validation) {
        layers.push_back(kValidationLayer);
        extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
        info.pNext = &debugInfo;
        if (synchronization) {
            extensions.push_back(VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME);
            features.pNext = info.pNext;
            info.pNext = &features;
        }
    }
    info.enabledLayerCount = static_cast<std::uint32_t>(layers.size());
    info.ppEnabledLayerNames = layers.data();
    info.enabledExtensionCount = static_cast<std::uint32_t>(extensions.size());
    info.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateInstance(&info, nullptr, &instance_));

    if (validation) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkCreateDebugUtilsMessengerEXT"));
        VkResult result = create != nullptr ? create(instance_, &debugInfo, nullptr, &messenger_)
                                            : VK_ERROR_EXTENSION_NOT_PRESENT;
        if (result != VK_SUCCESS) {
            vkDestroyInstance(instance_, nullptr);
            throwVulkanError(result, "vkCreateDebugUtilsMessengerEXT", __FILE__, __LINE__);
        }
    }
}

Instance::Instance(Instance&& other) noexcept
    : ownLog_(std::move(other.ownLog_)),
      log_(other.log_),
      instance_(std::exchange(other.instance_, VK_NULL_HANDLE)),
      messenger_(std::exchange(other.messenger_, VK_NULL_HANDLE)) {}

Instance::~Instance() {
    if (instance_ == VK_NULL_HANDLE) {
        return;
    }
    if (messenger_ != VK_NULL_HANDLE) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy != nullptr) {
            destroy(instance_, messenger_, nullptr);
        }
    }
    vkDestroyInstance(instance_, nullptr);
}

} // namespace simeco::vk
