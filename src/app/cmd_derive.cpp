// `simeco derive`: derive a grammar and print the string, statistics or JSON.
#include <chrono>
#include <cstdio>
#include <optional>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/error_report.h"
#include "app/field_options.h"
#include "cpu/derive.h"
#include "field/field.h"
#include "gpu/derive_gpu.h"
#include "gpu/stream_statistics.h"
#include "stream/statistics.h"
#include "vk/context.h"
#include "vk/kernel_profile.h"

namespace simeco::app {

namespace {

struct DeriveArgs {
    std::string file;
    int steps = -1;
    int64_t seed = -1;
    uint32_t plants = 0; // 0: one plant per grammar (each species of a scene once)
    field::Backend backend = field::Backend::Cpu;
    std::string format = "string";
    uint64_t maxModules = 0;
    double maxSeconds = stream::kDefaultMaxSeconds;
    std::string device;
    std::string strategy = "auto";
    bool profile = false;
};

void runDerive(const DeriveArgs& args) {
    std::vector<ir::Grammar> species = field::loadSpecies(args.file);
    const ir::Alphabet& alphabet = species.front().alphabet;
    stream::DeriveOptions options;
    options.steps = args.steps;
    options.seed = args.seed;
    options.plants = args.plants ? args.plants : static_cast<uint32_t>(species.size());
    options.maxModules = args.maxModules;
    options.maxSeconds = args.maxSeconds;
    auto start = std::chrono::steady_clock::now();
    stream::DeriveResult result;
    std::optional<stream::StringStatistics> total; // counted on the device, where the string stays
    double seconds = 0;
    if (args.backend == field::Backend::Gpu) {
        vk::ContextOptions contextOptions;
        contextOptions.device = args.device;
        vk::Context context(contextOptions);
        if (args.profile) context.enableKernelProfile();
        gpu::GpuStrategy strategy = args.strategy == "parallel"     ? gpu::GpuStrategy::Parallel
                                    : args.strategy == "sequential" ? gpu::GpuStrategy::Sequential
                                                                    : gpu::GpuStrategy::Auto;
        gpu::GpuDeriver deriver(context, species, strategy);
        gpu::GpuDeriveStats stats;
        // Only a printed string comes back to the host; statistics are counted where the string is.
        bool readBack = args.format == "string";
        result = deriver.derive(options, readBack, &stats);
        seconds = stats.seconds;
        if (!readBack) {
            auto counting = std::chrono::steady_clock::now();
            total = gpu::StreamStatistics(context).compute(deriver.lastString(), alphabet);
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - counting).count();
        }
        if (args.profile) std::fputs(context.kernelProfile()->table().c_str(), stderr);
    } else {
        result = cpu::deriveSpeciesCpu(species, options);
        seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }

    // Everything is derived before anything is printed: an error leaves no partial output.
    const stream::ModuleString& s = result.string;
    if (args.format == "string") {
        std::string out;
        for (size_t p = 0; p < s.plants(); ++p) {
            out += stream::formatModules(s, alphabet, s.plantStart[p], s.plantStart[p + 1]);
            out.push_back('\n');
        }
        std::fwrite(out.data(), 1, out.size(), stdout);
        return;
    }
    if (!total) total = stream::computeStatistics(s, alphabet);
    if (args.format == "stats") {
        std::printf("modules: %llu\n", static_cast<unsigned long long>(total->modules));
        std::printf("plants: %llu\n", static_cast<unsigned long long>(total->plants));
        std::printf("steps: %d\n", result.steps);
        std::printf("max branch depth: %d\n", total->maxBranchDepth);
        std::printf("time: %.6f s\n", seconds);
        std::printf("symbols:\n");
        for (const auto& [name, count] : total->perSymbol)
            std::printf("  %s %llu\n", name.c_str(), static_cast<unsigned long long>(count));
        return;
    }
    nlohmann::json j;
    j["file"] = args.file;
    j["backend"] = field::backendName(args.backend);
    j["modules"] = total->modules;
    j["plants"] = total->plants;
    j["steps"] = result.steps;
    j["max_branch_depth"] = total->maxBranchDepth;
    j["seconds"] = seconds;
    j["symbols"] = total->perSymbol;
    std::printf("%s\n", j.dump(2).c_str());
}

} // namespace

void registerDeriveCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<DeriveArgs>();
    CLI::App* cmd = app.add_subcommand("derive", "Derive an L-system (.l, .lsys) or the plants of a SimEco scene (.eco)");
    cmd->add_option("file", args->file, "grammar file")->required();
    cmd->add_option("-n,--steps", args->steps, "derivation steps (default: the file's derivation length)")
        ->check(CLI::Range(0, 1000000));
    cmd->add_option("--seed", args->seed, "seed of the random streams (default: the file's seed, else 0)")
        ->check(CLI::Range(int64_t(0), int64_t(UINT32_MAX)));
    cmd->add_option("--plants", args->plants,
                    "number of plants derived together; a scene's species take turns (default: one of each)")->check(CLI::Range(1u, 1000000u));
    addBackendOption(*cmd, args->backend, "cpu or gpu");
    cmd->add_option("--format", args->format, "string, stats or json")
        ->check(CLI::IsMember({"string", "stats", "json"}));
    cmd->add_option("--max-modules", args->maxModules, "module budget (default: sized to this machine's memory)");
    addTimeLimitOption(*cmd, args->maxSeconds);
    cmd->add_option("--device", args->device, "Vulkan device for --backend gpu: an index or a name part (see `simeco devices`)");
    cmd->add_option("--gpu-strategy", args->strategy,
                    "parallel (every module at once), sequential (one invocation per plant, for grammars whose "
                    "productions write globals) or auto")
        ->check(CLI::IsMember({"auto", "parallel", "sequential"}));
    cmd->add_flag("--profile", args->profile,
                  "--backend gpu: print the GPU time of every kernel, summed over the derivation, to stderr");
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runDerive(*args); }); });
}

} // namespace simeco::app
