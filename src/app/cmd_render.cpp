// `simeco render`: derive a grammar or scene, interpret it with the turtle, and render the field of plants
// headless to OpenEXR and/or PNG.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/error_report.h"
#include "app/field_options.h"
#include "app/render_options.h"
#include "draw/image_writers.h"
#include "draw/renderer.h"
#include "field/field_parts.h"
#include "field/simulation.h"
#include "turtle/turtle_gpu.h"
#include "vk/context.h"

namespace simeco::app {

namespace {

struct RenderArgs {
    field::FieldSource source;
    std::string output;
    std::string png;
    std::string size = "960x720";
    std::string camera;
    std::string style = "lit";
    std::string shadows = "volume";
};

bool hasExtension(const std::string& path, const char* ext) {
    return std::filesystem::path(path).extension() == ext;
}

void runRender(const RenderArgs& args) {
    bool exr = hasExtension(args.output, ".exr");
    if (!exr && !hasExtension(args.output, ".png"))
        throw CommandLineError(fmt::format("-o '{}': the image is written as .exr or .png", args.output));
    if (!args.png.empty() && !hasExtension(args.png, ".png"))
        throw CommandLineError(fmt::format("--png '{}': expected a .png file name", args.png));
    draw::RenderSettings settings = renderSettings(args.size, args.camera, args.style, args.shadows);

    // Rendering needs the device whichever backend derives and interprets.
    const field::FieldSource& source = args.source;
    vk::ContextOptions contextOptions;
    contextOptions.device = source.device;
    vk::Context context(contextOptions);
    auto start = std::chrono::steady_clock::now();
    field::Field field = field::deriveField(source, &context);
    const std::vector<const turtle::DeviceOrgans*> organs = field::interpretInParts(source, field, context);
    field::OrganExtent extent = field::organExtent(context, organs);
    if (extent.organs == 0) throw std::runtime_error(fmt::format("{}: the plants draw nothing", source.file));

    draw::Renderer renderer(context, field.assets);
    draw::Frame frame = renderer.render(field::organParts(organs), extent.bounds, settings);
    // Both files appear, or neither.
    draw::OutputBatch outputs;
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
    cmd->add_option("--size", args->size, "image size WIDTHxHEIGHT (default 960x720)");
    cmd->add_option("--camera", args->camera, "azimuth,elevation[,distance] in degrees (default: framed on the plants)");
    cmd->add_option("--style", args->style, "lit or toon")->check(CLI::IsMember({"lit", "toon"}));
    cmd->add_option("--shadows", args->shadows, "volume or none")->check(CLI::IsMember({"volume", "none"}));
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runRender(*args); }); });
}

} // namespace simeco::app
