#include "bench/runner.h"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/timing.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "ir/source_loc.h"
#include "lang/load_grammar.h"
#include "vk/context.h"
#include "vk/device_info.h"

namespace simeco::bench {
namespace {

// Bytes of one module in the module stream (stream/module_string.h): symbol, parameter count, parameter slots.
std::uint64_t moduleBytes(int stride) {
    return sizeof(std::uint32_t) + sizeof(std::uint8_t) + sizeof(float) * static_cast<std::uint64_t>(stride);
}

// The string size of `sample` plants after 0, 1, 2, ... steps, up to the first size that reaches `target`,
// exceeds `cap`, or `maxSteps`. Plant i of a many-plant derivation draws the same random numbers whatever the
// plant count, so for the first `sample` plants this is exact, and for a deterministic grammar every plant is
// the same; a stochastic grammar's other plants differ, and the sample's mean stands for them.
std::vector<std::uint64_t> growthProfile(const ir::Grammar& g, std::uint32_t sample, std::uint64_t target,
                                         std::uint64_t cap, int maxSteps) {
    std::vector<std::uint64_t> sizes;
    for (int steps = 0; steps <= maxSteps; ++steps) {
        stream::DeriveOptions options;
        options.steps = steps;
        options.plants = sample;
        options.maxModules = cap + 1;
        std::uint64_t size = 0;
        try {
            size = cpu::deriveCpu(g, options).string.size();
        } catch (const ir::LimitError&) {
            sizes.push_back(cap + 1); // beyond the cap: all planEntry needs to know
            break;
        }
        sizes.push_back(size);
        if (size >= target || size > cap) {
            break;
        }
    }
    return sizes;
}

// Plants derived by the calibration of an entry of `plants` plants.
std::uint32_t calibrationSample(std::uint32_t plants) {
    return std::min<std::uint32_t>(plants, 16);
}

struct Plan {
    int steps = 0;
    std::uint64_t expectedModules = 0;
    std::uint64_t stringTrafficBytes = 0; // module-stream bytes read and written by all steps, all plants
    bool targetReached = false;
    std::string note;
};

// The smallest step count that brings `plants` plants to the target, else the largest that stays under the cap.
// `profile` holds the sizes of `sample` plants.
Plan planEntry(const std::vector<std::uint64_t>& profile, std::uint32_t sample, std::uint32_t plants,
               std::uint64_t target, std::uint64_t cap, bool capFromDevice, int maxSteps, int stride) {
    auto scaled = [&](std::uint64_t sampleSize) {
        return static_cast<std::uint64_t>(static_cast<double>(sampleSize) * plants / sample);
    };
    Plan plan;
    for (std::size_t k = 0; k < profile.size(); ++k) {
        std::uint64_t total = scaled(profile[k]);
        if (total > cap) {
            plan.note = fmt::format("held at {} steps: {} steps would pass the cap of {} modules ({})", plan.steps, k,
                                    cap, capFromDevice ? "the device's largest storage buffer" : "memory budget");
            break;
        }
        plan.steps = static_cast<int>(k);
        plan.expectedModules = total;
        if (total >= target) {
            plan.targetReached = true;
            break;
        }
    }
    if (!plan.targetReached && plan.note.empty()) {
        plan.note = profile.size() > 1 && profile.back() == profile[profile.size() - 2]
                        ? fmt::format("the plants stop growing, at about {} modules each", profile.back() / sample)
                        : fmt::format("held at the suite's {} steps", maxSteps);
    }
    for (int k = 1; k <= plan.steps; ++k) {
        plan.stringTrafficBytes += scaled(profile[k - 1] + profile[k]) * moduleBytes(stride);
    }
    return plan;
}

void finish(BackendResult& r, std::uint64_t bytesMoved) {
    r.status = "ok";
    r.medianSeconds = median(r.runSeconds);
    r.bytesMoved = bytesMoved;
    if (r.medianSeconds > 0) {
        r.modulesPerSecond = static_cast<double>(r.modules) / r.medianSeconds;
        r.bytesPerSecond = static_cast<double>(r.bytesMoved) / r.medianSeconds;
    }
}

BackendResult failed(const std::string& status, const std::string& reason) {
    BackendResult r;
    r.status = status;
    r.reason = reason;
    return r;
}

// The CPU reference's and the GPU backend's runs of an entry, taken in turns (runInTurns).
class EntryRuns {
public:
    EntryRuns(const ir::Grammar& g, gpu::GpuDeriver* deriver, const EntryResult& entry) {
        derive_.steps = entry.steps;
        derive_.plants = entry.plants;
        cpu_.run = [this, &g] {
            Clock::time_point start = Clock::now();
            stream::DeriveResult result = cpu::deriveCpu(g, derive_);
            double seconds = secondsSince(start);
            cpuModules_ = result.string.size();
            return seconds;
        };
        if (deriver) {
            gpu_.run = [this, deriver] {
                gpu::GpuDeriveStats stats;
                Clock::time_point start = Clock::now();
                deriver->derive(derive_, /*readBack=*/false, &stats);
                double seconds = secondsSince(start);
                gpuStats_.push_back(stats);
                return seconds;
            };
        }
    }

