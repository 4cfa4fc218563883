// The subcommands of `simeco`. Each lives in its own file and registers itself on the top-level CLI.
#pragma once

#include <CLI/CLI.hpp>

namespace simeco::app {

// Commands set `exitCode` through this when they run; main returns it.
struct CommandContext {
    int exitCode = 0;
};

void registerDeriveCommand(CLI::App& app, CommandContext& ctx);
void registerDevicesCommand(CLI::App& app, CommandContext& ctx);
void registerBenchCommand(CLI::App& app, CommandContext& ctx);
void registerRenderCommand(CLI::App& app, CommandContext& ctx);
void registerExportCommand(CLI::App& app, CommandContext& ctx);
void registerRunCommand(CLI::App& app, CommandContext& ctx);
void registerSkeletonCommand(CLI::App& app, CommandContext& ctx);
void registerInferCommand(CLI::App& app, CommandContext& ctx);
void registerViewCommand(CLI::App& app, CommandContext& ctx);

} // namespace simeco::app
