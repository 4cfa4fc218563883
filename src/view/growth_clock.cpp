#include "view/growth_clock.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simeco::view {

GrowthClock::GrowthClock(double tickSeconds) : tickSeconds_(tickSeconds) {
    if (!(tickSeconds > 0.0) || !std::isfinite(tickSeconds))
        throw std::invalid_argument("a growth clock's tick must last a positive time");
}

std::uint32_t GrowthClock::ticksAfter(double seconds, double timeScale) {
    owed_ += std::max(seconds, 0.0) * std::max(timeScale, 0.0);
    // A tick due within a part in a million of the owed time is due now: a frame of exactly one tick's time
    // runs it, whatever the rounding of the sum.
    const double due = std::floor(owed_ / tickSeconds_ * (1.0 + 1e-6));
    if (due >= kMaxTicksAFrame) {
        owed_ = 0.0;
        return kMaxTicksAFrame;
    }
    owed_ = std::max(owed_ - due * tickSeconds_, 0.0);
    return static_cast<std::uint32_t>(due);
}

void GrowthRate::add(double clockSeconds, double simulatedSeconds) {
    samples_.emplace_back(clockSeconds, simulatedSeconds);
    // Keep one sample at or before the window's start, so the rate spans the whole window.
    while (samples_.size() > 2 && samples_[1].first <= clockSeconds - windowSeconds_) samples_.pop_front();
}

double GrowthRate::perSecond() const {
    if (samples_.size() < 2) return 0.0;
    const double clock = samples_.back().first - samples_.front().first;
    return clock > 0.0 ? (samples_.back().second - samples_.front().second) / clock : 0.0;
}

} // namespace simeco::view
