// `simeco export`: derive a grammar or scene, interpret it with the turtle, and write the geometry `simeco
// render` draws as a mesh file (OBJ, PLY or glTF 2.0).
#include <chrono>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/error_report.h"
#include "app/load_species.h"
#include "cpu/derive.h"
#include "draw/organ_meshes.h"
#include "export/gltf_writer.h"
#include "export/mesh_writers.h"
#include "export/organ_geometry.h"
#include "gpu/derive_gpu.h"
#include "ir/species.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "vk/context.h"

namespace simeco::app {

namespace {

struct ExportArgs {
    std::string file;
    int steps = -1;
    int64_t seed = -1;
    uint32_t plants = 0;
    float spacing = 0;
    std::string backend = "gpu";
    std::string output;
    bool noInstancing = false;
    uint64_t maxModules = 0;
    std::string device;
};

// The derived strings of all plants under their homomorphisms: what the turtle reads. The same steps as
// `simeco render`; the CPU backend needs no Vulkan device, so none is opened for it.
cpu::ModuleString deriveForTurtle(const ExportArgs& args, const std::vector<ir::Grammar>& species) {
    cpu::DeriveOptions options;
    options.steps = args.steps;
    options.seed = args.seed;
    options.plants = args.plants ? args.plants : static_cast<uint32_t>(species.size());
    options.maxModules = args.maxModules;
    if (args.backend == "cpu") {
        options.homomorphism = true;
        return cpu::deriveSpeciesCpu(species, options).string;
    }
    vk::ContextOptions contextOptions;
    contextOptions.device = args.device;
    vk::Context context(contextOptions);
    gpu::GpuDeriver deriver(context, species);
    cpu::DeriveResult derived = deriver.derive(options, true);
    return cpu::applyHomomorphismCpu(species, derived.string, options);
}

void runExport(const ExportArgs& args) {
    std::optional<exporter::MeshFormat> format = exporter::meshFormatOf(args.output);
    if (!format) {
        throw std::invalid_argument(fmt::format("-o '{}': the mesh is written as .obj, .ply or .gltf", args.output));
    }
    std::vector<ir::Grammar> species = ir::unifySpecies(loadGrammars(args.file));
    auto start = std::chrono::steady_clock::now();
    cpu::ModuleString string = deriveForTurtle(args, species);

    std::vector<turtle::TurtleSettings> turtles;
    for (const ir::Grammar& g : species)
        turtles.push_back(turtle::turtleSettings(g, species.front().alphabet));
    turtle::FieldOptions field;
    field.spacing = args.spacing;
    turtle::Interpretation interp =
        turtle::interpretCpu(string, turtle::turtleCommands(species.front().alphabet), turtles, field);
    if (interp.organs.empty()) throw std::runtime_error(fmt::format("{}: the plants draw nothing", args.file));

    exporter::OrganMeshSet meshes(draw::buildOrganMeshes());
    std::string counts;
    if (*format == exporter::MeshFormat::Gltf) {
        exporter::GltfOptions options;
        options.instancing = !args.noInstancing;
        options.source = args.file;
        options.plants = static_cast<uint32_t>(string.plants());
        exporter::writeGltf(args.output, interp.organs, meshes, options);
    } else {
        std::vector<uint32_t> order = exporter::plantOrder(interp.organs);
        exporter::WorldMesh mesh = exporter::placeOrgans(interp.organs, order, meshes);
        std::string comment =
            fmt::format("simeco export of {}: {} plants, {} organs", args.file, string.plants(), interp.organs.size());
        if (*format == exporter::MeshFormat::Obj)
            exporter::writeObj(args.output, mesh, comment);
        else
            exporter::writePly(args.output, mesh, comment);
        counts = fmt::format(", {} vertices, {} triangles", mesh.positions.size(), mesh.triangleCount());
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu plants, %zu modules, %zu organs%s, %.2f s -> %s\n", args.file.c_str(), string.plants(),
                string.size(), interp.organs.size(), counts.c_str(), seconds, args.output.c_str());
}

} // namespace

void registerExportCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App* cmd = app.add_subcommand("export", "Derive and interpret a field of plants and write it as a mesh "
                                                 "(OBJ, PLY or glTF)");
    cmd->add_option("file", args->file, "grammar (.l, .lsys) or scene (.eco)")->required();
    cmd->add_option("-n,--steps", args->steps, "derivation steps (default: the file's derivation length)")
        ->check(CLI::Range(0, 1000000));
    cmd->add_option("--seed", args->seed, "seed of the random streams (default: the file's seed, else 0)")
        ->check(CLI::Range(int64_t(0), int64_t(UINT32_MAX)));
    cmd->add_option("--plants", args->plants,
                    "plants in the field; a scene's species take turns (default: one of each)")
        ->check(CLI::Range(1u, 1000000u));
    cmd->add_option("--spacing", args->spacing, "distance between plants (default: from the widest plant)")
        ->check(CLI::Range(0.0f, 1e6f));
    // The format is checked while parsing, so a wrong name is bad input (exit 2) and nothing is derived.
    CLI::Validator meshFile(
        [](std::string& name) -> std::string {
            return exporter::meshFormatOf(name) ? "" : "the mesh is written as .obj, .ply or .gltf";
        },
        "{.obj,.ply,.gltf}", "mesh file");
    cmd->add_option("-o,--output", args->output,
                    "mesh file: .obj (vertex colours), .ply (binary, per-face plant) or .gltf (instanced organs)")
        ->required()
        ->check(meshFile);
    cmd->add_flag("--no-instancing", args->noInstancing,
                  "glTF: bake every organ into world space, for viewers without EXT_mesh_gpu_instancing");
    cmd->add_option("--backend", args->backend, "derivation backend: gpu or cpu")->check(CLI::IsMember({"cpu", "gpu"}));
    cmd->add_option("--max-modules", args->maxModules, "module budget (default: sized to this machine's memory)");
    cmd->add_option("--device", args->device, "Vulkan device: an index or a name part (see `simeco devices`)");
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runExport(*args); }); });
}

} // namespace simeco::app
