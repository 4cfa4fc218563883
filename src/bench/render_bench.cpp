#include "bench/render_bench.h"

#include <algorithm>
#include <filesystem>
#include <memory>
#include <vector>
#include <stdexcept>

#include <fmt/format.h>

#include "bench/suite.h"
#include "bench/timing.h"
#include "compute/shared/turtle_state_layout.h"
#include "cpu/derive.h"
#include "draw/renderer.h"
#include "field/field.h"
#include "ir/source_loc.h"
#include "lang/load_grammar.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_gpu.h"
#include "vk/context.h"
#include "vk/device_info.h"
#include "vk/submission.h"

namespace simeco::bench {
namespace {

// The README's tree: branching, tapering stems with joints, leaves of every segment's colour.
constexpr const char* kRenderGrammar = "grammars/abop/fig2.8-ternary.l";
constexpr int kMaxSteps = 8;

Timed timed(const RenderBenchOptions& o, std::uint64_t organs, const std::function<void()>& run) {
    Timed t;
    t.runSeconds = repeatRuns(o.warmUp, o.repeat, [&] {
        Clock::time_point start = Clock::now();
        run();
        return secondsSince(start);
    });
    t.medianSeconds = median(t.runSeconds);
    if (t.medianSeconds > 0) t.instancesPerSecond = static_cast<double>(organs) / t.medianSeconds;
    return t;
}

// Ticks as a growth loop runs them: draw::kFramesInFlight in flight, each into its own target, the host waiting
// for the oldest (and reading its frame back) before it records the next; the time per tick.
constexpr int kTicksPerRun = 8;
Timed ticksInFlight(const RenderBenchOptions& o, std::uint64_t organs, const vk::Context& context,
                    turtle::GpuTurtle& gpuTurtle, draw::Renderer& renderer, const stream::DeviceModules& modules,
                    const draw::FrameSetup& setup) {
    const turtle::TurtleRoom room = gpuTurtle.lastRoom();
    std::vector<std::unique_ptr<draw::RenderTarget>> targets;
    for (std::uint64_t k = 0; k < draw::kFramesInFlight; ++k)
        targets.push_back(renderer.makeTarget(setup.settings.width, setup.settings.height, setup.settings.samples));
    Timed t;
    t.runSeconds = repeatRuns(o.warmUp, o.repeat, [&] {
        Clock::time_point start = Clock::now();
        std::vector<vk::Submission> inFlight(targets.size());
        for (std::size_t tick = 0; tick < kTicksPerRun + targets.size(); ++tick) {
            std::size_t slot = tick % targets.size();
            if (inFlight[slot].pending()) {
                inFlight[slot].wait();
                if (!gpuTurtle.recorded().fit) throw std::logic_error("the tick's string outgrew the room it needed");
                renderer.readBack(*targets[slot], setup);
            }
            if (tick >= kTicksPerRun) continue;
            inFlight[slot] = context.submit([&](VkCommandBuffer cmd) {
                const turtle::DeviceOrgans& ticked = gpuTurtle.record(cmd, modules, {}, room);
                renderer.record(cmd, *targets[slot], ticked.instances, ticked.table, setup);
            });
        }
        return secondsSince(start) / kTicksPerRun;
    });
    t.medianSeconds = median(t.runSeconds);
    if (t.medianSeconds > 0) t.instancesPerSecond = static_cast<double>(organs) / t.medianSeconds;
    return t;
}

// The most steps (up to kMaxSteps) whose string for `plants` plants stays within `cap` modules.
stream::ModuleString deriveField(const ir::Grammar& g, std::uint32_t plants, std::uint64_t cap, int& steps) {
    stream::ModuleString best;
    steps = 0;
    for (int k = 0; k <= kMaxSteps; ++k) {
        stream::DeriveOptions options;
        options.steps = k;
        options.plants = plants;
        options.homomorphism = true;
        options.maxModules = cap;
        try {
            best = cpu::deriveCpu(g, options).string;
            steps = k;
        } catch (const ir::LimitError&) {
            break;
        }
    }
    return best;
}

} // namespace

RenderBenchReport runRenderBenchmark(const RenderBenchOptions& options,
                                     const std::function<void(const std::string&)>& progress) {
    RenderBenchReport report;
    report.options = options;
    report.grammar = kRenderGrammar;
    std::string root = options.root.empty() ? defaultSuiteRoot() : options.root;
    ir::Grammar g = lang::loadGrammarFile((std::filesystem::path(root) / kRenderGrammar).string());

    vk::ContextOptions contextOptions;
    contextOptions.device = options.device;
    vk::Context context(contextOptions);
    const vk::PhysicalDeviceInfo& info = context.deviceInfo();
    report.deviceName = info.name;
    report.deviceType = std::string(vk::deviceTypeName(info.type));
    report.driver = info.driverName;
    progress(fmt::format("device: {} ({}); measuring copy bandwidth", report.deviceName, report.deviceType));
    report.copy = measureCopyBandwidth(context, options.warmUp, options.repeat);
    if (report.options.samples == 0) report.options.samples = draw::interactiveSamples(context);
    draw::checkSamples(context, report.options.samples);

    // The turtle keeps a step per module in one buffer: the device's largest binding bounds a field.
    std::uint64_t cap = context.limits().maxStorageBufferRange / sizeof(shared::TurtleStep);
    if (options.maxModules > 0) cap = std::min(cap, options.maxModules);
    if (options.quick) cap = std::min<std::uint64_t>(cap, 20'000);

    turtle::TurtleCommands commands = turtle::turtleCommands(g.alphabet);
    std::vector<turtle::TurtleSettings> species{turtle::turtleSettings(g, g.alphabet)};
    turtle::GpuTurtle gpuTurtle(context, commands, species);
    draw::Renderer renderer(context);

    std::vector<std::uint32_t> plantCounts =
        options.quick ? std::vector<std::uint32_t>{1, 10} : std::vector<std::uint32_t>{1, 10, 100, 1000, 10000};
    for (std::uint32_t plants : plantCounts) {
        RenderEntry e;
        e.plants = plants;
        try {
            stream::ModuleString string = deriveField(g, plants, cap, e.steps);
            e.modules = string.size();
            progress(fmt::format("{} plants: {} steps, {} modules", plants, e.steps, e.modules));
            turtle::UploadedModules modules(context, string);
            // Every run writes the same organs; the last run's stay in the turtle for the frames.
            const turtle::DeviceOrgans* written = nullptr;
            e.gpuTurtle = timed(options, 0, [&] { written = &gpuTurtle.interpret(modules.view(), {}); });
            const turtle::DeviceOrgans& organs = *written;
            e.levels = gpuTurtle.lastLevels();
            e.bytesMoved = gpuTurtle.lastBytesMoved();
            field::OrganExtent extent = field::organExtent(context, organs);
            e.organs = extent.organs;
            if (e.gpuTurtle.medianSeconds > 0) {
                e.gpuTurtle.instancesPerSecond = double(e.organs) / e.gpuTurtle.medianSeconds;
                if (report.copy && report.copy->bytesPerSecond > 0)
                    e.copyFraction = double(e.bytesMoved) / e.gpuTurtle.medianSeconds / report.copy->bytesPerSecond;
            }
            if (options.runCpu)
                e.cpuTurtle = timed(options, e.organs, [&] { turtle::interpretCpu(string, commands, species, {}); });

            draw::RenderSettings settings;
            settings.width = options.width;
            settings.height = options.height;
            settings.samples = report.options.samples;
            for (draw::Shadows shadows : {draw::Shadows::Volume, draw::Shadows::None}) {
                settings.shadows = shadows;
                Timed t = timed(options, e.organs,
                                [&] { renderer.render(organs.instances, organs.table, extent.bounds, settings); });
                (shadows == draw::Shadows::Volume ? e.frameWithShadows : e.frameWithoutShadows) = t;
            }
            // A growth tick: the string interpreted again and drawn in one submission, with no wait inside.
            settings.shadows = draw::Shadows::None;
            draw::FrameSetup setup = renderer.prepare(organs.table, extent.bounds, settings);
            const draw::RenderTarget& target =
                renderer.offscreenTarget(settings.width, settings.height, setup.settings.samples);
            const turtle::TurtleRoom room = gpuTurtle.lastRoom();
            e.tick = timed(options, e.organs, [&] {
                context.submitAndWait([&](VkCommandBuffer cmd) {
                    const turtle::DeviceOrgans& ticked = gpuTurtle.record(cmd, modules.view(), {}, room);
                    renderer.record(cmd, target, ticked.instances, ticked.table, setup);
                });
                if (!gpuTurtle.recorded().fit) throw std::logic_error("the tick's string outgrew the room it needed");
                renderer.readBack(target, setup);
            });
            e.ticksInFlight = ticksInFlight(options, e.organs, context, gpuTurtle, renderer, modules.view(), setup);
        } catch (const std::exception& error) {
            e.status = "failed";
            e.reason = error.what();
        }
        report.entries.push_back(std::move(e));
    }
    return report;
}

} // namespace simeco::bench
