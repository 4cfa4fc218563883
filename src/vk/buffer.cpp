#include "vk/buffer.h"

#include <bit>
#include <cstring>

#include <fmt/format.h>

#include "vk/barriers.h"
#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::vk {

std::uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t typeBits,
                               VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) {
    std::uint32_t fallback = memory.memoryTypeCount;
    for (std::uint32_t i = 0; i < memory.memoryTypeCount; ++i) {
        VkMemoryPropertyFlags flags = memory.memoryTypes[i].propertyFlags;
        if ((typeBits & (1u << i)) == 0 || (flags & required) != required) {
            continue;
        }
        if ((flags & preferred) == preferred) {
            return i;
        }
        if (fallback == memory.memoryTypeCount) {
            fallback = i;
        }
    }
    if (fallback == memory.memoryTypeCount) {
        throw VulkanError(fmt::format("no memory type with properties {:#x} for this buffer", required),
                          VK_ERROR_FEATURE_NOT_PRESENT);
    }
    return fallback;
}

Buffer::Buffer(const Context& context, VkDeviceSize size, MemoryUsage usage, VkBufferUsageFlags extraUsage)
    : device_(context.device()), size_(size) {
    VkDevice device = device_;
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    // Zero-sized buffers are invalid in Vulkan; an empty input still gets a bindable buffer. Never a power of two
    // bytes: lavapipe compiles a kernel once for each combination of its texel buffers being powers of two in size
    // or not, so a buffer that grew from a power of two to another size made every large generated kernel that reads
    // it compile again (ten seconds and more each). size() stays the size asked for.
    info.size = std::max<VkDeviceSize>(size, 4);
    while (std::has_single_bit(info.size)) info.size += 16; // a multiple of every texel's size

    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT |
                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | extraUsage;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    VK_CHECK(vkCreateBuffer(device, &info, nullptr, &buffer));
    buffer_ = UniqueBuffer(device, buffer);

    VkMemoryRequirements requirements{};
    vkGetBufferMemoryRequirements(device, buffer, &requirements);
    VkMemoryPropertyFlags required = 0;
    VkMemoryPropertyFlags preferred = 0;
    switch (usage) {
    case MemoryUsage::DeviceLocal:
        preferred = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
        break;
    case MemoryUsage::Upload:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        break;
    case MemoryUsage::Readback:
        required = VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
        preferred = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
        break;
    }
    VkMemoryAllocateInfo allocateInfo{};
    allocateInfo.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    allocateInfo.allocationSize = requirements.size;
    allocateInfo.memoryTypeIndex =
        chooseMemoryType(context.memoryProperties(), requirements.memoryTypeBits, required, preferred);
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VK_CHECK(vkAllocateMemory(device, &allocateInfo, nullptr, &memory));
    memory_ = UniqueMemory(device, memory);
    VK_CHECK(vkBindBufferMemory(device, buffer, memory, 0));

    if (usage != MemoryUsage::DeviceLocal) {
        void* pointer = nullptr;
        VK_CHECK(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &pointer));
        mapped_ = static_cast<std::byte*>(pointer);
    }
}

VkBufferView Buffer::texelView(VkFormat format, VkDeviceSize offset, VkDeviceSize range) const {
    for (const TexelView& v : views_)
        if (v.format == format && v.offset == offset && v.range == range) return v.view.get();
    VkBufferViewCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO;
    info.buffer = buffer_.get();
    info.format = format;
    info.offset = offset;
    info.range = range;
    VkBufferView view = VK_NULL_HANDLE;
    VK_CHECK(vkCreateBufferView(device_, &info, nullptr, &view));
    views_.push_back({format, offset, range, UniqueBufferView(device_, view)});
    return view;
}

namespace {

void checkRange(const Buffer& buffer, VkDeviceSize offset, std::size_t bytes) {
    if (offset > buffer.size() || bytes > buffer.size() - offset) {
        throw VulkanError(fmt::format("copy of {} bytes at offset {} exceeds a buffer of {} bytes", bytes, offset,
                                      buffer.size()),
                          VK_ERROR_UNKNOWN);
    }
}

} // namespace

void upload(const Context& context, const Buffer& destination, std::span<const std::byte> bytes, VkDeviceSize offset) {
    checkRange(destination, offset, bytes.size());
    if (bytes.empty()) {
        return;
    }
    if (destination.mapped() != nullptr) {
        // Wait for earlier device work that may still read the old contents.
        VK_CHECK(vkQueueWaitIdle(context.queue()));
        std::memcpy(destination.mapped() + offset, bytes.data(), bytes.size());
        return;
    }
    Buffer staging(context, bytes.size(), MemoryUsage::Upload);
    std::memcpy(staging.mapped(), bytes.data(), bytes.size());
    context.submitAndWait([&](VkCommandBuffer cmd) {
        memoryBarrier(cmd, Hazard::AnyToTransfer);
        VkBufferCopy region{0, offset, bytes.size()};
        vkCmdCopyBuffer(cmd, staging.handle(), destination.handle(), 1, &region);
        memoryBarrier(cmd, Hazard::TransferToAny);
    });
}

void download(const Context& context, const Buffer& source, std::span<std::byte> bytes, VkDeviceSize offset) {
    checkRange(source, offset, bytes.size());
    if (bytes.empty()) {
        return;
    }
    if (source.mapped() != nullptr) {
        context.submitAndWait([&](VkCommandBuffer cmd) { memoryBarrier(cmd, Hazard::AnyToHost); });
        std::memcpy(bytes.data(), source.mapped() + offset, bytes.size());
        return;
    }
    Buffer staging(context, bytes.size(), MemoryUsage::Readback);
    context.submitAndWait([&](VkCommandBuffer cmd) {
        memoryBarrier(cmd, Hazard::AnyToTransfer);
        VkBufferCopy region{offset, 0, bytes.size()};
        vkCmdCopyBuffer(cmd, source.handle(), staging.handle(), 1, &region);
        memoryBarrier(cmd, Hazard::TransferToHost);
    });
    std::memcpy(bytes.data(), staging.mapped(), bytes.size());
}

void cmdFill(VkCommandBuffer cmd, const Buffer& buffer, std::uint32_t word) {
    vkCmdFillBuffer(cmd, buffer.handle(), 0, VK_WHOLE_SIZE, word);
}

} // namespace simeco::vk