    EntryRuns(const EntryRuns&) = delete; // the runs capture `this`
    EntryRuns& operator=(const EntryRuns&) = delete;

    void run(const BenchOptions& options, bool cpu, bool gpu) {
        std::vector<Measurement*> measurements;
        if (cpu) {
            measurements.push_back(&cpu_);
        }
        if (gpu && gpu_.run) {
            measurements.push_back(&gpu_);
        }
        runInTurns(options.warmUp, options.repeat, measurements);
        // The GPU's statistics of the timed runs only.
        std::size_t gpuWarmUps = gpuStats_.size() - std::min(gpuStats_.size(), gpu_.samples.size());
        gpuStats_.erase(gpuStats_.begin(), gpuStats_.begin() + static_cast<std::ptrdiff_t>(gpuWarmUps));
    }

    BackendResult cpuResult(std::uint64_t bytesMoved) const {
        if (!cpu_.error.empty()) {
            return failed("failed", cpu_.error);
        }
        BackendResult r;
        r.runSeconds = cpu_.samples;
        r.modules = cpuModules_;
        finish(r, bytesMoved);
        return r;
    }

    BackendResult gpuResult() const {
        if (!gpu_.error.empty()) {
            return failed("failed", gpu_.error);
        }
        BackendResult r;
        r.runSeconds = gpu_.samples;
        // The passes of the run with the median wall time (the upper middle one for an even count).
        std::vector<std::size_t> order(gpuStats_.size());
        for (std::size_t i = 0; i < order.size(); ++i)
            order[i] = i;
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return r.runSeconds[a] < r.runSeconds[b]; });
        const gpu::GpuDeriveStats& mid = gpuStats_.at(order.at(order.size() / 2));
        r.modules = mid.modules;
        r.compileSeconds = mid.compileSeconds;
        r.waits = mid.waits;
        r.passMillis = mid.stepMillis;
        for (double ms : mid.stepMillis)
            r.passMillisTotal += ms;
        finish(r, mid.bytesMoved);
        return r;
    }

private:
    stream::DeriveOptions derive_;
    Measurement cpu_, gpu_;
    std::uint64_t cpuModules_ = 0;
    std::vector<gpu::GpuDeriveStats> gpuStats_;
};

// The device the GPU runs use, with its name and copy bandwidth in the report; none (and why) when there is none
// or the GPU is skipped.
std::unique_ptr<vk::Context> openDevice(const BenchOptions& options, BenchReport& report,
                                        const std::function<void(const std::string&)>& progress) {
    if (!options.runGpu) {
        report.gpuNote = "skipped (--no-gpu)";
        return nullptr;
    }
    std::unique_ptr<vk::Context> context;
    try {
        vk::ContextOptions contextOptions;
        contextOptions.device = options.device;
        context = std::make_unique<vk::Context>(contextOptions);
    } catch (const std::exception& e) {
        report.gpuNote = fmt::format("no Vulkan device: {}", e.what());
        return nullptr;
    }
    const vk::PhysicalDeviceInfo& info = context->deviceInfo();
    report.deviceName = info.name;
    report.deviceType = std::string(vk::deviceTypeName(info.type));
    report.driver = info.driverName;
    report.maxStorageBufferRange = context->limits().maxStorageBufferRange;
    progress(fmt::format("device: {} ({}); measuring copy bandwidth", report.deviceName, report.deviceType));
    try {
        report.copy = measureCopyBandwidth(*context, options.warmUp, options.repeat);
    } catch (const std::exception& e) {
        report.notes.push_back(fmt::format("copy bandwidth not measured: {}", e.what()));
    }
    return context;
}

