// `simeco view`: grow a field live in a window and tune its environment while it grows.
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/default_scene.h"
#include "app/error_report.h"
#include "app/field_options.h"
#include "app/render_options.h"
#include "view/view_controls.h"
#include "view/viewer.h"
#include "view/window.h"

namespace simeco::app {

namespace {

namespace fs = std::filesystem;

struct ViewArgs {
    view::ViewOptions view;
    PictureOptions picture;
};

void runView(ViewArgs args) {
    view::ViewOptions& v = args.view;
    field::SimulationOptions& s = v.simulation;
    if (s.file.empty()) { // the built-in garden
        s.file = kDefaultSceneName;
        s.sceneText = kDefaultSceneText;
        if (s.plants == 0) s.plants = kDefaultViewPlants;
    }
    if (!v.screenshot.empty()) {
        const std::string ext = fs::path(v.screenshot).extension().string();
        if (ext != ".png" && ext != ".exr")
            throw CommandLineError(fmt::format("--screenshot: '{}' is neither a .png nor an .exr", v.screenshot));
    }
    const auto [width, height] = imageSize(args.picture.size);
    v.width = width;
    v.height = height;
    const PictureOptions picture = args.picture;
    v.settingsFor = [picture](const field::Simulation& simulation) {
        return grownFieldSettings(picture, simulation.species());
    };
    try {
        view::runViewer(v);
    } catch (const view::SettingError& e) {
        throw CommandLineError(e.what());
    }
}

} // namespace

void registerViewCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<ViewArgs>();
    CLI::App* cmd = app.add_subcommand("view", "Grow a field live in a window and tune its environment as it grows");
    field::SimulationOptions& s = args->view.simulation;
    cmd->add_option("scene", s.file,
                    fmt::format("scene (.eco) or grammar (.l, .lsys), reloaded when it changes on disk; none: the "
                                "built-in garden, {} plants of {}",
                                kDefaultViewPlants, kDefaultSceneName));
    cmd->add_option("--frames", args->view.frames,
                    "close after drawing N frames, each growing the field time_scale simulated seconds, so that it "
                    "grows alike on every device (default: when the window closes)")
        ->excludes(cmd->add_option("--seconds", args->view.seconds,
                                   "close after S seconds, the field growing by the clock as it does in a window left "
                                   "open (default: when the window closes)")
                       ->check(CLI::Range(0.0, 1e6)));
    cmd->add_option("--time", args->view.startTime, "simulated seconds the field grows before the first frame")
        ->check(CLI::Range(0.0, 1e6));
    cmd->add_option("--screenshot", args->view.screenshot,
                    "write the last frame to FILE (.png or .exr); also where the panel's screenshot button writes");
    cmd->add_option("--set", args->view.settings,
                    fmt::format("set a panel value, name=value (repeatable): {}", view::settingNames()));
    cmd->add_option("--seed", s.seed, "seed of the random streams (default: the file's seed, else 0)")
        ->check(CLI::Range(int64_t(0), int64_t(UINT32_MAX)));
    cmd->add_option("--plants", s.plants, "plants in the field; a scene's species take turns (default: the scene's)")
        ->check(CLI::Range(1u, 1000000u));
    addDensityOption(*cmd, s.density);
    cmd->add_option("--dt", s.dt, "simulated seconds per tick (default 1)")->check(CLI::Range(1e-3, 1e6));
    args->picture.size = "1280x720";
    addPictureOptions(*cmd, args->picture, "field");
    addColormapOption(*cmd, s.colormap);
    addBackendOption(*cmd, s.backend, "derivation, growth and turtle: gpu (compute kernels) or cpu (references)");
    cmd->add_option("--max-modules", s.maxModules, "module budget (default: sized to this machine's memory)");
    cmd->add_option("--device", args->view.device, "Vulkan device: an index or a name part (see `simeco devices`)");
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runView(*args); }); });
}

} // namespace simeco::app
