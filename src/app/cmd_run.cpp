// `simeco run`: grow a field over simulated time, tick by tick, and write what it did: a line of statistics per
// tick, a row per plant at the end, and frames of the field as it grows.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <glm/common.hpp>
#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/default_scene.h"
#include "app/error_report.h"
#include "app/field_options.h"
#include "app/render_options.h"
#include "draw/image_writers.h"
#include "ir/source_loc.h"
#include "lang/source_text.h"
#include "draw/renderer.h"
#include "field/field.h"
#include "field/saved_run.h"
#include "field/simulation.h"
#include "turtle/interpretation.h"
#include "vk/context.h"
#include "vk/kernel_profile.h"

namespace simeco::app {

namespace {

namespace fs = std::filesystem;

struct RunArgs {
    field::SimulationOptions simulation;
    double time = 0;     // 0: until every plant has grown
    uint32_t frames = 0; // a frame every N ticks; 0: the last only
    std::string out = "run";
    PictureOptions picture;
    std::string device;
    std::string save;   // where the state is written at the end; empty: nowhere
    std::string resume; // the state the field starts from; empty: the axioms
    std::optional<float> lightSlice;     // the height of the light grid's layer written as light.png
    std::optional<float> lightSection;   // the depth of its vertical layer written as light-section.png
    bool lightVolume = false;            // light-volume.png: the last frame with the grid's shade drawn in 3D
    std::optional<float> occupancySlice; // the height of the layer of the grid's holders written as occupancy.png
    bool profile = false;                // print each stage's seconds and each kernel's GPU time at the end
};

// One line on a terminal, rewritten as the run goes.
class Progress {
public:
    Progress(double until, double dt) : until_(until), dt_(dt), shown_(isatty(fileno(stderr)) != 0) {}
    void show(const field::Simulation& s, double ticksPerSecond) {
        if (!shown_) return;
        const double done = std::clamp(s.time() / until_, 0.0, 1.0);
        const int filled = int(done * 30);
        const double eta = ticksPerSecond > 0 ? (until_ - s.time()) / dt_ / ticksPerSecond : 0;
        std::fprintf(stderr, "\r[%s%s] %.1f/%.1f s  %u plants  %llu modules  %.1f ticks/s  ETA %.0f s ",
                     std::string(size_t(filled), '#').c_str(), std::string(size_t(30 - filled), '.').c_str(), s.time(),
                     until_, s.standingPlants(), static_cast<unsigned long long>(s.modules()), ticksPerSecond,
                     std::max(eta, 0.0));
    }
    ~Progress() {
        if (shown_) std::fprintf(stderr, "\n");
    }

private:
    double until_, dt_;
    bool shown_;
};

// A tick's line of stats.jsonl: the field's totals, and each species' (in the order of the scene).
std::string statsLine(const field::Simulation& simulation, const field::TickReport& report,
                      const std::vector<shared::PlantStatistics>& perPlant) {
    struct Totals {
        uint32_t plants = 0; // alive
        uint64_t organs = 0;
        double leafArea = 0, light = 0;
        void add(const shared::PlantStatistics& s) {
            plants += shared::plantAlive(s) ? 1 : 0;
            organs += s.organs;
            leafArea += s.leafArea;
            light += s.light;
        }
    };
    Totals field;
    std::vector<std::pair<std::string, Totals>> species;
    for (uint32_t p = 0; p < perPlant.size(); ++p) {
        if (!simulation.present(p)) continue;
        field.add(perPlant[p]);
        const std::string name = simulation.speciesName(p);
        auto it = std::find_if(species.begin(), species.end(), [&](const auto& s) { return s.first == name; });
        if (it == species.end()) it = species.insert(species.end(), {name, Totals{}});
        it->second.add(perPlant[p]);
    }
    std::string bySpecies;
    for (const auto& [name, t] : species)
        bySpecies += fmt::format("{}{}: {{\"plants\": {}, \"organs\": {}, \"leaf_area\": {:.9g}, \"light\": {:.9g}}}",
                                 bySpecies.empty() ? "" : ", ", nlohmann::json(name).dump(), t.plants, t.organs,
                                 t.leafArea, t.light);
    return fmt::format("{{\"tick\": {}, \"time\": {}, \"plants\": {}, \"modules\": {}, \"derived\": {}, "
                       "\"organs\": {}, \"leaf_area\": {:.9g}, \"light\": {:.9g}, \"species\": {{{}}}}}\n",
                       report.tick, report.time, field.plants, report.modules, report.derived, field.organs,
                       field.leafArea, field.light, bySpecies);
}

// plants.csv: a row per plant in plant order.
std::string plantsTable(const field::Simulation& simulation, const std::vector<shared::PlantStatistics>& perPlant) {
    std::string csv = "plant,species,x,z,alive,modules,height,leaf_area,light\n";
    const std::vector<uint64_t> modules = simulation.plantModules();
    uint32_t row = 0;
    for (uint32_t p = 0; p < simulation.plants(); ++p) {
        if (!simulation.present(p)) continue;
        const glm::vec3 at = turtle::plantOrigin(simulation.placements()[p]);
        std::string species = simulation.speciesName(p);
        std::replace(species.begin(), species.end(), '"', '\'');
        const shared::PlantStatistics& s = perPlant[p];
        csv += fmt::format("{},\"{}\",{:.9g},{:.9g},{},{},{:.9g},{:.9g},{:.9g}\n", row++, species, at.x, at.z,
                           shared::plantAlive(s) ? 1 : 0, modules[p], s.height, s.leafArea, s.light);
    }
    return csv;
}

void writeText(draw::OutputBatch& outputs, const fs::path& path, const std::string& text) {
    outputs.write(path, [&](const fs::path& temporary) {
        std::ofstream file(temporary, std::ios::binary);
        file << text;
        if (!file.flush()) throw draw::OutputError(fmt::format("cannot write {}", path.string()));
    });
}

// A saved run's bytes.
std::string readFile(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ir::InputError({path, 0, 0}, "cannot open the file");
    std::stringstream bytes;
    bytes << file.rdbuf();
    return bytes.str();
}

// The saved field's options in place of the command line's, but for how it runs (backend, budgets).
field::SavedRun readSavedRun(RunArgs& args) {
    field::SavedRun saved = field::decodeSavedRun(readFile(args.resume), args.resume);
    field::SimulationOptions& s = args.simulation;
    const field::SimulationOptions& o = saved.options;
    s.file = o.file;
    s.sceneText = o.sceneText;
    s.plants = o.plants;
    s.density = o.density;
    s.seed = o.seed;
    s.dt = o.dt;
    s.spacing = o.spacing;
    return saved;
}

void runRun(RunArgs args) {
    std::optional<field::SavedRun> saved;
    if (!args.resume.empty()) saved = readSavedRun(args);
    if (args.simulation.file.empty()) { // the built-in garden
        args.simulation.file = kDefaultSceneName;
        args.simulation.sceneText = kDefaultSceneText;
        if (args.simulation.plants == 0) args.simulation.plants = kDefaultScenePlants;
    }
    if (!args.simulation.colormap.empty() && fs::path(args.simulation.file).extension() == ".eco")
        throw CommandLineError("--colormap: a scene's colours are its stages' own; a colour map replaces a grammar's");
    // A scene's text goes into a saved state, so that the state stands alone.
    if (!args.save.empty() && args.simulation.sceneText.empty() && fs::path(args.simulation.file).extension() == ".eco")
        args.simulation.sceneText = lang::readSourceFile(args.simulation.file);
    vk::ContextOptions contextOptions;
    contextOptions.device = args.device;
    vk::Context context(contextOptions);
    if (args.profile) context.enableKernelProfile();
    field::Simulation simulation(args.simulation, &context);
    draw::RenderSettings settings = grownFieldSettings(args.picture, simulation.species());
    if (saved) {
        try {
            simulation.resume(saved->state);
        } catch (const std::invalid_argument& e) {
            throw ir::InputError({args.resume, 0, 0}, e.what());
        }
    }
    const double until = args.time > 0 ? args.time : simulation.grownBy();
    double drawSeconds = 0;
    const uint64_t ticks = std::max<uint64_t>(1, uint64_t(std::ceil(until / args.simulation.dt - 1e-9)));
    if (ticks <= simulation.ticks())
        throw CommandLineError(fmt::format("the saved field is {:g} s old already: ask for a later --time",
                                           simulation.time()));
    const fs::path out(args.out);
    fs::create_directories(out);

    draw::Renderer renderer(context, simulation.species().assets);
    draw::Bounds framed = simulation.grownBounds();
    if (framed.empty()) framed = draw::Bounds{};
    draw::OutputBatch outputs;
    std::string stats;
    std::vector<shared::PlantStatistics> perPlant;
    Progress progress(until, args.simulation.dt);
    const auto start = std::chrono::steady_clock::now();
    const uint64_t firstTick = simulation.ticks();
    std::vector<const turtle::DeviceOrgans*> organs;
    // What --profile counts: the submissions the host waited for, and the batches done again with readbacks.
    uint64_t tickSubmissions = 0, drawingSubmissions = 0, rederived = 0, reinterpreted = 0;
    for (uint64_t k = firstTick; k < ticks; ++k) {
        uint64_t before = context.submissions();
        const field::TickReport report = simulation.tick();
        tickSubmissions += context.submissions() - before;
        before = context.submissions();
        organs = simulation.interpretParts();
        drawingSubmissions += context.submissions() - before;
        rederived += report.rederived;
        reinterpreted += simulation.reinterpretedBatches();
        perPlant = simulation.statistics();
        stats += statsLine(simulation, report, perPlant);
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        progress.show(simulation, double(k + 1 - firstTick) / std::max(seconds, 1e-9));
        const bool last = k + 1 == ticks;
        if (last || (args.frames > 0 && (k + 1) % args.frames == 0)) {
            // Framed on the grown field, so that the camera stays put while the field grows.
            const auto drawStart = std::chrono::steady_clock::now();
            draw::Frame frame = renderer.render(field::organParts(organs), framed, settings);
            drawSeconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - drawStart).count();
            if (args.frames > 0) draw::writePng(outputs, out / fmt::format("frame-{:05}.png", k + 1), frame);
            if (last) {
                draw::writeExr(outputs, out / "final.exr", frame);
                draw::writePng(outputs, out / "final.png", frame);
            }
        }
    }
    if (args.lightSlice || args.lightSection || args.lightVolume || args.occupancySlice) {
        const field::LightVolume light = simulation.lightVolume();
        if (args.lightSlice)
            draw::writePng(outputs, out / "light.png",
                           field::lightSliceImage(field::lightSlice(light, *args.lightSlice)));
        if (args.lightSection)
            draw::writePng(outputs, out / "light-section.png",
                           field::lightSliceImage(field::lightSection(light, *args.lightSection)));
        if (args.occupancySlice)
            draw::writePng(outputs, out / "occupancy.png",
                           field::occupancySliceImage(field::occupancySlice(light, *args.occupancySlice)));
        if (args.lightVolume)
            draw::writePng(outputs, out / "light-volume.png",
                           field::renderWithShade(context, renderer, organs, light, simulation.plants() + 1, framed,
                                                  settings));
    }
    writeText(outputs, out / "stats.jsonl", stats);
    writeText(outputs, out / "plants.csv", plantsTable(simulation, perPlant));
    if (!args.save.empty())
        writeText(outputs, args.save, field::encodeSavedRun({args.simulation, simulation.save()}));
    outputs.commit();
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("%s: %u plants grown for %.1f s in %llu ticks, %llu modules, %.2f s -> %s\n",
                args.simulation.file.c_str(), simulation.standingPlants(), simulation.time(),
                static_cast<unsigned long long>(ticks - firstTick),
                static_cast<unsigned long long>(simulation.modules()), seconds, out.string().c_str());
    if (args.profile) {
        const field::StageSeconds& s = simulation.stageSeconds();
        std::fprintf(stderr,
                     "seconds by stage: derive %.2f, grow %.2f, interpret %.2f, light %.2f, statistics %.2f, "
                     "draw %.2f\n",
                     s.derive, s.grow, s.interpret, s.light, s.statistics, drawSeconds);
        const double counted = double(std::max<uint64_t>(ticks - firstTick, 1));
        std::fprintf(stderr,
                     "submissions waited for a tick: %.2f to derive (and grow, after a step), %.2f to draw (and grow, "
                     "between steps; %u batches); batches done again with readbacks: %llu steps, %llu drawings\n",
                     double(tickSubmissions) / counted, double(drawingSubmissions) / counted, simulation.batches(),
                     static_cast<unsigned long long>(rederived), static_cast<unsigned long long>(reinterpreted));
        std::fputs(context.kernelProfile()->table().c_str(), stderr);
    }
}

} // namespace

