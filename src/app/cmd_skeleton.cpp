// `simeco skeleton`: derive a grammar or scene, interpret it with the turtle, and write one plant's stem skeleton
// (polylines with parent links, widths, and the leaves, flowers and fruits on them) as JSON, or its stems as OBJ
// polylines or as three orthogonal views in SVG (docs/SKELETON.md).
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/format.h>

#include "app/commands.h"
#include "app/error_report.h"
#include "app/field_options.h"
#include "app/text_output.h"
#include "skeleton/internodes.h"
#include "skeleton/skeleton_check.h"
#include "skeleton/skeleton_from_turtle.h"
#include "skeleton/skeleton_json.h"
#include "skeleton/skeleton_obj.h"
#include "skeleton/skeleton_statistics.h"
#include "skeleton/three_views.h"
#include "vk/context.h"

namespace simeco::app {

namespace {

struct SkeletonArgs {
    field::FieldSource source;
    uint32_t plant = 0;
    std::string output;
    bool statistics = false;
};

void runSkeleton(const SkeletonArgs& args) {
    const bool json = args.output.ends_with(".json"), obj = args.output.ends_with(".obj");
    const bool views = args.output.ends_with(".svg");
    if (!json && !obj && !views)
        throw CommandLineError(fmt::format("-o '{}': the skeleton is written as .json, .obj or .svg", args.output));
    const field::FieldSource& source = args.source;
    std::unique_ptr<vk::Context> context = field::contextFor(source);
    field::Field field = field::deriveField(source, context.get());
    if (args.plant >= field.plants)
        throw CommandLineError(fmt::format("--plant {}: the field has {} plant{}", args.plant, field.plants,
                                           field.plants == 1 ? "" : "s"));
    turtle::Interpretation interp = field::interpretOnHost(source, field, context.get());
    if (field.string.plants() == 0)
        throw std::runtime_error("the derived string stayed on the device; use --backend cpu");
    skeleton::Skeleton skeleton;
    skeleton.source = fmt::format("{}, plant {}", source.file, args.plant);
    skeleton.plants.push_back(skeleton::plantFromTurtle(field.string, interp, args.plant));
    const skeleton::Plant& plant = skeleton.plants.front();
    if (plant.stems.empty()) throw std::runtime_error(fmt::format("{}: plant {} draws no stems", source.file,
                                                                  args.plant));
    draw::OutputBatch batch;
    if (json) writeText(batch, args.output, skeleton::skeletonJson(skeleton));
    else if (obj) writeText(batch, args.output, skeleton::skeletonObj(plant, "simeco skeleton of " + skeleton.source));
    else writeText(batch, args.output, skeleton::threeViewsSvg(skeleton::projectThreeViews(plant)));
    batch.commit();
    if (args.statistics) {
        skeleton::Plant checked = plant;
        skeleton::checkPlant(checked, args.output, 0);
        std::fputs(skeleton::statisticsTable(skeleton::levelStatistics(skeleton::internodeTree(checked))).c_str(),
                   stdout);
    }
    std::printf("%s: plant %u: %zu stems, %zu segments, %zu organs, size %.4g -> %s\n", source.file.c_str(),
                args.plant, plant.stems.size(), skeleton::segmentCount(plant), plant.organs.size(),
                skeleton::plantSize(plant), args.output.c_str());
}

} // namespace

void registerSkeletonCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<SkeletonArgs>();
    args->source.backend = field::Backend::Cpu; // the reference: the skeleton is exact and needs no device
    CLI::App* cmd = app.add_subcommand("skeleton", "Derive a grammar or scene and write one plant's stem skeleton "
                                                   "(JSON polylines with parents, widths, leaves and flowers)");
    addFieldOptions(*cmd, args->source);
    cmd->add_option("--plant", args->plant, "which plant of the field (default 0)");
    cmd->add_option("-o,--output", args->output,
                    "skeleton file: .json (stems, parents, widths, organs), .obj (polylines) or .svg (three views)")
        ->required();
    cmd->add_flag("--stats", args->statistics,
                  "print the skeleton's internodes level by level: their count, length, angle to their parent and "
                  "children");
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runSkeleton(*args); }); });
}

} // namespace simeco::app
