#include "vk/barriers.h"

#include "vk/buffer.h"

namespace simeco::vk {
namespace {

struct Scopes {
    VkPipelineStageFlags srcStage;
    VkAccessFlags srcAccess;
    VkPipelineStageFlags dstStage;
    VkAccessFlags dstAccess;
};

constexpr VkPipelineStageFlags kCompute = VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT;
constexpr VkPipelineStageFlags kTransfer = VK_PIPELINE_STAGE_TRANSFER_BIT;
constexpr VkAccessFlags kShaderReadWrite = VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT;
constexpr VkAccessFlags kTransferReadWrite = VK_ACCESS_TRANSFER_READ_BIT | VK_ACCESS_TRANSFER_WRITE_BIT;

Scopes scopes(Hazard hazard) {
    switch (hazard) {
    case Hazard::ComputeToCompute:
        return {kCompute, VK_ACCESS_SHADER_WRITE_BIT, kCompute, kShaderReadWrite};
    case Hazard::ComputeToTransfer:
        return {kCompute, VK_ACCESS_SHADER_WRITE_BIT, kTransfer, kTransferReadWrite};
    case Hazard::TransferToCompute:
        return {kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, kCompute, kShaderReadWrite};
    case Hazard::ComputeToIndirect:
        return {kCompute, VK_ACCESS_SHADER_WRITE_BIT, kCompute | VK_PIPELINE_STAGE_DRAW_INDIRECT_BIT,
                kShaderReadWrite | VK_ACCESS_INDIRECT_COMMAND_READ_BIT};
    case Hazard::ComputeToHost:
        return {kCompute, VK_ACCESS_SHADER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT};
    case Hazard::AnyToTransfer:
        return {kCompute | kTransfer, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT, kTransfer,
                kTransferReadWrite};
    case Hazard::TransferToAny:
        return {kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
                VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT};
    case Hazard::AnyToHost:
        return {kCompute | kTransfer, VK_ACCESS_SHADER_WRITE_BIT | VK_ACCESS_TRANSFER_WRITE_BIT,
                VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT};
    case Hazard::TransferToHost:
        return {kTransfer, VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_HOST_BIT, VK_ACCESS_HOST_READ_BIT};
    case Hazard::AnyToAny: break;
    }
    return {VK_PIPELINE_STAGE_ALL_COMMANDS_BIT, VK_ACCESS_MEMORY_WRITE_BIT, VK_PIPELINE_STAGE_ALL_COMMANDS_BIT,
            VK_ACCESS_MEMORY_READ_BIT | VK_ACCESS_MEMORY_WRITE_BIT};
}

} // namespace

void memoryBarrier(VkCommandBuffer cmd, Hazard hazard) {
    Scopes s = scopes(hazard);
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = s.srcAccess;
    barrier.dstAccessMask = s.dstAccess;
    vkCmdPipelineBarrier(cmd, s.srcStage, s.dstStage, 0, 1, &barrier, 0, nullptr, 0, nullptr);
}

void bufferBarrier(VkCommandBuffer cmd, const Buffer& buffer, Hazard hazard) {
    Scopes s = scopes(hazard);
    VkBufferMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER;
    barrier.srcAccessMask = s.srcAccess;
    barrier.dstAccessMask = s.dstAccess;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.buffer = buffer.handle();
    barrier.offset = 0;
    barrier.size = VK_WHOLE_SIZE;
    vkCmdPipelineBarrier(cmd, s.srcStage, s.dstStage, 0, 0, nullptr, 1, &barrier, 0, nullptr);
}

} // namespace simeco::vk
