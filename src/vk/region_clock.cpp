#include "vk/region_clock.h"

#include <stdexcept>

#include "vk/context.h"

namespace simeco::vk {

RegionClock::RegionClock(const Context& context, std::uint32_t regions) : capacity_(2 * regions) {
    if (context.timestampValidBits() > 0) stamps_.emplace(context, capacity_);
}

void RegionClock::open(VkCommandBuffer cmd) {
    if (!stamps_) return;
    if (written_ % 2 != 0) throw std::logic_error("RegionClock::open: a region is open");
    if (written_ + 2 > capacity_) throw std::logic_error("RegionClock::open: more regions than the clock holds");
    if (written_ == 0) stamps_->cmdReset(cmd);
    stamps_->cmdWrite(cmd, written_++);
}

void RegionClock::close(VkCommandBuffer cmd) {
    if (!stamps_) return;
    if (written_ % 2 == 0) throw std::logic_error("RegionClock::close: no region is open");
    stamps_->cmdWrite(cmd, written_++);
}

double RegionClock::read() {
    if (!stamps_ || written_ == 0) return 0.0;
    if (written_ % 2 != 0) throw std::logic_error("RegionClock::read: a region is open");
    const std::vector<double> ns = stamps_->readNs(written_);
    written_ = 0;
    double total = 0.0;
    for (std::uint32_t k = 0; k + 1 < ns.size(); k += 2) total += ns[k + 1] - ns[k];
    return total * 1e-9;
}

} // namespace simeco::vk
