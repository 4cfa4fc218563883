// The one Vulkan device simeco runs on: instance, chosen physical device, queue, command pool, and a
// one-shot submit for setup work and tests.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/device_info.h"
#include "vk/handle.h"
#include "vk/instance.h"
#include "vk/submission.h"

namespace simeco::vk {

class KernelCache;
class KernelProfile;

struct ContextOptions {
    // `--device`: an index or a name substring; empty picks the best device (a real GPU, else lavapipe).
    std::string device;
    // Validation layer plus a messenger counting its messages; on by default when SIMECO_VALIDATION=1.
    bool validation = validationRequestedByEnvironment();
    // With validation, the layer's synchronization checks too (vk::Instance): slow, for tests.
    bool synchronizationValidation = false;
    // Where validation messages are collected; must outlive the context. Null: the instance keeps its own.
    ValidationLog* validationLog = nullptr;
    // Presenting to a window: the window system's instance extensions (the surface's), and a test of whether a
    // device's queue family can present to it. Given, the device is made with VK_KHR_swapchain and its queue
    // family must present; a device that cannot is passed over when choosing, refused when named.
    std::vector<std::string> instanceExtensions;
    std::function<bool(VkInstance, VkPhysicalDevice, std::uint32_t)> presentsFrom;
};

class Context {
public:
    explicit Context(const ContextOptions& options = {});
    ~Context();

    // Buffers and pipelines keep the device handle, so the context stays put.
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkDevice device() const { return device_; }
    VkPhysicalDevice physicalDevice() const { return info_.handle; }
    VkQueue queue() const { return queue_; }
    std::uint32_t queueFamily() const { return queueFamily_; }

    const Instance& instance() const { return instance_; }
    const PhysicalDeviceInfo& deviceInfo() const { return info_; }
    const VkPhysicalDeviceLimits& limits() const { return properties_.limits; }
    const VkPhysicalDeviceMemoryProperties& memoryProperties() const { return memory_; }
    // Bits of a timestamp that are valid on the queue; 0 means no timestamps.
    std::uint32_t timestampValidBits() const { return timestampValidBits_; }

    // Whether the device was made to present to a window (ContextOptions::presentsFrom).
    bool presents() const { return presents_; }

    bool validationEnabled() const { return instance_.validationEnabled(); }
    const ValidationLog& validationLog() const { return instance_.validationLog(); }

    // VK_KHR_push_descriptor's entry point, loaded once for every pipeline.
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet() const { return cmdPushDescriptorSet_; }

    // Records with `record` into a fresh command buffer, submits it and waits. A GPU that does not finish
    // within `timeout` raises VulkanError rather than hanging the program.
    void submitAndWait(const std::function<void(VkCommandBuffer)>& record,
                       std::chrono::seconds timeout = std::chrono::seconds(120)) const;
    // Records and submits without waiting: the caller waits for the returned submission when it needs the
    // work's results (frames in flight). With the kernel profile on, it waits at once, to read the timestamps.
    [[nodiscard]] Submission submit(const std::function<void(VkCommandBuffer)>& record) const;
    // Submissions made since the context was made: on a discrete GPU each wait costs far more than a small
    // kernel, so the derivation counts its own (GpuDeriveStats::waits).
    std::uint64_t submissions() const { return submissions_; }

    // From now on, time every dispatch of submitAndWait's submissions per kernel (see KernelProfile).
    void enableKernelProfile();
    // The profile, or null when it is not enabled.
    KernelProfile* kernelProfile() const { return profile_.get(); }
    // The kernels compiled on this device, shared by the pipelines made from the same SPIR-V (vk/kernel_cache.h).
    KernelCache& kernelCache() const { return *kernelCache_; }

private:
    Instance instance_;
    PhysicalDeviceInfo info_;
    VkPhysicalDeviceProperties properties_{};
    VkPhysicalDeviceMemoryProperties memory_{};
    std::uint32_t queueFamily_ = 0;
    std::uint32_t timestampValidBits_ = 0;
    bool presents_ = false;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    UniqueCommandPool commandPool_;
    PFN_vkCmdPushDescriptorSetKHR cmdPushDescriptorSet_ = nullptr;
    std::unique_ptr<KernelProfile> profile_;
    std::unique_ptr<KernelCache> kernelCache_;
    mutable std::uint64_t submissions_ = 0;
};

} // namespace simeco::vk
