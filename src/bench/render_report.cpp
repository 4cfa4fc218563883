#include <fmt/format.h>

#include "bench/render_bench.h"
#include "bench/report.h"

namespace simeco::bench {
namespace {

nlohmann::json timedJson(const Timed& t) {
    return {{"median_seconds", t.medianSeconds}, {"run_seconds", t.runSeconds},
            {"instances_per_second", t.instancesPerSecond}};
}

std::string rate(double perSecond) {
    if (perSecond >= 1e6) return fmt::format("{:.2f} M", perSecond * 1e-6);
    if (perSecond >= 1e3) return fmt::format("{:.1f} k", perSecond * 1e-3);
    return fmt::format("{:.0f}", perSecond);
}

} // namespace

nlohmann::json renderReportJson(const RenderBenchReport& report) {
    const RenderBenchOptions& o = report.options;
    nlohmann::json j;
    j["tool"] = "simeco bench --render";
    j["settings"] = frameBenchSettings(o.quick, o.repeat, o.warmUp, o.width, o.height, o.samples);
    j["settings"]["max_modules"] = o.maxModules;
    j["settings"]["grammar"] = report.grammar;
    j["settings"]["cpu_threads"] = 1;
    j["device"] = {{"name", report.deviceName}, {"type", report.deviceType}, {"driver", report.driver}};
    if (report.copy) {
        j["copy_bandwidth"] = copyBandwidthSummary(*report.copy);
    }
    nlohmann::json entries = nlohmann::json::array();
    for (const RenderEntry& e : report.entries) {
        nlohmann::json entry = {{"plants", e.plants}, {"steps", e.steps}, {"modules", e.modules},
                                {"organs", e.organs}, {"status", e.status}};
        if (e.status != "ok") {
            entry["reason"] = e.reason;
        } else {
            entry["gpu_turtle"] = timedJson(e.gpuTurtle);
            entry["gpu_turtle"]["levels"] = e.levels;
            entry["gpu_turtle"]["bytes_moved"] = e.bytesMoved;
            entry["gpu_turtle"]["copy_bandwidth_fraction"] = e.copyFraction;
            if (!e.cpuTurtle.runSeconds.empty()) {
                entry["cpu_turtle"] = timedJson(e.cpuTurtle);
                if (e.cpuTurtle.instancesPerSecond > 0)
                    entry["gpu_turtle_speedup_vs_cpu"] = e.gpuTurtle.instancesPerSecond / e.cpuTurtle.instancesPerSecond;
            }
            entry["frame_shadow_volumes"] = timedJson(e.frameWithShadows);
            entry["frame_no_shadows"] = timedJson(e.frameWithoutShadows);
            entry["tick"] = timedJson(e.tick);
            entry["ticks_in_flight"] = timedJson(e.ticksInFlight);
        }
        entries.push_back(std::move(entry));
    }
    j["entries"] = std::move(entries);
    return j;
}

std::string formatRenderTable(const RenderBenchReport& report) {
    std::string out = fmt::format("device: {} ({}, {})\n", report.deviceName, report.deviceType, report.driver);
    if (report.copy) out += fmt::format("copy bandwidth: {:.2f} GB/s\n", report.copy->bytesPerSecond * 1e-9);
    out += fmt::format("{}, {}x{} frames of {} sample(s) a pixel; medians of {} runs after {} warm-up; CPU turtle = "
                       "reference, one thread\n\n",
                       report.grammar, report.options.width, report.options.height, report.options.samples,
                       report.options.repeat, report.options.warmUp);
    out += fmt::format("{:>6} {:>5} {:>8} {:>8} | {:>12} {:>12} {:>7} {:>7} | {:>10} {:>10} {:>8} {:>9}\n",
                       "plants", "steps", "modules", "organs", "GPU turtle/s", "CPU turtle/s", "vs CPU", "of copy",
                       "frame ms", "no shadow", "tick ms", "in flight");
    for (const RenderEntry& e : report.entries) {
        if (e.status != "ok") {
            out += fmt::format("{:>6} failed: {}\n", e.plants, e.reason);
            continue;
        }
        std::string cpu = e.cpuTurtle.runSeconds.empty() ? "skipped" : rate(e.cpuTurtle.instancesPerSecond);
        std::string vs = e.cpuTurtle.instancesPerSecond > 0
                             ? fmt::format("{:.2f}x", e.gpuTurtle.instancesPerSecond / e.cpuTurtle.instancesPerSecond)
                             : "";
        out += fmt::format(
            "{:>6} {:>5} {:>8} {:>8} | {:>12} {:>12} {:>7} {:>6.1f}% | {:>10.1f} {:>10.1f} {:>8.1f} {:>9.1f}\n",
            e.plants, e.steps, e.modules, e.organs, rate(e.gpuTurtle.instancesPerSecond), cpu, vs, 100 * e.copyFraction,
            1e3 * e.frameWithShadows.medianSeconds, 1e3 * e.frameWithoutShadows.medianSeconds,
            1e3 * e.tick.medianSeconds, 1e3 * e.ticksInFlight.medianSeconds);
    }
    out += "\n'GPU/CPU turtle/s': organ instances written per second of interpretation (wall time, the host\n"
           "waiting for each submission); 'of copy': the turtle kernels' bytes moved per second over the copy\n"
           "bandwidth; 'frame ms': a headless frame with stencil shadow volumes, read back ('no shadow': without);\n"
           "'tick ms': the turtle again and a frame without shadows in one submission, read back (a growth tick);\n"
           "'in flight': the same per tick with two ticks in flight, each into its own target.\n";
    return out;
}

} // namespace simeco::bench
