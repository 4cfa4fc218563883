// The GPU time of one stage's work recorded in a submission among other stages' work (a tick's growth in the
// submission of its derivation or of its drawing): regions opened and closed around it in a command buffer, their
// times summed once the submission has finished. Where the device has no timestamps it measures nothing, and the
// caller counts the stage with the work around it.
#pragma once

#include <cstdint>
#include <optional>

#include <vulkan/vulkan.h>

#include "vk/timestamps.h"

namespace simeco::vk {

class Context;

class RegionClock {
public:
    // `regions`: the most one submission records.
    RegionClock(const Context& context, std::uint32_t regions);

    bool available() const { return stamps_.has_value(); }
    // The first region since the last read() resets the timestamps, so it must be in the command buffer of the
    // regions after it. Throws std::logic_error past `regions`, or where regions nest.
    void open(VkCommandBuffer cmd);
    void close(VkCommandBuffer cmd);
    // The seconds of the regions recorded since the last read(), their submission finished; 0 where none was.
    double read();

private:
    std::optional<Timestamps> stamps_;
    std::uint32_t capacity_ = 0;
    std::uint32_t written_ = 0; // timestamps since the last read()
};

} // namespace simeco::vk
