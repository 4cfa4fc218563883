// Timing helpers of the benchmark: a wall clock, warm-up followed by repeated runs, and medians.
#pragma once

#include <chrono>
#include <functional>
#include <string>
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

// One of several measurements taken in turns (runInTurns): `run` measures once.
struct Measurement {
    std::function<double()> run;
    std::vector<double> samples; // of the timed rounds
    std::string error;           // why it stopped: what `run` threw; empty while it takes part
};

// `warmUp` rounds whose results are discarded, then `repeat` rounds, each running every measurement once in
// turn: on a machine whose speed drifts over minutes, each measurement's samples then span the same stretch of
// time as the others', and their ratio holds. A measurement whose run throws takes no further part.
void runInTurns(int warmUp, int repeat, const std::vector<Measurement*>& measurements);

} // namespace simeco::bench
