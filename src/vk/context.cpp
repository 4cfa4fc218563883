#include "vk/context.h"

#include <utility>
#include <vector>

#include <fmt/format.h>

#include "vk/kernel_cache.h"
#include "vk/kernel_profile.h"
#include "vk/vk_error.h"

namespace simeco::vk {
namespace {

// The family that can do everything (graphics + compute) comes first: the renderer shares the queue.
std::uint32_t chooseQueueFamily(VkPhysicalDevice device, std::uint32_t& timestampValidBits) {
    std::uint32_t count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, nullptr);
    std::vector<VkQueueFamilyProperties> families(count);
    vkGetPhysicalDeviceQueueFamilyProperties(device, &count, families.data());
    std::uint32_t chosen = count;
    for (std::uint32_t i = 0; i < count; ++i) {
        VkQueueFlags flags = families[i].queueFlags;
        if ((flags & VK_QUEUE_COMPUTE_BIT) == 0) {
            continue;
        }
        if (chosen == count || (flags & VK_QUEUE_GRAPHICS_BIT) != 0) {
            chosen = i;
        }
        if ((flags & VK_QUEUE_GRAPHICS_BIT) != 0) {
            break;
        }
    }
    if (chosen == count) {
        throw VulkanError("the selected device has no compute queue", VK_ERROR_FEATURE_NOT_PRESENT);
    }
    timestampValidBits = families[chosen].timestampValidBits;
    return chosen;
}

} // namespace

Context::Context(const ContextOptions& options)
    : instance_(options.validation, options.validationLog, options.instanceExtensions,
                options.synchronizationValidation),
      kernelCache_(std::make_unique<KernelCache>()) {
    std::vector<PhysicalDeviceInfo> devices = listPhysicalDevices(instance_.get());
    presents_ = bool(options.presentsFrom);
    if (presents_) {
        // The one queue computes, draws and presents.
        for (PhysicalDeviceInfo& d : devices) {
            if (!d.suitable()) continue;
            std::uint32_t bits = 0;
            if (!options.presentsFrom(instance_.get(), d.handle, chooseQueueFamily(d.handle, bits)))
                d.unsuitableReason = "its queue cannot present to the window";
        }
    }
    info_ = devices[selectPhysicalDevice(devices, options.device)];
    vkGetPhysicalDeviceProperties(info_.handle, &properties_);
    vkGetPhysicalDeviceMemoryProperties(info_.handle, &memory_);
    queueFamily_ = chooseQueueFamily(info_.handle, timestampValidBits_);

    // Optional features are turned on where they exist; kernels that need one check for it themselves.
    VkPhysicalDeviceVulkan12Features supported12{};
    supported12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    VkPhysicalDeviceFeatures2 supported{};
    supported.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    supported.pNext = &supported12;
    vkGetPhysicalDeviceFeatures2(info_.handle, &supported);

    VkPhysicalDeviceVulkan12Features enabled12{};

    enabled12.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES;
    enabled12.hostQueryReset = supported12.hostQueryReset;
    enabled12.timelineSemaphore = supported12.timelineSemaphore;
    enabled12.scalarBlockLayout = supported12.scalarBlockLayout;
    enabled12.vulkanMemoryModel = supported12.vulkanMemoryModel;
    enabled12.vulkanMemoryModelDeviceScope = supported12.vulkanMemoryModelDeviceScope;
    enabled12.storageBuffer8BitAccess = supported12.storageBuffer8BitAccess;
    enabled12.shaderInt8 = supported12.shaderInt8;
    VkPhysicalDeviceFeatures2 enabled{};
    enabled.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2;
    enabled.pNext = &enabled12;
    enabled.features.shaderInt64 = supported.features.shaderInt64;
    enabled.features.shaderInt16 = supported.features.shaderInt16;
    enabled.features.shaderFloat64 = supported.features.shaderFloat64;
    // The renderer: draws whose firstInstance selects a kind's instances, per-attachment blending (colour
    // blends, ids do not), depth clamp for shadow volumes reaching infinity, and a multisampled frame's sunlit
    // pass run per sample.
    enabled.features.drawIndirectFirstInstance = supported.features.drawIndirectFirstInstance;
    enabled.features.independentBlend = supported.features.independentBlend;
    enabled.features.depthClamp = supported.features.depthClamp;
    enabled.features.sampleRateShading = supported.features.sampleRateShading;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo queueInfo{};
    queueInfo.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO;
    queueInfo.queueFamilyIndex = queueFamily_;
    queueInfo.queueCount = 1;
    queueInfo.pQueuePriorities = &priority;

    std::vector<const char*> extensions = {VK_KHR_PUSH_DESCRIPTOR_EXTENSION_NAME};
    if (presents_) extensions.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    VkDeviceCreateInfo deviceInfo{};
    deviceInfo.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO;
    deviceInfo.pNext = &enabled;
    deviceInfo.queueCreateInfoCount = 1;
    deviceInfo.pQueueCreateInfos = &queueInfo;
    deviceInfo.enabledExtensionCount = std::uint32_t(extensions.size());
    deviceInfo.ppEnabledExtensionNames = extensions.data();
    VK_CHECK(vkCreateDevice(info_.handle, &deviceInfo, nullptr, &device_));
    vkGetDeviceQueue(device_, queueFamily_, 0, &queue_);

    cmdPushDescriptorSet_ =
        reinterpret_cast<PFN_vkCmdPushDescriptorSetKHR>(vkGetDeviceProcAddr(device_, "vkCmdPushDescriptorSetKHR"));
    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = VK_COMMAND_POOL_CREATE_TRANSIENT_BIT | VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = queueFamily_;
    VkCommandPool pool = VK_NULL_HANDLE;
    VkResult result = vkCreateCommandPool(device_, &poolInfo, nullptr, &pool);
    if (cmdPushDescriptorSet_ == nullptr || result != VK_SUCCESS) {
        vkDestroyDevice(device_, nullptr);
        throwVulkanError(result != VK_SUCCESS ? result : VK_ERROR_EXTENSION_NOT_PRESENT,
                         "vkCreateCommandPool / vkGetDeviceProcAddr(vkCmdPushDescriptorSetKHR)", __FILE__, __LINE__);
    }
    commandPool_ = UniqueCommandPool(device_, pool);
}

