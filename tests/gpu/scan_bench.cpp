// Scan throughput on the default device (or SIMECO_DEVICE): GPU timestamps around each scan, warm-up runs
// first, median of the timed runs, one JSON object per algorithm on stdout.
// Usage: simeco_scan_bench [count=10000000] [runs=15]
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <numeric>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "gpu/scan.h"
#include "vk/barriers.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/timestamps.h"

namespace {

using simeco::gpu::ScanAlgorithm;
namespace vk = simeco::vk;

constexpr int kWarmUpRuns = 3;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values[values.size() / 2];
}

int benchmark(std::uint32_t count, int runs) {
    vk::ContextOptions options;
    if (const char* device = std::getenv("SIMECO_DEVICE")) {
        options.device = device;
    }
    vk::Context context(options);
    std::vector<std::uint32_t> input(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        input[i] = (i * 2654435761u) >> 28;  // fixed, small values
    }
    std::vector<std::uint32_t> expected(count);
    std::exclusive_scan(input.begin(), input.end(), expected.begin(), std::uint32_t{0});

    vk::Buffer in(context, std::uint64_t{count} * 4, vk::MemoryUsage::DeviceLocal);
    vk::Buffer out(context, std::uint64_t{count} * 4, vk::MemoryUsage::DeviceLocal);
    vk::uploadSpan<std::uint32_t>(context, in, input);
    simeco::gpu::GpuScan scan(context);
    scan.reserve(count);
    vk::Timestamps timestamps(context, 2);

    for (ScanAlgorithm algorithm : {ScanAlgorithm::ReduceThenScan, ScanAlgorithm::DecoupledLookBack}) {
        std::vector<double> ms;
        for (int run = 0; run < kWarmUpRuns + runs; ++run) {
            context.submitAndWait([&](VkCommandBuffer cmd) {
                timestamps.cmdReset(cmd);
                vk::memoryBarrier(cmd, vk::Hazard::TransferToCompute);
                timestamps.cmdWrite(cmd, 0, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
                scan.record(cmd, in, out, count, algorithm);
                timestamps.cmdWrite(cmd, 1, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
            });
            if (run >= kWarmUpRuns) {
                ms.push_back(timestamps.elapsedNs(0, 1) * 1e-6);
            }
        }
        bool correct = vk::downloadVector<std::uint32_t>(context, out, count) == expected;
        double medianMs = median(ms);
        std::printf("%s\n",
                    fmt::format("{{\"device\": \"{}\", \"algorithm\": \"{}\", \"count\": {}, \"runs\": {}, "
                                "\"median_ms\": {:.3f}, \"min_ms\": {:.3f}, \"gelements_per_s\": {:.3f}, "
                                "\"correct\": {}}}",
                                context.deviceInfo().name, simeco::gpu::scanAlgorithmName(algorithm), count, runs,
                                medianMs, *std::min_element(ms.begin(), ms.end()), count / (medianMs * 1e6),
                                correct)
                        .c_str());
        if (!correct) {
            return 1;
        }
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    try {
        std::uint32_t count = argc > 1 ? static_cast<std::uint32_t>(std::stoul(argv[1])) : 10'000'000u;
        int runs = argc > 2 ? std::max(1, std::stoi(argv[2])) : 15;
        return benchmark(count, runs);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "simeco_scan_bench: error: %s\n", e.what());
        return 1;
    }
}
