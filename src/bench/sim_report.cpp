#include <fmt/format.h>

#include "bench/report.h"
#include "bench/sim_bench.h"
#include "export/organ_geometry.h"

namespace simeco::bench {

nlohmann::json simReportJson(const SimBenchReport& report) {
    const SimBenchOptions& o = report.options;
    nlohmann::json j;
    j["tool"] = "simeco bench --sim";
    j["settings"] = frameBenchSettings(o.quick, o.repeat, o.warmUp, o.width, o.height, o.samples);
    j["settings"]["scene"] = report.scene;
    j["settings"]["timer"] = "host wall clock around each blocking stage";
    j["device"] = {{"name", report.deviceName}, {"type", report.deviceType}, {"driver", report.driver}};
    if (report.copy)
        j["copy_bandwidth"] = copyBandwidthSummary(*report.copy);
    j["bytes_per_particle"] = report.bytesPerParticle;
    j["grow_bytes_per_particle"] = report.growBytesPerParticle;
    nlohmann::json entries = nlohmann::json::array();
    for (const SimEntry& e : report.entries) {
        nlohmann::json entry = {{"plants", e.plants}, {"status", e.status}};
        if (e.status != "ok") {
            entry["reason"] = e.reason;
        } else {
            entry["batches"] = e.batches;
            entry["simulated_time"] = e.time;
            entry["particles"] = e.modules;
            entry["organs"] = e.organs;
            entry["tick_seconds"] = e.tickSeconds;
            entry["median_tick_seconds"] = e.medianTickSeconds;
            entry["ticks_per_second"] = e.ticksPerSecond;
            entry["particles_per_second"] = e.particlesPerSecond;
            entry["grow_bytes_per_second"] = e.growBytesPerSecond;
            entry["grow_copy_bandwidth_fraction"] = e.copyFraction;
            if (!e.notDrawn.empty()) entry["not_drawn"] = e.notDrawn;
            entry["stage_median_seconds"] = {{"derive", e.stages.derive},
                                             {"grow", e.stages.grow},
                                             {"interpret", e.stages.interpret},
                                             {"light", e.stages.light},
                                             {"statistics", e.stages.statistics},
                                             {"draw", e.stages.draw}};
            if (e.notDrawn.empty()) {
                entry["frame_median_seconds"] = {{"shadow_volumes", e.frameShadowsSeconds},
                                                 {"no_shadows", e.frameNoShadowsSeconds}};
                entry["growing_frames_per_second"] = {{"shadow_volumes", e.growingFramesPerSecondShadows},
                                                      {"no_shadows", e.growingFramesPerSecondNoShadows}};
                entry["real_time_frames_per_second"] = {{"shadow_volumes", e.realTimeFramesPerSecondShadows},
                                                        {"no_shadows", e.realTimeFramesPerSecondNoShadows}};
                nlohmann::json near, far;
                for (std::uint32_t kind = 0; kind < shared::kOrganKinds; ++kind) {
                    near[exporter::organKindName(kind)] = e.drawnNear[kind];
                    far[exporter::organKindName(kind)] = e.drawnFar[kind];
                }
                entry["drawn_organs"] = {{"near", near}, {"far", far}};
                entry["shadow_volumes"] = e.shadowVolumes;
            }
        }
        entries.push_back(std::move(entry));
    }
    j["entries"] = std::move(entries);
    return j;
}

std::string formatSimTable(const SimBenchReport& report) {
    std::string out = fmt::format("simeco bench --sim: {} on {} ({}); {} bytes of state per particle\n", report.scene,
                                  report.deviceName, report.deviceType, report.bytesPerParticle);
    if (report.copy) out += fmt::format("copy bandwidth: {:.2f} GB/s\n", report.copy->bytesPerSecond * 1e-9);
    out += fmt::format("frames {} x {}, {} sample(s) a pixel\n", report.options.width, report.options.height,
                       report.options.samples);
    out += fmt::format("{:>7} {:>7} {:>10} {:>9} {:>12} {:>9} {:>9} {:>10} {:>10} {:>9} {:>9} {:>8}\n", "plants",
                       "batches", "particles", "ticks/s", "particles/s", "copy", "derive", "grow", "interpret", "light",
                       "stats", "draw");
    for (const SimEntry& e : report.entries) {
        if (e.status != "ok") {
            out += fmt::format("{:>7} failed: {}\n", e.plants, e.reason);
            continue;
        }
        out += fmt::format("{:>7} {:>7} {:>10} {:>9.3f} {:>12.3g} {:>8.1f}% {:>8.3f}s {:>9.3f}s {:>9.3f}s {:>8.3f}s "
                           "{:>8.3f}s {:>7.3f}s\n",
                           e.plants, e.batches, e.modules, e.ticksPerSecond, e.particlesPerSecond,
                           100.0 * e.copyFraction, e.stages.derive, e.stages.grow, e.stages.interpret, e.stages.light,
                           e.stages.statistics, e.stages.draw);
        if (!e.notDrawn.empty())
            out += fmt::format("{:>7} not drawn: {}\n", "", e.notDrawn);
        else
            out += fmt::format("{:>7} a frame: {:.3f} s with shadow volumes, {:.3f} s without; growing a tick a frame: "
                               "{:.2f} and {:.2f} frames/s; at real time: {:.2f} and {:.2f} frames/s\n",
                               "", e.frameShadowsSeconds, e.frameNoShadowsSeconds, e.growingFramesPerSecondShadows,
                               e.growingFramesPerSecondNoShadows, e.realTimeFramesPerSecondShadows,
                               e.realTimeFramesPerSecondNoShadows);
        if (e.notDrawn.empty()) {
            std::uint64_t near = 0, far = 0;
            for (std::uint32_t kind = 0; kind < shared::kOrganKinds; ++kind) {
                near += e.drawnNear[kind];
                far += e.drawnFar[kind];
            }
            out += fmt::format("{:>7} organs drawn: {} with the finer meshes, {} with the coarser; {} shadow volumes\n",
                               "", near, far, e.shadowVolumes);
        }
    }
    return out;
}

} // namespace simeco::bench
