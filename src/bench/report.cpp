#include "bench/report.h"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

#include <fmt/format.h>
#include <unistd.h>

namespace simeco::bench {
namespace {

nlohmann::json backendJson(const BackendResult& r, bool gpu) {
    nlohmann::json j = {{"status", r.status}};
    if (!r.reason.empty()) {
        j["reason"] = r.reason;
    }
    if (!r.ok()) {
        return j;
    }
    j["modules"] = r.modules;
    j["median_seconds"] = r.medianSeconds;
    j["run_seconds"] = r.runSeconds;
    j["modules_per_second"] = r.modulesPerSecond;
    j["bytes_moved"] = r.bytesMoved;
    j["bytes_per_second"] = r.bytesPerSecond;
    if (gpu) {
        j["compile_seconds"] = r.compileSeconds;
        j["pass_ms"] = r.passMillis;
        j["pass_ms_total"] = r.passMillisTotal;
        j["copy_bandwidth_fraction"] = r.copyFraction;
        j["waits"] = r.waits;
    }
    return j;
}

std::string si(double value, const char* unit) {
    if (value >= 1e9) return fmt::format("{:.2f} G{}", value * 1e-9, unit);
    if (value >= 1e6) return fmt::format("{:.2f} M{}", value * 1e-6, unit);
    if (value >= 1e3) return fmt::format("{:.2f} k{}", value * 1e-3, unit);
    return fmt::format("{:.0f} {}", value, unit);
}

std::string count(std::uint64_t n) {
    if (n >= 10'000'000) return fmt::format("{:.1f}M", static_cast<double>(n) * 1e-6);
    if (n >= 100'000) return fmt::format("{:.0f}k", static_cast<double>(n) * 1e-3);
    return fmt::format("{}", n);
}

} // namespace

nlohmann::json frameBenchSettings(bool quick, int repeat, int warmUp, std::uint32_t width, std::uint32_t height,
                                  std::uint32_t samples) {
    return {{"quick", quick},   {"repeat", repeat},   {"warm_up", warmUp},    {"width", width},
            {"height", height}, {"samples", samples}, {"statistic", "median"}};
}

nlohmann::json reportJson(const BenchReport& report) {
    const BenchOptions& o = report.options;
    nlohmann::json j;
    j["tool"] = "simeco bench";
    j["settings"] = {{"quick", o.quick},
                     {"repeat", o.repeat},
                     {"warm_up", o.warmUp},
                     {"target_modules", o.quick ? std::min(o.targetModules, kQuickTargetModules) : o.targetModules},
                     {"max_modules", o.maxModules},
                     {"statistic", "median"},
                     {"cpu_threads", 1}};
    j["device"] = {{"name", report.deviceName},
                   {"type", report.deviceType},
                   {"driver", report.driver},
                   {"max_storage_buffer_range", report.maxStorageBufferRange}};
    if (!report.gpuNote.empty()) {
        j["device"]["note"] = report.gpuNote;
    }
    if (report.copy) {
        const CopyBandwidth& c = *report.copy;
        j["copy_bandwidth"] = {
            {"buffer_bytes", c.bufferBytes},        {"bytes_per_copy", 2 * c.bufferBytes},
            {"median_ms", c.medianMillis},          {"run_ms", c.runMillis},
            {"bytes_per_second", c.bytesPerSecond}, {"timer", c.timestamps ? "gpu timestamps" : "host wall clock"},
            {"kernel", c.kernel},                   {"other_kernel_bytes_per_second", c.otherBytesPerSecond}};
    } else {
        j["copy_bandwidth"] = nullptr;
    }
    j["scaled_down"] = report.scaledDown;
    j["notes"] = report.notes;
    nlohmann::json entries = nlohmann::json::array();
    for (const EntryResult& e : report.entries) {
        nlohmann::json entry = {{"name", e.name},
                                {"file", e.file},
                                {"kind", e.kind},
                                {"plants", e.plants},
                                {"steps", e.steps},
                                {"stride", e.stride},
                                {"expected_modules", e.expectedModules},
                                {"string_traffic_bytes", e.stringTrafficBytes},
                                {"target_reached", e.targetReached},
                                {"cpu", backendJson(e.cpu, false)},
                                {"gpu", backendJson(e.gpu, true)}};
        if (!e.note.empty()) {
            entry["note"] = e.note;
        }
        if (e.cpu.ok() && e.gpu.ok() && e.cpu.modulesPerSecond > 0) {
            entry["gpu_speedup_vs_cpu"] = e.gpu.modulesPerSecond / e.cpu.modulesPerSecond;
        }
        entries.push_back(std::move(entry));
    }
    j["entries"] = std::move(entries);
    return j;
}

void writeJsonAtomically(const std::string& path, const nlohmann::json& json) {
    std::filesystem::path target(path);
    std::filesystem::path temporary = target;
    temporary += fmt::format(".tmp{}", static_cast<long>(getpid()));
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << json.dump(2) << '\n';
        out.flush();
        if (!out) {
            std::error_code ignored;
            std::filesystem::remove(temporary, ignored);
            throw std::runtime_error(fmt::format("cannot write {}", temporary.string()));
        }
    }
    std::error_code error;
    std::filesystem::rename(temporary, target, error);
    if (error) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw std::runtime_error(fmt::format("cannot write {}: {}", path, error.message()));
    }
}

