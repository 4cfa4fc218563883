// How far a viewed field grows each frame. Its simulated time follows the viewer's clock times the time scale
// (simulated seconds a second), so that a field grows as fast on a device that draws five frames a second as on one
// that draws sixty, and the frames between two ticks cost only their drawing. A frame runs at most kMaxTicksAFrame
// ticks: further behind, the field lets the rest go and grows slower than asked rather than the viewer stalling.
#pragma once

#include <cstdint>
#include <deque>
#include <utility>

namespace simeco::view {

inline constexpr std::uint32_t kMaxTicksAFrame = 16;

class GrowthClock {
public:
    // `tickSeconds`: the simulated seconds of one tick (the field's dt).
    explicit GrowthClock(double tickSeconds);

    // The ticks due after `seconds` more of the viewer's clock at `timeScale` simulated seconds a second.
    std::uint32_t ticksAfter(double seconds, double timeScale);
    // Nothing owed: a new field, whose time starts anew.
    void restart() { owed_ = 0.0; }

private:
    double tickSeconds_;
    double owed_ = 0.0; // simulated seconds due and not yet ticked
};

// How fast a field grows: the simulated seconds it grew a second of the clock over the last `windowSeconds` (the
// panel's figure, which a single frame's ticks would make jump between zero and many).
class GrowthRate {
public:
    explicit GrowthRate(double windowSeconds = 2.0) : windowSeconds_(windowSeconds) {}

    // A frame: the clock's time and the field's simulated time.
    void add(double clockSeconds, double simulatedSeconds);
    double perSecond() const;
    // Another field, whose time starts anew.
    void restart() { samples_.clear(); }

private:
    double windowSeconds_;
    std::deque<std::pair<double, double>> samples_; // (clock, simulated), oldest first
};

} // namespace simeco::view
