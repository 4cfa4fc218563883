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
#include "app/field_options.h"
#include "draw/organ_meshes.h"
#include "export/gltf_writer.h"
#include "export/mesh_writers.h"
#include "export/organ_geometry.h"
#include "vk/context.h"

namespace simeco::app {

namespace {

struct ExportArgs {
    field::FieldSource source;
    std::string output;
    bool noInstancing = false;
};

void runExport(const ExportArgs& args) {
    std::optional<exporter::MeshFormat> format = exporter::meshFormatOf(args.output);
    if (!format) {
        throw CommandLineError(fmt::format("-o '{}': the mesh is written as .obj, .ply or .gltf", args.output));
    }
    const field::FieldSource& source = args.source;
    std::unique_ptr<vk::Context> context = field::contextFor(source);
    auto start = std::chrono::steady_clock::now();
    field::Field field = field::deriveField(source, context.get());
    turtle::Interpretation interp = field::interpretOnHost(source, field, context.get());
    if (interp.organs.empty()) throw std::runtime_error(fmt::format("{}: the plants draw nothing", source.file));

    exporter::OrganMeshSet meshes(draw::buildOrganMeshes(field.assets.models)); // a model's own triangles
    std::string counts;
    if (*format == exporter::MeshFormat::Gltf) {
        exporter::GltfOptions options;
        options.instancing = !args.noInstancing;
        options.source = source.file;
        options.plants = field.plants;
        exporter::writeGltf(args.output, interp.organs, meshes, options);
    } else {
        std::vector<uint32_t> order = exporter::plantOrder(interp.organs);
        exporter::WorldMesh mesh = exporter::placeOrgans(interp.organs, order, meshes);
        std::string comment =
            fmt::format("simeco export of {}: {} plants, {} organs", source.file, field.plants, interp.organs.size());
        if (*format == exporter::MeshFormat::Obj)
            exporter::writeObj(args.output, mesh, comment);
        else
            exporter::writePly(args.output, mesh, comment);
        counts = fmt::format(", {} vertices, {} triangles", mesh.positions.size(), mesh.triangleCount());
    }
    double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %zu plants, %zu modules, %zu organs%s, %.2f s -> %s\n", source.file.c_str(), size_t(field.plants),
                size_t(field.modules), interp.organs.size(), counts.c_str(), seconds, args.output.c_str());
}

} // namespace

void registerExportCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<ExportArgs>();
    CLI::App* cmd = app.add_subcommand("export", "Derive and interpret a field of plants and write it as a mesh "
                                                 "(OBJ, PLY or glTF)");
    addFieldOptions(*cmd, args->source);
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
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runExport(*args); }); });
}

} // namespace simeco::app
