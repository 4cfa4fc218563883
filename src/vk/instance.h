// The Vulkan instance, with the Khronos validation layer and a messenger that records what it reports.
#pragma once

#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

namespace simeco::vk {

// True when the environment asks for validation (SIMECO_VALIDATION=1); the GPU tests set it.
bool validationRequestedByEnvironment();

// Messages from the validation layer, kept so tests can fail on any of them. Written from driver threads.
class ValidationLog {
public:
    void add(std::string message);
    std::size_t count() const;
    std::vector<std::string> messages() const;

private:
    mutable std::mutex mutex_;
    std::vector<std::string> messages_;
};

class Instance {
public:
    // With `validation`, VK_LAYER_KHRONOS_validation must be installed: a missing layer is an error rather than
    // a silent run without checks. Messages go to `externalLog` when given (it must outlive the instance, which
    // lets tests see messages emitted while the instance is destroyed), else to a log of the instance's own.
    // `extensions`: instance extensions besides the validation's (a window system's surface, for presenting).
    // `synchronization`: the layer also checks the barriers between commands (hazards of one command's reads and
    // writes against another's), at a cost: for tests.
    explicit Instance(bool validation, ValidationLog* externalLog = nullptr,
                      const std::vector<std::string>& extensions = {}, bool synchronization = false);
    ~Instance();

    Instance(const Instance&) = delete;
    Instance& operator=(const Instance&) = delete;
    Instance(Instance&& other) noexcept;
    Instance& operator=(Instance&& other) = delete;

    VkInstance get() const { return instance_; }
    // The API version simeco targets; devices below it are reported but not selected.
    static constexpr std::uint32_t kApiVersion = VK_API_VERSION_1_2;

    bool validationEnabled() const { return messenger_ != VK_NULL_HANDLE; }
    // Warnings and errors reported by the validation layer so far (also printed to stderr as they come).
    const ValidationLog& validationLog() const { return *log_; }

private:
    // Heap-allocated so the messenger's user-data pointer survives moves of the Instance.
    std::unique_ptr<ValidationLog> ownLog_;
    ValidationLog* log_ = nullptr;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
};

} // namespace simeco::vk