std::string formatTable(const BenchReport& report) {
    std::string out;
    if (!report.deviceName.empty()) {
        out += fmt::format("device: {} ({}, {})\n", report.deviceName, report.deviceType, report.driver);
    }
    if (report.copy) {
        out += fmt::format("copy bandwidth: {}/s (compute copy of {} MiB reading a {}, read + write, median of {}; "
                           "the other kernel: {}/s)\n",
                           si(report.copy->bytesPerSecond, "B"), report.copy->bufferBytes >> 20, report.copy->kernel,
                           report.copy->runMillis.size(), si(report.copy->otherBytesPerSecond, "B"));
    }
    if (!report.gpuNote.empty()) {
        out += fmt::format("GPU backend: {}\n", report.gpuNote);
    }
    out += fmt::format("medians of {} runs after {} warm-up; CPU = reference engine, one thread\n\n",
                       report.options.repeat, report.options.warmUp);
    out += fmt::format("{:<11} {:>6} {:>5} {:>8} | {:>13} {:>11} | {:>13} {:>11} {:>7} {:>7} {:>9}\n", "grammar",
                       "plants", "steps", "modules", "CPU modules/s", "CPU bytes/s", "GPU modules/s", "GPU bytes/s",
                       "vs CPU", "of copy", "pass ms");
    for (const EntryResult& e : report.entries) {
        std::uint64_t modules = e.cpu.ok() ? e.cpu.modules : e.gpu.ok() ? e.gpu.modules : e.expectedModules;
        std::string cpuRate = e.cpu.ok() ? si(e.cpu.modulesPerSecond, "") : e.cpu.status;
        std::string cpuBytes = e.cpu.ok() ? si(e.cpu.bytesPerSecond, "B") : "";
        std::string gpuRate = e.gpu.ok() ? si(e.gpu.modulesPerSecond, "") : e.gpu.status;
        std::string gpuBytes, vsCpu, ofCopy, pass;
        if (e.gpu.ok()) {
            gpuBytes = si(e.gpu.bytesPerSecond, "B");
            vsCpu = e.cpu.ok() ? fmt::format("{:.2f}x", e.gpu.modulesPerSecond / e.cpu.modulesPerSecond) : "";
            ofCopy = report.copy ? fmt::format("{:.1f}%", 100 * e.gpu.copyFraction) : "";
            pass = e.gpu.passMillis.empty() ? "n/a" : fmt::format("{:.2f}", e.gpu.passMillis.back());
        }
        out +=
            fmt::format("{:<11} {:>6} {:>5} {:>8} | {:>13} {:>11} | {:>13} {:>11} {:>7} {:>7} {:>9}\n", e.name,
                        e.plants, e.steps, count(modules), cpuRate, cpuBytes, gpuRate, gpuBytes, vsCpu, ofCopy, pass);
    }
    std::string remarks;
    for (const EntryResult& e : report.entries) {
        if (!e.note.empty()) remarks += fmt::format("  {} x{}: {}\n", e.name, e.plants, e.note);
        if (!e.cpu.ok() && !e.cpu.reason.empty())
            remarks += fmt::format("  {} x{} CPU {}: {}\n", e.name, e.plants, e.cpu.status, e.cpu.reason);
        if (!e.gpu.ok() && !e.gpu.reason.empty() && e.gpu.status != "unavailable")
            remarks += fmt::format("  {} x{} GPU {}: {}\n", e.name, e.plants, e.gpu.status, e.gpu.reason);
    }
    out += "\n'vs CPU': GPU modules/s over CPU modules/s; 'of copy': GPU bytes/s over the copy bandwidth;\n"
           "'pass ms': GPU time of the last derivation step (timestamps). CPU bytes are the module stream each step\n"
           "reads and writes; GPU bytes are what its passes read and write.\n";
    if (!remarks.empty()) {
        out += "\nnotes:\n" + remarks;
    }
    for (const std::string& note : report.notes) {
        out += fmt::format("note: {}\n", note);
    }
    return out;
}

} // namespace simeco::bench
