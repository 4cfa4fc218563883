#include "vk/timestamps.h"

#include <stdexcept>

#include <fmt/format.h>

#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::vk {

Timestamps::Timestamps(const Context& context, std::uint32_t count)
    : device_(context.device()), count_(count), periodNs_(context.limits().timestampPeriod) {
    std::uint32_t bits = context.timestampValidBits();
    if (bits == 0) {
        throw VulkanError(fmt::format("device {} has no timestamps on its compute queue", context.deviceInfo().name),
                          VK_ERROR_FEATURE_NOT_PRESENT);
    }
    // Only the low `bits` bits of a raw timestamp are meaningful; the rest is undefined.
    validMask_ = bits >= 64 ? ~std::uint64_t{0} : (std::uint64_t{1} << bits) - 1;
    VkQueryPoolCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO;
    info.queryType = VK_QUERY_TYPE_TIMESTAMP;
    info.queryCount = count;
    VkQueryPool pool = VK_NULL_HANDLE;
    VK_CHECK(vkCreateQueryPool(device_, &info, nullptr, &pool));
    pool_ = UniqueQueryPool(device_, pool);
}

void Timestamps::cmdReset(VkCommandBuffer cmd) const {
    vkCmdResetQueryPool(cmd, pool_.get(), 0, count_);
}

void Timestamps::cmdWrite(VkCommandBuffer cmd, std::uint32_t index, VkPipelineStageFlagBits stage) const {
    vkCmdWriteTimestamp(cmd, stage, pool_.get(), index);
}

std::vector<double> Timestamps::readNs(std::uint32_t count) const {
    std::vector<std::uint64_t> raw(count);
    VK_CHECK(vkGetQueryPoolResults(device_, pool_.get(), 0, count, raw.size() * sizeof(std::uint64_t), raw.data(),
                                   sizeof(std::uint64_t), VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
    std::vector<double> ns(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        ns[i] = static_cast<double>(raw[i] & validMask_) * periodNs_;
    }
    return ns;
}

double Timestamps::elapsedNs(std::uint32_t from, std::uint32_t to) const {
    // Only the two queries: the others may not have been written since the pool was reset.
    auto read = [&](std::uint32_t index) {
        if (index >= count_) throw std::out_of_range(fmt::format("timestamp query {} of {}", index, count_));
        std::uint64_t raw = 0;
        VK_CHECK(vkGetQueryPoolResults(device_, pool_.get(), index, 1, sizeof raw, &raw, sizeof raw,
                                       VK_QUERY_RESULT_64_BIT | VK_QUERY_RESULT_WAIT_BIT));
        return static_cast<double>(raw & validMask_) * periodNs_;
    };
    return read(to) - read(from);
}

} // namespace simeco::vk
