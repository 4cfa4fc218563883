// `simeco bench`: derivation throughput of the GPU backend and the CPU reference on a fixed suite, with the
// device's copy bandwidth measured in the same run (see docs/BENCHMARKS.md).
#include <cstdio>
#include <memory>
#include <string>

#include "app/commands.h"
#include "app/error_report.h"
#include "bench/report.h"
#include "bench/runner.h"

namespace simeco::app {
namespace {

struct BenchArgs {
    bench::BenchOptions options;
    std::string json;
    bool noCpu = false;
    bool noGpu = false;
};

void runBench(BenchArgs args) {
    if (args.options.root.empty()) {
        args.options.root = bench::defaultSuiteRoot();
    }
    args.options.runCpu = !args.noCpu;
    args.options.runGpu = !args.noGpu;
    bench::BenchReport report = bench::runBenchmark(
        args.options, [](const std::string& line) { std::fprintf(stderr, "bench: %s\n", line.c_str()); });
    if (!args.json.empty()) {
        bench::writeJsonAtomically(args.json, bench::reportJson(report));
    }
    std::fputs(bench::formatTable(report).c_str(), stdout);
}

} // namespace

void registerBenchCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<BenchArgs>();
    CLI::App* cmd = app.add_subcommand("bench", "Benchmark derivation throughput: GPU backend, CPU reference and "
                                                "the device's copy bandwidth on a fixed suite");
    cmd->add_option("--repeat", args->options.repeat, "timed runs per entry and backend (median reported)")
        ->check(CLI::Range(1, 1000));
    cmd->add_option("--warm-up", args->options.warmUp, "untimed runs before them")->check(CLI::Range(0, 100));
    cmd->add_option("--json", args->json, "also write the results as JSON to this file");
    cmd->add_flag("--quick", args->options.quick, "a tiny suite (1 and 10 plants, small strings) for smoke tests");
    cmd->add_option("--target-modules", args->options.targetModules,
                    "grow every entry until all its plants together have this many modules")
        ->check(CLI::Range(uint64_t(1), uint64_t(1) << 40));
    cmd->add_option("--max-modules", args->options.maxModules,
                    "cap on an entry's string (default: sized to memory and the device's largest buffer)");
    cmd->add_option("--grammar", args->options.grammars,
                    "only these suite grammars: abop-1.24d, abop-2.6, abop-1.31a, abop-1.27, lantana");
    cmd->add_option("--root", args->options.root, "folder holding grammars/ and scenes/ (default: simeco's sources)");
    cmd->add_option("--device", args->options.device, "Vulkan device: an index or a name part (see `simeco devices`)");
    cmd->add_flag("--no-cpu", args->noCpu, "skip the CPU reference");
    cmd->add_flag("--no-gpu", args->noGpu, "skip the GPU backend and the copy bandwidth");
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runBench(*args); }); });
}

} // namespace simeco::app
