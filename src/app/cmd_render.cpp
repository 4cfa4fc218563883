// `simeco render`: derive a grammar or scene, interpret it with the turtle, and render the field of plants
// headless to OpenEXR and/or PNG.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/error_report.h"
#include "app/field_options.h"
#include "app/render_options.h"
#include "draw/image_writers.h"
#include "draw/renderer.h"
#include "lang/eco_parser.h"
#include "field/field_parts.h"
#include "field/light_view.h"
#include "field/plant_statistics.h"
#include "field/simulation.h"
#include "turtle/turtle_gpu.h"
#include "vk/context.h"

namespace simeco::app {

namespace {

bool hasExtension(const std::string& path, const char* ext) {
    return std::filesystem::path(path).extension() == ext;
}

struct RenderArgs {
    field::FieldSource source;
    std::string output;
    std::string png;
    PictureOptions picture;
    std::optional<float> lightSlice;     // the light grid's layer at this height, written beside the image
    std::optional<float> lightSection;   // its vertical layer at this depth, written beside the image
    bool lightVolume = false;            // the grid's shade drawn among the plants
    std::optional<float> occupancySlice; // the grid's holders at this height, written beside the image
    uint32_t frames = 0;                 // the growth animated in this many frames; 0: the grown plants only
};

// The light grid of the field drawn: a scene's sun, sky and obstacles, else the defaults.
field::LightVolume fieldLight(const vk::Context& context, const field::Field& field,
                              const std::vector<const turtle::DeviceOrgans*>& organs, const draw::Bounds& bounds,
                              const std::string& file) {
    ir::EcoLight light;
    std::vector<ir::EcoObstacle> obstacles;
    if (hasExtension(file, ".eco")) {
        const ir::EcoScene scene = lang::parseEcoFile(file);
        light = scene.light;
        obstacles = scene.obstacles;
    }
    return field::lightOfOrgans(context, organs, bounds, field.plants, light, obstacles,
                                field::leafShapeAreas(field.assets.models));
}

// The image beside `output` whose name ends in `suffix` in place of the output's extension.
std::string besideOutput(const std::string& output, const std::string& suffix) {
    std::filesystem::path p(output);
    return (p.parent_path() / (p.stem().string() + suffix)).string();
}

// The animation's k-th frame (from 1) beside `output`: NAME-00001.EXT.
std::string frameFile(const std::string& output, uint32_t k) {
    std::filesystem::path p(output);
    return (p.parent_path() / fmt::format("{}-{:05}{}", p.stem().string(), k, p.extension().string())).string();
}

// --frames N: the file grown as `simeco run` grows it, from the axiom through its derivation length, each step's
// segments, spheres and discs growing over the step's time, drawn in N frames evenly spread over the growth from
// a camera framed on the grown plants. Every frame is written, or none.
void renderGrowth(const RenderArgs& args, bool exr) {
    const field::FieldSource& source = args.source;
    if (source.steps >= 0)
        throw CommandLineError("--frames grows the file through its own derivation length: leave out -n");
    field::SimulationOptions options;
    options.file = source.file;
    options.plants = source.plants;
    options.seed = source.seed;
    options.spacing = source.spacing;
    options.maxModules = source.maxModules;
    options.maxSeconds = source.maxSeconds;
    options.backend = source.backend;
    options.colormap = source.colormap;
    vk::ContextOptions contextOptions;
    contextOptions.device = source.device;
    vk::Context context(contextOptions);
    const auto start = std::chrono::steady_clock::now();
    field::Simulation simulation(options, &context);
    simulation.setTickSeconds(float(simulation.grownBy() / args.frames));
    draw::RenderSettings settings = grownFieldSettings(args.picture, simulation.species());
    draw::Renderer renderer(context, simulation.species().assets);
    draw::Bounds framed = simulation.grownBounds();
    if (framed.empty()) framed = draw::Bounds{};
    draw::OutputBatch outputs;
    for (uint32_t k = 1; k <= args.frames; ++k) {
        simulation.tick();
        const draw::Frame frame = renderer.render(field::organParts(simulation.interpretParts()), framed, settings);
        if (exr) draw::writeExr(outputs, frameFile(args.output, k), frame);
        else draw::writePng(outputs, frameFile(args.output, k), frame);
        if (!args.png.empty()) draw::writePng(outputs, frameFile(args.png, k), frame);
    }
    outputs.commit();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %u plants grown for %.1f s in %u frames, %llu modules, %ux%u, %.2f s (%.2f frames/s) -> "
                "%s%s%s\n",
                source.file.c_str(), simulation.standingPlants(), simulation.time(), args.frames,
                static_cast<unsigned long long>(simulation.modules()), settings.width, settings.height, seconds,
                args.frames / seconds, frameFile(args.output, 1).c_str(), args.png.empty() ? "" : ", ",
                args.png.empty() ? "" : frameFile(args.png, 1).c_str());
}

void runRender(const RenderArgs& args) {
    bool exr = hasExtension(args.output, ".exr");
    if (!exr && !hasExtension(args.output, ".png"))
        throw CommandLineError(fmt::format("-o '{}': the image is written as .exr or .png", args.output));
    if (!args.png.empty() && !hasExtension(args.png, ".png"))
        throw CommandLineError(fmt::format("--png '{}': expected a .png file name", args.png));
    const field::FieldSource& source = args.source;
    if (!source.colormap.empty() && hasExtension(source.file, ".eco"))
        throw CommandLineError("--colormap: a scene's colours are its stages' own; a colour map replaces a grammar's");
    if (args.frames > 0) {
        if (args.lightSlice || args.lightSection || args.lightVolume || args.occupancySlice)
            throw CommandLineError("--frames draws the growth; the light grid's views are drawn without it");
        renderGrowth(args, exr);
        return;
    }

    // Rendering needs the device whichever backend derives and interprets.
    vk::ContextOptions contextOptions;
    contextOptions.device = source.device;
    vk::Context context(contextOptions);
    auto start = std::chrono::steady_clock::now();
    field::Field field = field::deriveField(source, &context);
    draw::RenderSettings settings = renderSettings(args.picture, field.species.front().view);
    const std::vector<const turtle::DeviceOrgans*> organs = field::interpretInParts(source, field, context);
    field::OrganExtent extent = field::organExtent(context, organs);
    if (extent.organs == 0) throw std::runtime_error(fmt::format("{}: the plants draw nothing", source.file));

    draw::Renderer renderer(context, field.assets);
    const bool light = args.lightSlice || args.lightSection || args.lightVolume || args.occupancySlice;
    const field::LightVolume volume =
        light ? fieldLight(context, field, organs, extent.bounds, source.file) : field::LightVolume{};
    draw::Frame frame =
        args.lightVolume
            ? field::renderWithShade(context, renderer, organs, volume, field.plants, extent.bounds, settings)
            : renderer.render(field::organParts(organs), extent.bounds, settings);
    // Every file appears, or none.
    draw::OutputBatch outputs;
    if (args.lightSlice)
        draw::writePng(outputs, besideOutput(args.output, "-light.png"),
                       field::lightSliceImage(field::lightSlice(volume, *args.lightSlice)));
    if (args.lightSection)
        draw::writePng(outputs, besideOutput(args.output, "-light-section.png"),
                       field::lightSliceImage(field::lightSection(volume, *args.lightSection)));
    if (args.occupancySlice)
        draw::writePng(outputs, besideOutput(args.output, "-occupancy.png"),
                       field::occupancySliceImage(field::occupancySlice(volume, *args.occupancySlice)));
    if (exr) draw::writeExr(outputs, args.output, frame);
    else draw::writePng(outputs, args.output, frame);
    if (!args.png.empty()) draw::writePng(outputs, args.png, frame);
    outputs.commit();
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu plants, %zu modules, %zu organs, %ux%u, %.2f s -> %s%s%s\n", source.file.c_str(),
                size_t(field.plants), size_t(field.modules), size_t(extent.organs), settings.width, settings.height,
                seconds, args.output.c_str(), args.png.empty() ? "" : ", ", args.png.c_str());
}

} // namespace

void registerRenderCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Derive, interpret and render a field of plants to OpenEXR or PNG");
    addFieldOptions(*cmd, args->source);
    cmd->add_option("-o,--output", args->output, "image file: .exr (RGBA, depth, plant and organ ids) or .png")
        ->required();
    cmd->add_option("--png", args->png, "also write a PNG preview");
    addPictureOptions(*cmd, args->picture, "plants");
    addColormapOption(*cmd, args->source.colormap);
    cmd->add_option("--light-slice", args->lightSlice,
                    "also write OUTPUT-light.png: the light grid's layer at height H, seen from above");
    cmd->add_option("--light-section", args->lightSection,
                    "also write OUTPUT-light-section.png: the light grid's vertical layer at depth Z, seen from the "
                    "front");
    cmd->add_option("--occupancy-slice", args->occupancySlice,
                    "also write OUTPUT-occupancy.png: which plant holds each voxel of the light grid's layer at "
                    "height H, seen from above");
    cmd->add_option("--frames", args->frames,
                    "animate the growth in N frames, OUTPUT-00001.png ... (or .exr; --png too): every derivation "
                    "step's segments, spheres and discs growing over the step's time, as `simeco run` grows a field")
        ->check(CLI::Range(1u, 100000u));
    cmd->add_flag("--light-volume", args->lightVolume,
                  "draw the light grid's shade among the plants: a sphere in each shaded voxel, larger and darker "
                  "the deeper its shade (no shadow volumes)");
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runRender(*args); }); });
}

} // namespace simeco::app
