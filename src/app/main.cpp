// `simeco`: a git-style command line over the simeco libraries.
#include <cstdio>
#include <exception>

#include "app/commands.h"
#include "app/error_report.h"

int main(int argc, char** argv) {
    CLI::App app{"simeco: a GPU plant-ecosystem simulator (L-systems derived, grown and rendered on Vulkan)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "simeco 0.1.0");

    simeco::app::CommandContext ctx;
    simeco::app::registerDeriveCommand(app, ctx);
    simeco::app::registerDevicesCommand(app, ctx);
    simeco::app::registerBenchCommand(app, ctx);
    simeco::app::registerRenderCommand(app, ctx);
    simeco::app::registerExportCommand(app, ctx);
    simeco::app::registerRunCommand(app, ctx);
    simeco::app::registerSkeletonCommand(app, ctx);
    simeco::app::registerInferCommand(app, ctx);
    simeco::app::registerViewCommand(app, ctx);

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int code = app.exit(e);
        return code == 0 ? 0 : simeco::app::kExitBadInput;
    }
    return ctx.exitCode;
}