// A suite grammar loaded for its entries: its module cap and, with a device, its deriver or why there is none.
struct LoadedGrammar {
    ir::Grammar grammar;
    std::uint64_t cap = 0;
    bool capFromDevice = false;
    std::unique_ptr<gpu::GpuDeriver> deriver;
    std::string gpuStatus; // why there is no deriver: "unsupported" or "failed"
    std::string gpuReason;
};

std::unique_ptr<LoadedGrammar> loadSuiteGrammar(const SuiteGrammar& sg, const BenchOptions& options,
                                                const vk::Context* context, const BenchReport& report) {
    auto l = std::make_unique<LoadedGrammar>();
    l->grammar = lang::loadGrammarFile((std::filesystem::path(options.root) / sg.file).string());
    int stride = std::max(l->grammar.maxParams(), 1);
    l->cap = options.maxModules ? options.maxModules : stream::defaultModuleBudget(stride);
    if (!context) return l;
    // The GPU keeps each module's parameters in one storage buffer (4 bytes per slot).
    std::uint64_t deviceCap = report.maxStorageBufferRange / (sizeof(float) * std::uint64_t(stride));
    if (deviceCap < l->cap) {
        l->cap = deviceCap;
        l->capFromDevice = true;
    }
    if (std::optional<std::string> reason = codegen::gpuUnsupportedReason(l->grammar)) {
        l->gpuStatus = "unsupported";
        l->gpuReason = *reason;
        return l;
    }
    try {
        l->deriver = std::make_unique<gpu::GpuDeriver>(*context, l->grammar);
    } catch (const std::exception& e) {
        l->gpuStatus = "failed";
        l->gpuReason = fmt::format("the grammar's kernels were not built: {}", e.what());
    }
    return l;
}

