// The benchmark's outputs: the JSON report (written atomically), and the table printed on stdout.
#pragma once

#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "bench/runner.h"

namespace simeco::bench {

nlohmann::json reportJson(const BenchReport& report);

// The settings the benchmarks that draw frames (--render, --sim) share: their runs, and their frames' size and
// samples a pixel; each adds its own.
nlohmann::json frameBenchSettings(bool quick, int repeat, int warmUp, std::uint32_t width, std::uint32_t height,
                                  std::uint32_t samples);

// Writes `json` to a temporary file beside `path`, then renames it over `path`: readers never see half a file.
// Throws std::runtime_error when the file cannot be written.
void writeJsonAtomically(const std::string& path, const nlohmann::json& json);

// The human-readable summary: one row per entry, GPU throughput as a ratio to the CPU reference and to the
// copy bandwidth measured in the same run.
std::string formatTable(const BenchReport& report);

} // namespace simeco::bench
