#include "bench/sim_bench.h"

#include <algorithm>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "bench/timing.h"
#include "compute/shared/particle_layout.h"
#include "draw/renderer.h"
#include "field/simulation.h"
#include "ir/source_loc.h"
#include "vk/context.h"
#include "vk/device_info.h"

namespace simeco::bench {
namespace {

constexpr const char* kSimScene = "scenes/garden.eco";
// What the growth tick reads and writes per particle: its state read, the next state written and copied back (read
// and written), its symbol and its stage.
constexpr std::uint32_t kGrowBytesPerParticle = 4 * sizeof(shared::ParticleState) + 8;

SimEntry measure(const SimBenchOptions& o, const std::string& scene, std::uint32_t plants, const vk::Context& context,
                 draw::Renderer& renderer) {
    SimEntry e;
    e.plants = plants;
    field::SimulationOptions options;
    options.file = scene;
    options.plants = plants;
    field::Simulation simulation(options, &context);
    e.batches = simulation.batches();
    // Untimed, to half the field's life: the plants as they are when most of the field grows.
    while (simulation.time() < simulation.grownBy() / 2) simulation.tick();
    e.time = simulation.time();
    e.modules = simulation.modules();
    draw::RenderSettings settings;
    settings.width = o.width;
    settings.height = o.height;
    settings.samples = o.samples;
    const draw::Bounds framed = simulation.grownBounds();
    std::vector<double> derive, grow, interpret, light, statistics, draw;
    auto tick = [&] {
        const field::StageSeconds before = simulation.stageSeconds();
        const Clock::time_point start = Clock::now();
        simulation.tick();
        Clock::time_point drawn = Clock::now();
        if (e.notDrawn.empty()) {
            try {
                const std::vector<const turtle::DeviceOrgans*> parts = simulation.interpretParts();
                e.organs = 0;
                for (const shared::PlantStatistics& s : simulation.statistics()) e.organs += s.organs;
                drawn = Clock::now();
                renderer.render(field::organParts(parts), framed, settings);
            } catch (const ir::LimitError& error) { // a field larger than the device draws: its growth still runs
                e.notDrawn = error.what();
                drawn = Clock::now();
            }
        }
        const field::StageSeconds& after = simulation.stageSeconds();
        derive.push_back(after.derive - before.derive);
        grow.push_back(after.grow - before.grow);
        interpret.push_back(after.interpret - before.interpret);
        light.push_back(after.light - before.light);
        statistics.push_back(after.statistics - before.statistics);
        draw.push_back(e.notDrawn.empty() ? secondsSince(drawn) : 0.0);
        return secondsSince(start);
    };
    e.tickSeconds = repeatRuns(o.warmUp, o.repeat, tick);
    // The stages of the timed ticks only.
    for (std::vector<double>* v : {&derive, &grow, &interpret, &light, &statistics, &draw})
        v->erase(v->begin(), v->begin() + o.warmUp);
    e.medianTickSeconds = median(e.tickSeconds);
    e.ticksPerSecond = e.medianTickSeconds > 0 ? 1.0 / e.medianTickSeconds : 0;
    e.stages = {median(derive), median(grow), median(interpret), median(light), median(statistics), median(draw)};
    if (e.notDrawn.empty()) {
        const std::vector<draw::OrganPart> parts = field::organParts(simulation.interpretParts());
        for (const draw::Shadows shadows : {draw::Shadows::Volume, draw::Shadows::None}) {
            settings.shadows = shadows;
            const double frame =
                median(repeatRuns(o.warmUp, o.repeat, [&] {
                    const Clock::time_point start = Clock::now();
                    renderer.render(parts, framed, settings);
                    return secondsSince(start);
                }));
            const double tickWork = std::max(e.medianTickSeconds - e.stages.draw, 0.0);
            const double growing = 1.0 / std::max(tickWork + frame, 1e-9);
            const double realTime = std::max(1.0 - tickWork / options.dt, 0.0) / std::max(frame, 1e-9);
            const bool volumes = shadows == draw::Shadows::Volume;
            (volumes ? e.frameShadowsSeconds : e.frameNoShadowsSeconds) = frame;
            (volumes ? e.growingFramesPerSecondShadows : e.growingFramesPerSecondNoShadows) = growing;
            (volumes ? e.realTimeFramesPerSecondShadows : e.realTimeFramesPerSecondNoShadows) = realTime;
            if (shadows == draw::Shadows::Volume) e.shadowVolumes = renderer.drawnOrgans().shadowVolumes;
        }
        for (size_t part = 0; part < parts.size(); ++part) {
            const draw::DrawnOrgans drawn = renderer.drawnOrgans(part);
            for (std::uint32_t kind = 0; kind < shared::kOrganKinds; ++kind) {
                e.drawnNear[kind] += drawn.near[kind];
                e.drawnFar[kind] += drawn.far[kind];
            }
        }
    }
    if (e.stages.grow > 0) {
        e.particlesPerSecond = double(simulation.modules()) / e.stages.grow;
        e.growBytesPerSecond = e.particlesPerSecond * kGrowBytesPerParticle;
    }
    return e;
}

} // namespace

SimBenchReport runSimBenchmark(const SimBenchOptions& options, const std::function<void(const std::string&)>& progress) {
    SimBenchReport report;
    report.options = options;
    report.scene = kSimScene;
    report.bytesPerParticle = sizeof(shared::ParticleState);
    report.growBytesPerParticle = kGrowBytesPerParticle;
    vk::ContextOptions contextOptions;
    contextOptions.device = options.device;
    vk::Context context(contextOptions);
    report.deviceName = context.deviceInfo().name;
    report.deviceType = std::string(vk::deviceTypeName(context.deviceInfo().type));
    report.driver = context.deviceInfo().driverName;
    progress("copy bandwidth");
    report.copy = measureCopyBandwidth(context, options.warmUp, options.repeat);
    draw::Renderer renderer(context);
    if (report.options.samples == 0) report.options.samples = draw::interactiveSamples(context);
    draw::checkSamples(context, report.options.samples);
    const std::string scene = (std::filesystem::path(options.root) / kSimScene).string();
    const std::vector<std::uint32_t> fields = !options.fields.empty() ? options.fields
                                              : options.quick         ? std::vector<std::uint32_t>{10, 100}
                                                                      : std::vector<std::uint32_t>{100, 1000, 10000};
    for (std::uint32_t plants : fields) {
        progress(fmt::format("{} plants", plants));
        try {
            SimEntry e = measure(report.options, scene, plants, context, renderer);
            if (report.copy && report.copy->bytesPerSecond > 0)
                e.copyFraction = e.growBytesPerSecond / report.copy->bytesPerSecond;
            report.entries.push_back(std::move(e));
        } catch (const std::exception& error) {
            SimEntry e;
            e.plants = plants;
            e.status = "failed";
            e.reason = error.what();
            report.entries.push_back(std::move(e));
        }
    }
    return report;
}

} // namespace simeco::bench
