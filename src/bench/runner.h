// Running the suite: calibration (how many steps each entry needs), then warm-up and timed runs of the CPU
// reference engine and the GPU backend on every entry, and the device's copy bandwidth in the same run.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "bench/copy_bandwidth.h"
#include "bench/suite.h"

namespace simeco::bench {

struct BenchOptions {
    std::string root;   // where the suite's files are (bench::defaultSuiteRoot())
    bool quick = false; // the tiny suite (1 and 10 plants, kQuickTargetModules)
    int repeat = 5;     // timed runs per backend and entry
    int warmUp = 1;     // untimed runs before them
    std::uint64_t targetModules = kDefaultTargetModules;
    std::uint64_t maxModules = 0; // cap on any entry's string; 0: sized to memory and device
    bool runCpu = true;
    bool runGpu = true;
    std::string device;                // Vulkan device (index or name part); empty: the default
    std::vector<std::string> grammars; // only these suite grammars (by name); empty: all
};

// One backend on one entry. `status` is "ok", "unsupported" (the grammar cannot run there), "unavailable"
// (no such backend in this run), "skipped" or "failed" (with `reason`).
struct BackendResult {
    std::string status = "skipped";
    std::string reason;
    std::vector<double> runSeconds; // wall time of each timed run
    double medianSeconds = 0;
    std::uint64_t modules = 0;    // modules of all plants after the last step
    std::uint64_t bytesMoved = 0; // per run; see BenchReport
    double modulesPerSecond = 0;
    double bytesPerSecond = 0;
    // GPU only.
    double compileSeconds = 0;      // kernel generation and compilation, once per grammar
    std::vector<double> passMillis; // GPU time of each derivation step (timestamps), median run
    double passMillisTotal = 0;     // their sum
    double copyFraction = 0;        // bytesPerSecond / the copy kernel's bytes per second
    std::uint32_t waits = 0;        // submissions the host waited for in the median run (GpuDeriveStats::waits)

    bool ok() const { return status == "ok"; }
};

struct EntryResult {
    std::string name;
    std::string file;
    std::string kind;
    std::uint32_t plants = 1;
    int steps = 0;
    int stride = 1;                       // parameter slots per module
    std::uint64_t expectedModules = 0;    // from the calibration (exact for deterministic grammars)
    std::uint64_t stringTrafficBytes = 0; // the module stream read and written by all steps
    bool targetReached = false;
    std::string note; // why an entry stays below the target
    BackendResult cpu;
    BackendResult gpu;
};

struct BenchReport {
    BenchOptions options;
    std::string deviceName; // empty without a Vulkan device
    std::string deviceType;
    std::string driver;
    std::uint64_t maxStorageBufferRange = 0;
    std::string gpuNote; // why the GPU column is empty, when it is
    std::optional<CopyBandwidth> copy;
    bool scaledDown = false; // some entries were held below the target by memory or the device
    std::vector<std::string> notes;
    std::vector<EntryResult> entries;
};

// Progress lines go to `progress` (e.g. stderr). Errors of one entry's backend are recorded in the report;
// missing suite files and bad options throw.
BenchReport runBenchmark(const BenchOptions& options, const std::function<void(const std::string&)>& progress);

} // namespace simeco::bench
