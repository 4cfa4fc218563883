// Move-only buffers with their own memory, and the copies between host and device.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include <vulkan/vulkan.h>

#include "vk/handle.h"

namespace simeco::vk {

class Context;

enum class MemoryUsage {
    DeviceLocal,  // kernels' working memory; reached from the host only through staging copies
    Upload,       // host-visible, written by the host and read once by the device
    Readback,     // host-visible and preferably cached, written by the device and read by the host
};

// `value` rounded up to a multiple of `alignment` (binding offsets, suballocations).
inline VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
    return (value + alignment - 1) / alignment * alignment;
}

class Buffer {
public:
    Buffer() = default;
    // Storage, uniform texel and transfer usages are always included: every buffer can be bound to a kernel,
    // filled and copied.
    Buffer(const Context& context, VkDeviceSize size, MemoryUsage usage, VkBufferUsageFlags extraUsage = 0);

    Buffer(Buffer&&) noexcept = default;
    Buffer& operator=(Buffer&&) noexcept = default;

    VkBuffer handle() const { return buffer_.get(); }
    VkDeviceSize size() const { return size_; }
    // What a binding of the whole buffer covers: the size asked for, which its allocation exceeds a little (never a
    // power of two, see the constructor); VK_WHOLE_SIZE for an empty buffer.
    VkDeviceSize bindingRange() const { return size_ > 0 ? size_ : VK_WHOLE_SIZE; }
    explicit operator bool() const { return static_cast<bool>(buffer_); }

    // The persistent mapping of an Upload or Readback buffer; nullptr for DeviceLocal.
    std::byte* mapped() const { return mapped_; }

    // A view of `range` bytes from `offset` read as `format`, for uniform texel buffer bindings. Made the first
    // time it is asked for and kept as long as the buffer.
    VkBufferView texelView(VkFormat format, VkDeviceSize offset, VkDeviceSize range) const;

private:
    struct TexelView {
        VkFormat format;
        VkDeviceSize offset, range;
        UniqueBufferView view;
    };
    UniqueMemory memory_;  // declared first so the buffer is destroyed before its memory
    UniqueBuffer buffer_;
    mutable std::vector<TexelView> views_; // after buffer_, so destroyed before it
    VkDevice device_ = VK_NULL_HANDLE;
    VkDeviceSize size_ = 0;
    std::byte* mapped_ = nullptr;
};

// Index of a memory type allowed by `typeBits` that has all `required` flags, preferring one that also has
// `preferred`. Throws VulkanError when none has the required flags.
std::uint32_t chooseMemoryType(const VkPhysicalDeviceMemoryProperties& memory, std::uint32_t typeBits,
                               VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred);

// Blocking copies through a staging buffer (or the mapping, for host-visible buffers). Each waits for the
// device, and orders itself after all earlier transfer and compute work on the queue.
void upload(const Context& context, const Buffer& destination, std::span<const std::byte> bytes,
            VkDeviceSize offset = 0);
void download(const Context& context, const Buffer& source, std::span<std::byte> bytes, VkDeviceSize offset = 0);

template <typename T>
void uploadSpan(const Context& context, const Buffer& destination, std::span<const T> values) {
    upload(context, destination, std::as_bytes(values));
}

// A device-local buffer holding `values` (at least 4 bytes, so that even an empty one can be bound).
template <typename T>
Buffer deviceBufferWith(const Context& context, std::span<const T> values) {
    Buffer buffer(context, std::max<VkDeviceSize>(values.size_bytes(), 4), MemoryUsage::DeviceLocal);
    if (!values.empty()) upload(context, buffer, std::as_bytes(values));
    return buffer;
}

template <typename T>
std::vector<T> downloadVector(const Context& context, const Buffer& source, std::size_t count) {
    std::vector<T> values(count);
    download(context, source, std::as_writable_bytes(std::span<T>(values)));
    return values;
}

// Records a fill of the whole buffer with a repeated 32-bit word; the caller places the barrier after it.
void cmdFill(VkCommandBuffer cmd, const Buffer& buffer, std::uint32_t word);

} // namespace simeco::vk
