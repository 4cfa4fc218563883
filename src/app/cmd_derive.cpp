// `simeco derive`: derive a grammar and print the string, statistics or JSON.
#include <chrono>
#include <cstdio>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/error_report.h"
#include "cpu/derive.h"
#include "cpu/statistics.h"
#include "lang/load_grammar.h"

namespace simeco::app {

namespace {

struct DeriveArgs {
    std::string file;
    int steps = -1;
    int64_t seed = -1;
    uint32_t plants = 1;
    std::string backend = "cpu";
    std::string format = "string";
    uint64_t maxModules = 0;
};

void runDerive(const DeriveArgs& args) {
    ir::Grammar g = lang::loadGrammarFile(args.file);
    if (args.backend != "cpu")
        throw std::runtime_error("the gpu backend is not available in this build; use --backend cpu");
    cpu::DeriveOptions options;
    options.steps = args.steps;
    options.seed = args.seed;
    options.plants = args.plants;
    options.maxModules = args.maxModules;
    auto start = std::chrono::steady_clock::now();
    cpu::DeriveResult result = cpu::deriveCpu(g, options);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const cpu::ModuleString& s = result.string;

    if (args.format == "string") {
        for (size_t p = 0; p < s.plants(); ++p) {
            std::string line = cpu::formatModules(s, g.alphabet, s.plantStart[p], s.plantStart[p + 1]);
            std::fwrite(line.data(), 1, line.size(), stdout);
            std::fputc('\n', stdout);
        }
        return;
    }
    cpu::StringStatistics stats = cpu::computeStatistics(s, g.alphabet);
    if (args.format == "stats") {
        std::printf("modules: %llu\n", static_cast<unsigned long long>(stats.modules));
        std::printf("plants: %llu\n", static_cast<unsigned long long>(stats.plants));
        std::printf("steps: %d\n", result.steps);
        std::printf("max branch depth: %d\n", stats.maxBranchDepth);
        std::printf("time: %.6f s\n", seconds);
        std::printf("symbols:\n");
        for (const auto& [name, count] : stats.perSymbol)
            std::printf("  %s %llu\n", name.c_str(), static_cast<unsigned long long>(count));
        return;
    }
    nlohmann::json j;
    j["file"] = args.file;
    j["backend"] = args.backend;
    j["modules"] = stats.modules;
    j["plants"] = stats.plants;
    j["steps"] = result.steps;
    j["max_branch_depth"] = stats.maxBranchDepth;
    j["seconds"] = seconds;
    j["symbols"] = stats.perSymbol;
    std::printf("%s\n", j.dump(2).c_str());
}

} // namespace

void registerDeriveCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<DeriveArgs>();
    CLI::App* cmd = app.add_subcommand("derive", "Derive an L-system (.l, .lsys) or a SimEco scene's plant (.eco)");
    cmd->add_option("file", args->file, "grammar file")->required();
    cmd->add_option("-n,--steps", args->steps, "derivation steps (default: the file's derivation length)")
        ->check(CLI::Range(0, 1000000));
    cmd->add_option("--seed", args->seed, "seed of the random streams (default: the file's seed, else 0)")
        ->check(CLI::Range(int64_t(0), int64_t(UINT32_MAX)));
    cmd->add_option("--plants", args->plants, "number of plants derived together")->check(CLI::Range(1u, 1000000u));
    cmd->add_option("--backend", args->backend, "cpu or gpu")->check(CLI::IsMember({"cpu", "gpu"}));
    cmd->add_option("--format", args->format, "string, stats or json")
        ->check(CLI::IsMember({"string", "stats", "json"}));
    cmd->add_option("--max-modules", args->maxModules, "module budget (default: sized to this machine's memory)");
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runDerive(*args); }); });
}

} // namespace simeco::app
