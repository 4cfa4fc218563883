// `simeco infer`: a grammar from a plant's skeleton, as the L-Grammar Generator of seed 002 makes it: the
// initial-state grammar that regrows the skeleton exactly and the prediction rules that grow it on, as a SimEco
// script (.eco) or a cpfg L-system (.l) (docs/SKELETON.md).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/error_report.h"
#include "app/text_output.h"
#include "skeleton/dressing.h"
#include "skeleton/eco_writer.h"
#include "skeleton/lsystem_writer.h"
#include "skeleton/skeleton_check.h"
#include "skeleton/skeleton_json.h"
#include "skeleton/skeleton_obj.h"
#include "skeleton/three_views.h"

namespace simeco::app {

namespace {

struct InferArgs {
    std::string input;
    uint32_t plant = 0;
    std::string description;
    bool initialOnly = false;
    std::string output;
};

// Whether a JSON file holds three views (a "views" object) rather than a skeleton.
bool holdsThreeViews(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    nlohmann::json document = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    return document.is_object() && document.contains("views");
}

// A skeleton file by its kind: three views (.svg, or JSON with "views"), OBJ polylines, or simeco's JSON.
skeleton::Skeleton readAnySkeleton(const std::string& path) {
    const std::string ext = std::filesystem::path(path).extension().string();
    if (ext == ".obj") return skeleton::readObjSkeleton(path);
    if (ext == ".svg") return skeleton::readThreeViews(path);
    if (ext != ".json") throw CommandLineError(fmt::format("'{}': a skeleton is read from .json, .obj or .svg", path));
    return holdsThreeViews(path) ? skeleton::readThreeViews(path) : skeleton::readSkeletonJson(path);
}

void runInfer(const InferArgs& args) {
    const bool eco = args.output.ends_with(".eco");
    if (!eco && !args.output.ends_with(".l"))
        throw CommandLineError(fmt::format("-o '{}': the grammar is written as .eco or .l", args.output));
    skeleton::PlantDescription description;
    try {
        description = skeleton::describePlant(args.description);
    } catch (const std::invalid_argument& e) {
        throw CommandLineError(fmt::format("--describe: {}", e.what()));
    }
    skeleton::Skeleton skel = readAnySkeleton(args.input);
    skeleton::checkSkeleton(skel, args.input);
    if (args.plant >= skel.plants.size())
        throw CommandLineError(fmt::format("--plant {}: the skeleton has {} plant{}", args.plant, skel.plants.size(),
                                           skel.plants.size() == 1 ? "" : "s"));
    skeleton::Plant plant = skel.plants[args.plant];
    const std::string dressing = skeleton::dressPlant(plant, description);
    const std::string source = fmt::format("{}, plant {}", std::filesystem::path(args.input).filename().string(),
                                           args.plant);
    const skeleton::Regrowth growth =
        skeleton::regrowth(plant, eco ? skeleton::Dialect::SimEco : skeleton::Dialect::Cpfg);
    draw::OutputBatch batch;
    if (eco) {
        const skeleton::Prediction prediction = skeleton::predictionOf(plant, growth);
        skeleton::EcoScriptOptions options;
        options.source = source;
        options.position = growth.tree.base;
        options.dressing = dressing;
        options.prediction = args.initialOnly ? nullptr : &prediction;
        options.description = &description;
        writeText(batch, args.output, skeleton::ecoScript(plant, growth, options));
    } else {
        writeText(batch, args.output, skeleton::lsystemText(plant, growth, source));
        writeText(batch, std::filesystem::path(args.output).replace_extension(".v"), skeleton::lsystemView());
    }
    batch.commit();
    std::printf("%s: plant %u: %zu internodes in %d levels%s -> %s\n", args.input.c_str(), args.plant,
                growth.internodes.size(), growth.tree.levels, dressing.empty() ? "" : (", " + dressing).c_str(),
                args.output.c_str());
}

} // namespace

void registerInferCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<InferArgs>();
    CLI::App* cmd = app.add_subcommand("infer", "Infer a grammar from a plant's skeleton: the initial state that "
                                                "regrows it and prediction rules that grow it on (.eco or .l)");
    cmd->add_option("skeleton", args->input,
                    "skeleton: simeco's JSON (simeco skeleton), OBJ polylines, or three views (.svg, or JSON)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_option("--plant", args->plant, "which plant of the skeleton (default 0)");
    cmd->add_option("--describe", args->description,
                    "keywords: phyllotaxy (alternate, opposite, whorled, basal, clustered, or 互生 對生 輪生 基生 叢生), "
                    "leaf shape (ovate, lanceolate, cordate, compound, trifoliate, serrate), habit (herb, shrub, "
                    "tree)");
    cmd->add_flag("--initial-only", args->initialOnly, "write the initial-state grammar without prediction rules");
    cmd->add_option("-o,--output", args->output,
                    "grammar file: .eco (SimEco script) or .l (cpfg, with its view file .v beside it)")
        ->required();
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runInfer(*args); }); });
}

} // namespace simeco::app