void registerRunCommand(CLI::App& app, CommandContext& ctx) {
    auto args = std::make_shared<RunArgs>();
    CLI::App* cmd = app.add_subcommand("run", "Grow a field of plants over simulated time and render it");
    field::SimulationOptions& s = args->simulation;
    CLI::Option* scene = cmd->add_option("scene", s.file,
                    fmt::format("scene (.eco) or grammar (.l, .lsys); none: the built-in garden, {1} plants of {0}",
                                kDefaultSceneName, kDefaultScenePlants));
    cmd->add_option("--time", args->time, "simulated seconds (default: until every plant has grown)")
        ->check(CLI::Range(0.0, 1e9));
    CLI::Option* dt =
        cmd->add_option("--dt", s.dt, "simulated seconds per tick (default 1)")->check(CLI::Range(1e-3, 1e6));
    cmd->add_option("--frames", args->frames, "write a PNG frame every N ticks (default: the last frame only)");
    cmd->add_option("--out", args->out, "folder of the outputs (default: run)");
    CLI::Option* seed =
        cmd->add_option("--seed", s.seed, "seed of the random streams (default: the file's seed, else 0)")
            ->check(CLI::Range(int64_t(0), int64_t(UINT32_MAX)));
    CLI::Option* plants =
        cmd->add_option("--plants", s.plants,
                        "plants in the field; a scene's species take turns (default: the scene's)")
            ->check(CLI::Range(1u, 1000000u));
    CLI::Option* density = addDensityOption(*cmd, s.density);
    CLI::Option* spacing =
        cmd->add_option("--spacing", s.spacing, "distance between plants of a field (default: from a grown plant)")
            ->check(CLI::Range(0.0f, 1e6f));
    addPictureOptions(*cmd, args->picture, "field");
    addColormapOption(*cmd, s.colormap);
    addBackendOption(*cmd, s.backend, "derivation, growth and turtle: gpu (compute kernels) or cpu (references)");
    cmd->add_option("--max-modules", s.maxModules, "module budget (default: sized to this machine's memory)");
    addTimeLimitOption(*cmd, s.maxSeconds);
    cmd->add_option("--device", args->device, "Vulkan device: an index or a name part (see `simeco devices`)");
    cmd->add_option("--save", args->save, "write the field's whole state to FILE at the end");
    cmd->add_option("--light-slice", args->lightSlice,
                    "also write light.png: the light grid's layer at height H at the end, seen from above")
        ->check(CLI::Range(-1e6f, 1e6f));
    cmd->add_option("--occupancy-slice", args->occupancySlice,
                    "also write occupancy.png: which plant holds each voxel of the light grid's layer at height H at "
                    "the end, seen from above");
    cmd->add_flag("--light-volume", args->lightVolume,
                  "also write light-volume.png: the last frame with the light grid's shade drawn among the plants");
    cmd->add_option("--light-section", args->lightSection,
                    "also write light-section.png: the light grid's vertical layer at depth Z (z = Z) at the end, "
                    "seen from the front")
        ->check(CLI::Range(-1e6f, 1e6f));
    cmd->add_flag("--profile", args->profile,
                  "print the seconds of each stage and the GPU time of every kernel, summed over the run, to stderr");
    cmd->add_option("--resume", args->resume,
                    "go on from a state --save wrote (its scene and options; --time counts from the field's start)")
        ->excludes(scene)
        ->excludes(plants)
        ->excludes(density)
        ->excludes(seed)
        ->excludes(dt)
        ->excludes(spacing);
    cmd->callback([args, &ctx] { ctx.exitCode = runReportingErrors([&] { runRun(*args); }); });
}

} // namespace simeco::app
