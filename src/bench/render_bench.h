// `simeco bench --render`: the turtle and the renderer on fields of 1 to 10,000 plants. For each field: the
// turtle kernels against the CPU reference turtle (instances per second, bytes moved against the device's copy
// bandwidth), the frame time with and without shadow volumes, and a growth tick's (turtle and frame in one
// submission), one at a time and with ticks in flight. See docs/BENCHMARKS.md.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bench/copy_bandwidth.h"

namespace simeco::bench {

struct RenderBenchOptions {
    std::string root;   // where grammars/ is (defaultSuiteRoot())
    bool quick = false; // 1 and 10 plants, small strings
    int repeat = 5;
    int warmUp = 1;
    std::uint32_t width = 640;
    std::uint32_t height = 480;
    std::uint32_t samples = 0;    // a pixel; 0: as the viewer draws them (draw::interactiveSamples)
    std::uint64_t maxModules = 0; // cap on a field's string; 0: what the turtle's buffers can bind
    std::string device;
    bool runCpu = true;
};

struct Timed {
    std::vector<double> runSeconds;
    double medianSeconds = 0;
    double instancesPerSecond = 0;
};

struct RenderEntry {
    std::uint32_t plants = 1;
    int steps = 0;
    std::uint64_t modules = 0;
    std::uint64_t organs = 0;
    std::uint32_t levels = 0;      // levels of non-linear commands the turtle kernels resolved in turn
    std::uint64_t bytesMoved = 0;  // by the turtle kernels (GpuTurtle::lastBytesMoved)
    double copyFraction = 0;       // their bytes/s over the copy bandwidth
    Timed gpuTurtle, cpuTurtle, frameWithShadows, frameWithoutShadows;
    Timed tick; // the turtle again and a frame without shadows in one submission (GpuTurtle::record)
    Timed ticksInFlight; // per tick, with draw::kFramesInFlight of them in flight
    std::string status = "ok";     // or "failed" with `reason`
    std::string reason;
};

struct RenderBenchReport {
    RenderBenchOptions options;
    std::string grammar; // the suite's file, relative to the root
    std::string deviceName, deviceType, driver;
    std::optional<CopyBandwidth> copy;
    std::vector<RenderEntry> entries;
};

RenderBenchReport runRenderBenchmark(const RenderBenchOptions& options,
                                     const std::function<void(const std::string&)>& progress);

nlohmann::json renderReportJson(const RenderBenchReport& report);
std::string formatRenderTable(const RenderBenchReport& report);

} // namespace simeco::bench
