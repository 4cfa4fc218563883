// `simeco render`: derive a grammar or scene, interpret it with the turtle, and render the field of plants
// headless to OpenEXR and/or PNG.
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/error_report.h"
#include "app/load_species.h"
#include "compute/shared/organ_layout.h"
#include "cpu/derive.h"
#include "draw/bounds.h"
#include "draw/image_writers.h"
#include "draw/renderer.h"
#include "gpu/derive_gpu.h"
#include "gpu/turtle_gpu.h"
#include "ir/species.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace simeco::app {

namespace {

struct RenderArgs {
    std::string file;
    int steps = -1;
    int64_t seed = -1;
    uint32_t plants = 0;
    float spacing = 0;
    std::string backend = "gpu";
    std::string output;
    std::string png;
    std::string size = "960x720";
    std::string camera;
    std::string style = "lit";
    std::string shadows = "volume";
    uint64_t maxModules = 0;
    std::string device;
};

bool hasExtension(const std::string& path, const char* ext) {
    return std::filesystem::path(path).extension() == ext;
}

draw::RenderSettings renderSettings(const RenderArgs& args) {
    draw::RenderSettings s;
    unsigned w = 0, h = 0;
    char x = 0;
    if (std::sscanf(args.size.c_str(), "%u%c%u", &w, &x, &h) != 3 || x != 'x' || w == 0 || h == 0 || w > 16384 ||
        h > 16384)
        throw std::invalid_argument(fmt::format("--size '{}': expected WIDTHxHEIGHT, each 1 to 16384", args.size));
    s.width = w;
    s.height = h;
    if (!args.camera.empty()) {
        draw::Camera c;
        int read = std::sscanf(args.camera.c_str(), "%f,%f,%f", &c.azimuthDegrees, &c.elevationDegrees, &c.distance);
        if (read < 2 || c.elevationDegrees <= -90 || c.elevationDegrees >= 90)
            throw std::invalid_argument(fmt::format(
                "--camera '{}': expected azimuth,elevation[,distance] in degrees, elevation within (-90, 90)",
                args.camera));
        s.camera = c;
    }
    s.style = args.style == "toon" ? draw::Style::Toon : draw::Style::Lit;
    s.shadows = args.shadows == "none" ? draw::Shadows::None : draw::Shadows::Volume;
    return s;
}

// The derived strings of all plants under their homomorphisms: what the turtle reads.
cpu::ModuleString deriveForTurtle(const RenderArgs& args, const std::vector<ir::Grammar>& species,
                                  const vk::Context& context) {
    cpu::DeriveOptions options;
    options.steps = args.steps;
    options.seed = args.seed;
    options.plants = args.plants ? args.plants : static_cast<uint32_t>(species.size());
    options.maxModules = args.maxModules;
    if (args.backend == "cpu") {
        options.homomorphism = true;
        return cpu::deriveSpeciesCpu(species, options).string;
    }
    gpu::GpuDeriver deriver(context, species);
    cpu::DeriveResult derived = deriver.derive(options, true);
    return cpu::applyHomomorphismCpu(species, derived.string, options);
}

void runRender(const RenderArgs& args) {
    bool exr = hasExtension(args.output, ".exr");
    if (!exr && !hasExtension(args.output, ".png"))
        throw std::invalid_argument(fmt::format("-o '{}': the image is written as .exr or .png", args.output));
    if (!args.png.empty() && !hasExtension(args.png, ".png"))
        throw std::invalid_argument(fmt::format("--png '{}': expected a .png file name", args.png));
    draw::RenderSettings settings = renderSettings(args);

    std::vector<ir::Grammar> species = ir::unifySpecies(loadGrammars(args.file));
    vk::ContextOptions contextOptions;
    contextOptions.device = args.device;
    vk::Context context(contextOptions);
    auto start = std::chrono::steady_clock::now();
    cpu::ModuleString string = deriveForTurtle(args, species, context);

    std::vector<turtle::TurtleSettings> turtles;
    for (const ir::Grammar& g : species) turtles.push_back(turtle::turtleSettings(g, species.front().alphabet));
    turtle::TurtleCommands commands = turtle::turtleCommands(species.front().alphabet);
    turtle::FieldOptions field;
    field.spacing = args.spacing;

    // The organs on the device, written by the turtle kernels (or, with the CPU backend, uploaded from the
    // reference turtle); only the table (counts and bounds) comes back for framing.
    gpu::DeviceOrgans organs;
    if (args.backend == "cpu") {
        organs = gpu::uploadOrgans(context, turtle::interpretCpu(string, commands, turtles, field));
    } else {
        gpu::GpuTurtle turtle(context, commands, turtles);
        gpu::UploadedModules modules(context, string);
        organs = turtle.interpret(modules.view(), field);
    }
    shared::OrganTable table = vk::downloadVector<shared::OrganTable>(context, organs.table, 1)[0];
    uint32_t organCount = 0;
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k) organCount += table.count[k];
    if (organCount == 0) throw std::runtime_error(fmt::format("{}: the plants draw nothing", args.file));
    draw::Bounds bounds = draw::decodeBounds(table);

