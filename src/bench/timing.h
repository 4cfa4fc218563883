// Timing helpers of the benchmark: a wall clock, warm-up followed by repeated runs, and medians.
#pragma once

#include <chrono>
#include <functional>
#include <vector>

namespace simeco::bench {

using Clock = std::chrono::steady_clock;

inline double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The median (the mean of the middle two for an even count); 0 for no values.
double median(std::vector<double> values);

// Runs `run` warmUp times, discarding what it returns, then `repeat` times, returning each run's measurement
// (whatever `run` measures: its own wall time, or a GPU time).
std::vector<double> repeatRuns(int warmUp, int repeat, const std::function<double()>& run);

} // namespace simeco::bench