// One suite entry: its steps planned from a calibration sample, then both backends' runs.
EntryResult runEntry(const SuiteEntry& entry, const LoadedGrammar& l, const BenchOptions& options,
                     const vk::Context* context, std::uint64_t target, BenchReport& report,
                     const std::function<void(const std::string&)>& progress) {
    const SuiteGrammar& sg = entry.grammar;
    EntryResult e;
    e.name = sg.name;
    e.file = sg.file;
    e.kind = sg.kind;
    e.plants = entry.plants;
    e.stride = std::max(l.grammar.maxParams(), 1);
    std::uint32_t sample = calibrationSample(entry.plants);
    progress(fmt::format("{} x{}: calibrating the steps on {} plant(s) (target {} modules, cap {})", e.name,
                         e.plants, sample, target, l.cap));
    // Targets and caps scaled down to the sample, rounded up so that the sample grows far enough.
    std::uint64_t sampleTarget = (target * sample + entry.plants - 1) / entry.plants;
    std::uint64_t sampleCap = (l.cap * sample + entry.plants - 1) / entry.plants;
    std::vector<std::uint64_t> profile = growthProfile(l.grammar, sample, sampleTarget, sampleCap, sg.maxSteps);
    Plan plan = planEntry(profile, sample, entry.plants, target, l.cap, l.capFromDevice, sg.maxSteps, e.stride);
    e.steps = plan.steps;
    e.expectedModules = plan.expectedModules;
    e.stringTrafficBytes = plan.stringTrafficBytes;
    e.targetReached = plan.targetReached;
    e.note = plan.note;
    if (!plan.targetReached && plan.note.find("cap") != std::string::npos) {
        report.scaledDown = true;
    }

    progress(fmt::format("{} x{}: {} steps, about {} modules", e.name, e.plants, e.steps, e.expectedModules));
    // The two backends take turns, so that a drift in the machine's speed reaches both alike.
    EntryRuns runs(l.grammar, l.deriver.get(), e);
    runs.run(options, options.runCpu, context && l.deriver);
    if (options.runCpu) {
        e.cpu = runs.cpuResult(e.stringTrafficBytes);
        // A stochastic grammar's plants differ: rescale the traffic estimate to the real string size.
        if (e.cpu.ok() && e.expectedModules > 0 && e.cpu.modules != e.expectedModules) {
            double scale = static_cast<double>(e.cpu.modules) / static_cast<double>(e.expectedModules);
            e.stringTrafficBytes = static_cast<std::uint64_t>(static_cast<double>(e.stringTrafficBytes) * scale);
            finish(e.cpu, e.stringTrafficBytes);
        }
    }
    if (!context) {
        e.gpu = failed(options.runGpu ? "unavailable" : "skipped", report.gpuNote);
    } else if (!l.deriver) {
        e.gpu = failed(l.gpuStatus, l.gpuReason);
    } else {
        e.gpu = runs.gpuResult();
        if (e.gpu.ok() && report.copy && report.copy->bytesPerSecond > 0) {
            e.gpu.copyFraction = e.gpu.bytesPerSecond / report.copy->bytesPerSecond;
        }
        if (e.gpu.ok() && e.cpu.ok() && e.gpu.modules != e.cpu.modules) {
            e.gpu.status = "failed";
            e.gpu.reason =
                fmt::format("the GPU derived {} modules, the CPU reference {}", e.gpu.modules, e.cpu.modules);
        }
    }
    auto rate = [](const BackendResult& r) {
        return r.ok() ? fmt::format("{:.3g} modules/s", r.modulesPerSecond) : r.status;
    };
    progress(fmt::format("{} x{}: CPU {}, GPU {}", e.name, e.plants, rate(e.cpu), rate(e.gpu)));
    return e;
}

} // namespace

BenchReport runBenchmark(const BenchOptions& options, const std::function<void(const std::string&)>& progress) {
    BenchReport report;
    report.options = options;
    if (options.repeat < 1) {
        throw std::invalid_argument("--repeat must be at least 1");
    }
    std::unique_ptr<vk::Context> context = openDevice(options, report, progress);

    std::uint64_t target = options.quick ? std::min(options.targetModules, kQuickTargetModules) : options.targetModules;
    std::vector<SuiteEntry> suite = benchSuite(options.quick);
    for (const std::string& name : options.grammars) {
        if (std::none_of(suite.begin(), suite.end(), [&](const SuiteEntry& e) { return e.grammar.name == name; })) {
            throw std::invalid_argument(fmt::format("no suite grammar named '{}'", name));
        }
    }
    // One grammar at a time (the suite lists a grammar's entries together), so that the GPU memory of the
    // previous grammar is released before the next one grows.
    std::string loadedName;
    std::unique_ptr<LoadedGrammar> loaded;
    for (const SuiteEntry& entry : suite) {
        const SuiteGrammar& sg = entry.grammar;
        if (!options.grammars.empty() &&
            std::find(options.grammars.begin(), options.grammars.end(), sg.name) == options.grammars.end()) {
            continue;
        }
        if (!loaded || loadedName != sg.name) {
            loaded.reset();
            loaded = loadSuiteGrammar(sg, options, context.get(), report);
            loadedName = sg.name;
        }
        report.entries.push_back(runEntry(entry, *loaded, options, context.get(), target, report, progress));
    }
    if (report.scaledDown) {
        report.notes.push_back(fmt::format(
            "scaled down: some entries stop below {} modules because of this machine's memory or the device's "
            "largest storage buffer ({} MiB)",
            target, report.maxStorageBufferRange >> 20));
    }
    if (options.quick) {
        report.notes.push_back(fmt::format("quick suite: {} modules per entry at most, 1 and 10 plants", target));
    }
    return report;
}

} // namespace simeco::bench
