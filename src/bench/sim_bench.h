// `simeco bench --sim`: the growing field (field::Simulation) of the built-in garden at 100, 1,000 and 10,000
// plants. Each field grows untimed to half its life, then ticks are timed as `simeco run` runs them: the due
// plants derive, every particle grows, the turtle draws the field with each plant's statistics, and a frame is
// rendered; then frames of the field with and without shadow volumes. Reported: ticks per second, particles per second of the growth tick and its bytes against the device's
// copy bandwidth, and each stage's wall time (medians). See docs/BENCHMARKS.md.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/copy_bandwidth.h"
#include "compute/shared/organ_layout.h"

namespace simeco::bench {

struct SimBenchOptions {
    std::string root;   // where scenes/ is (defaultSuiteRoot())
    bool quick = false; // 10 and 100 plants
    std::vector<std::uint32_t> fields; // the fields' plants; empty: 100, 1,000 and 10,000 (quick: 10 and 100)
    int repeat = 5;
    int warmUp = 1;
    std::uint32_t width = 640;
    std::uint32_t height = 480;
    std::uint32_t samples = 0; // a pixel; 0: as the viewer draws them (draw::interactiveSamples)
    std::string device;
};

// Median seconds of each stage over the timed ticks.
struct SimStages {
    double derive = 0, grow = 0, interpret = 0, light = 0, statistics = 0, draw = 0;
};

struct SimEntry {
    std::uint32_t plants = 0;
    std::uint32_t batches = 0;
    double time = 0;            // simulated seconds when the timed ticks began
    std::uint64_t modules = 0;  // particles, when they began
    std::uint64_t organs = 0;
    std::vector<double> tickSeconds; // each timed tick, all its stages
    double medianTickSeconds = 0;
    double ticksPerSecond = 0;
    SimStages stages;
    double particlesPerSecond = 0; // of the growth tick
    double growBytesPerSecond = 0;
    double copyFraction = 0;       // growBytesPerSecond over the copy bandwidth
    std::string status = "ok";     // or "failed" with `reason`
    std::string reason;
    std::string notDrawn; // why the field was not interpreted and drawn (larger than the device binds); its growth was
    // A frame of the field as the timed ticks left it, with shadow volumes and without (medians); the frames a
    // second of a field that ticks once a frame: 1 / (the tick's other stages + a frame); and of one growing at real
    // time, a simulated second a second, as `simeco view` grows it by default: what a second leaves for frames once
    // its ticks have run, (1 - the tick's other stages / dt) / a frame (0 where the ticks alone take longer).
    double frameShadowsSeconds = 0, frameNoShadowsSeconds = 0;
    double growingFramesPerSecondShadows = 0, growingFramesPerSecondNoShadows = 0;
    double realTimeFramesPerSecondShadows = 0, realTimeFramesPerSecondNoShadows = 0;
    // The frame's organs by kind (kOrgan*) drawn with the finer meshes and the coarser ones; the rest were outside
    // the view.
    std::array<std::uint64_t, shared::kOrganKinds> drawnNear{}, drawnFar{};
    std::uint64_t shadowVolumes = 0; // in the frame with shadow volumes
};

struct SimBenchReport {
    SimBenchOptions options;
    std::string scene;
    std::string deviceName, deviceType, driver;
    std::optional<CopyBandwidth> copy;
    std::uint32_t bytesPerParticle = 0; // the state each module carries
    std::uint32_t growBytesPerParticle = 0; // what the growth tick reads and writes per particle
    std::vector<SimEntry> entries;
};

SimBenchReport runSimBenchmark(const SimBenchOptions& options, const std::function<void(const std::string&)>& progress);

nlohmann::json simReportJson(const SimBenchReport& report);
std::string formatSimTable(const SimBenchReport& report);

} // namespace simeco::bench