Context::~Context() {
    // Objects made from the device must go before it; the instance member goes last on its own.
    vkDeviceWaitIdle(device_);
    profile_.reset();
    commandPool_.reset();
    vkDestroyDevice(device_, nullptr);
}

void Context::submitAndWait(const std::function<void(VkCommandBuffer)>& record, std::chrono::seconds timeout) const {
    Submission submission = submit(record);
    submission.wait(timeout);
}

Submission Context::submit(const std::function<void(VkCommandBuffer)>& record) const {
    ++submissions_;
    VkCommandBufferAllocateInfo allocateInfo{};
    allocateInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocateInfo.commandPool = commandPool_.get();
    allocateInfo.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocateInfo.commandBufferCount = 1;
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateCommandBuffers(device_, &allocateInfo, &cmd));
    // Freed on a throw from `record` or the submission; once submitted, the Submission frees it.
    struct FreeOnThrow {
        VkDevice device;
        VkCommandPool pool;
        VkCommandBuffer cmd;
        ~FreeOnThrow() {
            if (cmd != VK_NULL_HANDLE) vkFreeCommandBuffers(device, pool, 1, &cmd);
        }
    } freeOnThrow{device_, commandPool_.get(), cmd};

    VkCommandBufferBeginInfo beginInfo{};
    beginInfo.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    beginInfo.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    VK_CHECK(vkBeginCommandBuffer(cmd, &beginInfo));
    if (profile_) profile_->begin(cmd);
    record(cmd);
    VK_CHECK(vkEndCommandBuffer(cmd));

    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    VkFence rawFence = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFence(device_, &fenceInfo, nullptr, &rawFence));
    UniqueFence fence(device_, rawFence);

    VkSubmitInfo submitInfo{};
    submitInfo.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submitInfo.commandBufferCount = 1;
    submitInfo.pCommandBuffers = &cmd;
    VK_CHECK(vkQueueSubmit(queue_, 1, &submitInfo, fence.get()));
    Submission submission(device_, commandPool_.get(), std::exchange(freeOnThrow.cmd, VK_NULL_HANDLE),
                          std::move(fence));
    if (profile_) {
        submission.wait();
        profile_->finish();
    }
    return submission;
}

void Context::enableKernelProfile() {
    if (!profile_) profile_ = std::make_unique<KernelProfile>(*this);
}

} // namespace simeco::vk
