// Named execution + memory dependencies, so every pass states which hazard it closes.
#pragma once

#include <vulkan/vulkan.h>

namespace simeco::vk {

class Buffer;

enum class Hazard {
    ComputeToCompute,   // a kernel reads or overwrites what an earlier kernel wrote
    ComputeToTransfer,  // a copy or fill reads or overwrites what a kernel wrote
    TransferToCompute,  // a kernel reads or overwrites what a copy or fill wrote
    ComputeToIndirect,  // a dispatch takes its workgroup counts, and a kernel reads, what a kernel wrote
    ComputeToHost,      // the host maps what a kernel wrote (after a fence wait)
    AnyToTransfer,      // a copy after kernels or copies of unknown order (staging helpers)
    TransferToAny,      // anything after a copy (staging helpers)
    AnyToHost,          // the host maps what kernels or copies wrote
    TransferToHost,     // the host maps what a copy wrote
    AnyToAny,           // a stage recorded after others in one submission: all earlier writes before any access
};

// A dependency covering all memory: cheap on every driver and right when several buffers are involved.
void memoryBarrier(VkCommandBuffer cmd, Hazard hazard);

// The same dependency restricted to one buffer (whole range).
void bufferBarrier(VkCommandBuffer cmd, const Buffer& buffer, Hazard hazard);

} // namespace simeco::vk