    draw::Renderer renderer(context);
    draw::Frame frame = renderer.render(organs.instances, organs.table, bounds, settings);
    if (exr) draw::writeExr(args.output, frame);
    else draw::writePng(args.output, frame);
    if (!args.png.empty()) draw::writePng(args.png, frame);
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu plants, %zu modules, %zu organs, %ux%u, %.2f s -> %s%s%s\n", args.file.c_str(),
                string.plants(), string.size(), size_t(organCount), settings.width, settings.height, seconds,
                args.output.c_str(), args.png.empty() ? "" : ", ", args.png.c_str());
}

} // namespace

void registerRenderCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<RenderArgs>();
    CLI::App* cmd = app.add_subcommand("render", "Derive, interpret and render a field of plants to OpenEXR or PNG");
    cmd->add_option("file", args->file, "grammar (.l, .lsys) or scene (.eco)")->required();
    cmd->add_option("-n,--steps", args->steps, "derivation steps (default: the file's derivation length)")
        ->check(CLI::Range(0, 1000000));
    cmd->add_option("--seed", args->seed, "seed of the random streams (default: the file's seed, else 0)")
        ->check(CLI::Range(int64_t(0), int64_t(UINT32_MAX)));
    cmd->add_option("--plants", args->plants, "plants in the field; a scene's species take turns (default: one of each)")
        ->check(CLI::Range(1u, 1000000u));
    cmd->add_option("--spacing", args->spacing, "distance between plants (default: from the widest plant)")
        ->check(CLI::Range(0.0f, 1e6f));
    cmd->add_option("-o,--output", args->output, "image file: .exr (RGBA, depth, plant and organ ids) or .png")
        ->required();
    cmd->add_option("--png", args->png, "also write a PNG preview");
    cmd->add_option("--size", args->size, "image size WIDTHxHEIGHT (default 960x720)");
    cmd->add_option("--camera", args->camera, "azimuth,elevation[,distance] in degrees (default: framed on the plants)");
    cmd->add_option("--style", args->style, "lit or toon")->check(CLI::IsMember({"lit", "toon"}));
    cmd->add_option("--shadows", args->shadows, "volume or none")->check(CLI::IsMember({"volume", "none"}));
    cmd->add_option("--backend", args->backend, "derivation and turtle: gpu (compute kernels) or cpu (reference)")->check(CLI::IsMember({"cpu", "gpu"}));
    cmd->add_option("--max-modules", args->maxModules, "module budget (default: sized to this machine's memory)");
    cmd->add_option("--device", args->device, "Vulkan device: an index or a name part (see `simeco devices`)");
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runRender(*args); }); });
}

} // namespace simeco::app
