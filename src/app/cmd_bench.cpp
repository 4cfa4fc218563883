// `simeco bench`: derivation throughput of the GPU backend and the CPU reference on a fixed suite, with the
// device's copy bandwidth measured in the same run; `--render`: the turtle and frame times (docs/BENCHMARKS.md).
#include <cstdio>
#include <stdexcept>

#include <fmt/format.h>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "app/error_report.h"
#include "bench/render_bench.h"
#include "bench/report.h"
#include "bench/runner.h"
#include "bench/sim_bench.h"
#include "bench/suite.h"

namespace simeco::app {
namespace {

struct BenchArgs {
    bench::BenchOptions options;
    std::string json;
    bool noCpu = false;
    bool noGpu = false;
    bool render = false;
    bool sim = false;
    std::string size = "640x480";
    std::uint32_t msaa = 0; // --render, --sim: samples a pixel; 0: as the viewer draws them
    std::vector<std::uint32_t> fields; // --sim: the fields' plants
};

// --size as the render and growth benchmarks take it.
void frameSize(const std::string& size, std::uint32_t& width, std::uint32_t& height) {
    char x = 0;
    if (std::sscanf(size.c_str(), "%u%c%u", &width, &x, &height) != 3 || x != 'x' || width == 0 || height == 0 ||
        width > 16384 || height > 16384)
        throw CommandLineError(fmt::format("--size '{}': expected WIDTHxHEIGHT, each 1 to 16384", size));
}

void runSimBench(const BenchArgs& args) {
    bench::SimBenchOptions o;
    o.root = args.options.root.empty() ? bench::defaultSuiteRoot() : args.options.root;
    o.quick = args.options.quick;
    o.repeat = args.options.repeat;
    o.warmUp = args.options.warmUp;
    o.device = args.options.device;
    if (!args.fields.empty()) o.fields = args.fields;
    frameSize(args.size, o.width, o.height);
    o.samples = args.msaa;
    bench::SimBenchReport report =
        bench::runSimBenchmark(o, [](const std::string& line) { std::fprintf(stderr, "bench: %s\n", line.c_str()); });
    if (!args.json.empty()) bench::writeJsonAtomically(args.json, bench::simReportJson(report));
    std::fputs(bench::formatSimTable(report).c_str(), stdout);
}

void runRenderBench(const BenchArgs& args) {
    bench::RenderBenchOptions o;
    o.root = args.options.root;
    o.quick = args.options.quick;
    o.repeat = args.options.repeat;
    o.warmUp = args.options.warmUp;
    o.maxModules = args.options.maxModules;
    o.device = args.options.device;
    o.runCpu = !args.noCpu;
    frameSize(args.size, o.width, o.height);
    o.samples = args.msaa;
    bench::RenderBenchReport report = bench::runRenderBenchmark(
        o, [](const std::string& line) { std::fprintf(stderr, "bench: %s\n", line.c_str()); });
    if (!args.json.empty()) bench::writeJsonAtomically(args.json, bench::renderReportJson(report));
    std::fputs(bench::formatRenderTable(report).c_str(), stdout);
}

void runBench(BenchArgs args) {
    if (args.render && args.sim) throw CommandLineError("--render and --sim are benchmarks of their own: pick one");
    if ((args.render || args.sim) && args.noGpu)
        throw CommandLineError(fmt::format("{} measures the device: it cannot run with --no-gpu",
                                           args.render ? "--render" : "--sim"));
    if (!args.fields.empty() && !args.sim) throw CommandLineError("--fields sizes the fields of --sim only");
    if (args.msaa != 0 && !args.render && !args.sim)
        throw CommandLineError("--msaa sets the frames of --render and --sim only");
    if (args.render) return runRenderBench(args);
    if (args.sim) return runSimBench(args);
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
    cmd->add_flag("--render", args->render,
                  "benchmark the turtle (kernels and CPU reference) and frames with and without shadow volumes on "
                  "fields of 1 to 10,000 plants instead of derivation");
    cmd->add_flag("--sim", args->sim,
                  "benchmark the growing field (derive, grow, interpret, statistics and a frame per tick) of the "
                  "garden at 100, 1,000 and 10,000 plants instead of derivation");
    cmd->add_option("--size", args->size, "--render, --sim: frame size WIDTHxHEIGHT (default 640x480)");
    cmd->add_option("--msaa", args->msaa,
                    "--render, --sim: samples a pixel of the frames (default: as the viewer draws them, 1 on a CPU "
                    "device, else 4)")
        ->check(CLI::IsMember({1u, 2u, 4u, 8u, 16u}));
    cmd->add_option("--fields", args->fields,
                    "--sim: the fields' plants, comma-separated (default 100,1000,10000; --quick 10,100), e.g. "
                    "10000,1000000 on a large GPU")
        ->delimiter(',')
        ->check(CLI::Range(1u, 1000000u));
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runBench(*args); }); });
}

} // namespace simeco::app
