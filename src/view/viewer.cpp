#include "view/viewer.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "draw/image_writers.h"
#include "draw/renderer.h"
#include "ir/source_loc.h"
#include "view/growth_clock.h"
#include "view/orbit_camera.h"
#include "view/overlay.h"
#include "view/panel.h"
#include "view/presenter.h"
#include "view/steering.h"
#include "view/swapchain.h"
#include "view/view_controls.h"
#include "view/window.h"
#include "vk/context.h"
#include "vk/vk_error.h"

namespace simeco::view {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// Ticks of leaf area and light the panel's plot shows.
constexpr size_t kHistoryLength = 240;

// A growing field and what draws it.
struct LiveField {
    std::unique_ptr<field::Simulation> simulation;
    std::unique_ptr<draw::Renderer> renderer;
    draw::RenderSettings settings;
    draw::Bounds framed; // the grown field's bounds: the camera stays put while it grows
    std::vector<const turtle::DeviceOrgans*> organs;
    std::vector<shared::PlantStatistics> statistics;
    std::vector<std::uint64_t> plantModules; // read from the device when a picked plant needs them, once a drawing
    std::vector<SpeciesHistory> history;
    double tickSeconds = 0; // wall-clock seconds of the last tick, its organs drawn again with it
};

LiveField makeField(const vk::Context& context, const ViewOptions& options, const field::SimulationOptions& sim) {
    LiveField f;
    f.simulation = std::make_unique<field::Simulation>(sim, &context);
    f.renderer = std::make_unique<draw::Renderer>(context, f.simulation->species().assets);
    f.settings = options.settingsFor(*f.simulation);
    f.framed = f.simulation->grownBounds();
    if (f.framed.empty()) f.framed = draw::Bounds{};
    return f;
}

std::vector<std::string> speciesNames(const field::Simulation& s) {
    std::vector<std::string> names;
    for (std::uint32_t p = 0; p < s.plants() && names.size() < s.species().species.size(); ++p)
        if (std::find(names.begin(), names.end(), s.speciesName(p)) == names.end()) names.push_back(s.speciesName(p));
    while (names.size() < s.species().species.size()) names.push_back(fmt::format("species {}", names.size()));
    return names;
}

// The organs drawn again after ticks, with each species' leaf area and light added to its history.
void drawAgain(LiveField& f) {
    f.organs = f.simulation->interpretParts();
    f.statistics = f.simulation->statistics();
    f.plantModules.clear();
    const std::vector<std::string> names = speciesNames(*f.simulation);
    if (f.history.size() != names.size()) {
        f.history.clear();
        for (const std::string& n : names) f.history.push_back({n, {}, {}});
    }
    std::vector<float> leafArea(names.size(), 0.0f), light(names.size(), 0.0f);
    for (std::uint32_t p = 0; p < f.statistics.size(); ++p) {
        if (!f.simulation->present(p)) continue;
        const auto at = std::find(names.begin(), names.end(), f.simulation->speciesName(p));
        if (at == names.end()) continue;
        leafArea[size_t(at - names.begin())] += f.statistics[p].leafArea;
        light[size_t(at - names.begin())] += f.statistics[p].light;
    }
    for (size_t s = 0; s < names.size(); ++s) {
        SpeciesHistory& h = f.history[s];
        h.leafArea.push_back(leafArea[s]);
        h.light.push_back(light[s]);
        if (h.leafArea.size() > kHistoryLength) {
            h.leafArea.erase(h.leafArea.begin());
            h.light.erase(h.light.begin());
        }
    }
}

void tickField(LiveField& f, std::uint32_t ticks) {
    const auto start = Clock::now();
    for (std::uint32_t k = 0; k < ticks; ++k) f.simulation->tick();
    drawAgain(f);
    f.tickSeconds = secondsSince(start) / ticks;
}

using UniqueFence = vk::UniqueFence;

// A frame in flight: its command buffer, fence, the semaphore its window image's acquisition signals, and the
// offscreen target the renderer draws it into.
struct FrameSlot {
    VkCommandBuffer cmd = VK_NULL_HANDLE;
    UniqueFence fence;
    UniqueSemaphore acquired;
    std::unique_ptr<draw::RenderTarget> target;
    draw::FrameSetup setup;
    bool submitted = false;
};

UniqueFence makeSignalledFence(VkDevice device) {
    VkFenceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    info.flags = VK_FENCE_CREATE_SIGNALED_BIT;
    VkFence fence = VK_NULL_HANDLE;
    VK_CHECK(vkCreateFence(device, &info, nullptr, &fence));
    return UniqueFence(device, fence);
}

void waitFor(VkDevice device, const FrameSlot& slot) {
    const VkFence fence = slot.fence.get();
    VK_CHECK(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX));
}

void writeScreenshot(const fs::path& path, const draw::Frame& frame) {
    if (path.extension() == ".exr")
        draw::writeExr(path, frame);
    else
        draw::writePng(path, frame);
    std::printf("screenshot: %s\n", path.string().c_str());
}

// The next free name beside `path` for the panel's screenshot button: path itself, then name-2.png, ...
fs::path nextScreenshot(const fs::path& path, std::uint32_t& taken) {
    ++taken;
    if (taken == 1) return path;
    return path.parent_path() / fmt::format("{}-{}{}", path.stem().string(), taken, path.extension().string());
}

// Waits for the device to be done with everything when the viewer leaves, by return or by throw, before the
// objects it used go.
struct IdleOnExit {
    VkDevice device;
    ~IdleOnExit() { vkDeviceWaitIdle(device); }
};

struct CommandPool {
    VkDevice device;
    VkCommandPool pool = VK_NULL_HANDLE;
    CommandPool(VkDevice d, std::uint32_t family) : device(d) {
        VkCommandPoolCreateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
        info.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
        info.queueFamilyIndex = family;
        VK_CHECK(vkCreateCommandPool(device, &info, nullptr, &pool));
    }
    ~CommandPool() { vkDestroyCommandPool(device, pool, nullptr); }
};

// A reloaded scene's controls with the user's kept: how the field runs, and the sun and the species' factors where
// the scene keeps its species.
ViewControls keptControls(ViewControls scene, const ViewControls& user) {
    if (scene.species.size() == user.species.size()) {
        for (size_t s = 0; s < scene.species.size(); ++s) scene.species[s].factors = user.species[s].factors;
        scene.sunAzimuth = user.sunAzimuth;
        scene.sunElevation = user.sunElevation;
    }
    scene.timeScale = user.timeScale;
    scene.paused = user.paused;
    scene.seed = user.seed;
    scene.plants = user.plants;
    scene.density = user.density;
    scene.renderScale = user.renderScale;
    scene.samples = user.samples;
    return scene;
}

std::string loadError(const std::exception& e) {
    if (const auto* input = dynamic_cast<const ir::InputError*>(&e)) return input->formatted();
    return fmt::format("simeco: error: {}", e.what());
}

} // namespace

void runViewer(const ViewOptions& options) {
    Window window(options.width, options.height, "simeco view: " + options.simulation.file);
    Steering steering(window.handle());

    vk::ContextOptions contextOptions;
    contextOptions.device = options.device;
    contextOptions.instanceExtensions = Window::instanceExtensions();
    contextOptions.presentsFrom = &Window::presentsFrom;
    vk::Context context(contextOptions);
    const VkDevice device = context.device();
    Surface surface(context.instance().get(), window);
    Swapchain swapchain(context, surface.get(), window.framebufferSize());
    Overlay overlay(context, window.handle(), swapchain);
    Presenter presenter(context);
    CommandPool pool(device, context.queueFamily());
    std::vector<FrameSlot> slots(draw::kFramesInFlight);
    for (FrameSlot& slot : slots) {
        VkCommandBufferAllocateInfo info{};
        info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
        info.commandPool = pool.pool;
        info.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
        info.commandBufferCount = 1;
        VK_CHECK(vkAllocateCommandBuffers(device, &info, &slot.cmd));
        slot.fence = makeSignalledFence(device);
        slot.acquired = makeSemaphore(device);
    }
    const auto waitForFrames = [&] {
        for (const FrameSlot& slot : slots) waitFor(device, slot);
    };
    GrowthClock growth(options.simulation.dt);
    GrowthRate growthRate;
    // Another field in place of the drawn one: its renderer makes the frames' targets anew, its time starts anew.
    const auto replaceField = [&](LiveField& field, LiveField&& next) {
        waitForFrames();
        for (FrameSlot& slot : slots) slot.target.reset();
        field = std::move(next);
        growth.restart();
        growthRate.restart();
    };

    field::SimulationOptions simulationOptions = options.simulation;
    LiveField live = makeField(context, options, simulationOptions);
    IdleOnExit idleOnExit{device};
    ViewControls controls = controlsFor(live.simulation->environment(), live.settings, speciesNames(*live.simulation));
    controls.seed = simulationOptions.seed >= 0 ? std::uint32_t(simulationOptions.seed) : 0;
    controls.plants = simulationOptions.plants;
    controls.density = simulationOptions.density;
    if (controls.samples == 0) controls.samples = draw::interactiveSamples(context);
    for (const std::string& s : options.settings) applySetting(controls, s);
    draw::checkSamples(context, controls.samples);
    const std::uint32_t drawableSamples = draw::drawableSampleCounts(context);
    live.simulation->setEnvironment(environmentOf(controls, live.simulation->environment()));
    const auto ticksBefore = std::uint32_t(std::ceil(options.startTime / simulationOptions.dt - 1e-9));
    if (ticksBefore > 0)
        tickField(live, ticksBefore);
    else
        drawAgain(live);
    OrbitCamera orbit(live.settings.camera.value_or(draw::Camera{}), draw::frameCamera(live.framed, live.settings));

    // The scene file, looked at for changes.
    const bool watching = fs::exists(simulationOptions.file) && simulationOptions.sceneText.empty();
    std::optional<fs::file_time_type> seen;
    if (watching) seen = fs::last_write_time(simulationOptions.file);
    auto lastLook = Clock::now();
    std::string error;

    std::uint64_t frames = 0;
    std::uint32_t screenshots = 0;
    const auto opened = Clock::now();
    double frameSeconds = 0;
    std::vector<double> frameTimes; // every frame's after the first
    auto lastFrame = Clock::now();
    std::optional<std::uint32_t> pickedPlant;
    std::optional<glm::dvec2> click; // to look up once its frame is drawn
    while (!window.closing()) {
        glfwPollEvents();
        const auto now = Clock::now();
        frameSeconds = std::chrono::duration<double>(now - lastFrame).count();
        lastFrame = now;
        if (frames > 0) frameTimes.push_back(frameSeconds);

        // The scene edited on disk: a new field from it, or its error beside the field that goes on.
        if (watching && std::chrono::duration<double>(now - lastLook).count() >= options.watchSeconds) {
            lastLook = now;
            std::error_code failed;
            const fs::file_time_type written = fs::last_write_time(simulationOptions.file, failed);
            if (!failed && written != seen) {
                seen = written;
                try {
                    replaceField(live, makeField(context, options, simulationOptions));
                    controls = keptControls(
                        controlsFor(live.simulation->environment(), live.settings, speciesNames(*live.simulation)),
                        controls);
                    live.simulation->setEnvironment(environmentOf(controls, live.simulation->environment()));
                    drawAgain(live);
                    error.clear();
                    std::fprintf(stderr, "%s: reloaded\n", simulationOptions.file.c_str());
                } catch (const std::exception& e) {
                    error = loadError(e);
                    std::fprintf(stderr, "%s\n", error.c_str());
                }
            }
        }

        overlay.begin();
        PanelFigures figures;
        figures.frameSeconds = frameSeconds;
        figures.growthPerSecond = growthRate.perSecond();
        figures.tickSeconds = live.tickSeconds;
        figures.time = live.simulation->time();
        figures.plants = live.simulation->standingPlants();
        figures.modules = live.simulation->modules();
        for (const shared::PlantStatistics& s : live.statistics) figures.instances += s.organs;
        figures.history = live.history;
        figures.error = error;
        figures.drawableSamples = drawableSamples;
        if (pickedPlant && *pickedPlant < live.statistics.size()) {
            const shared::PlantStatistics& s = live.statistics[*pickedPlant];
            if (live.plantModules.empty()) live.plantModules = live.simulation->plantModules();
            figures.picked = PickedPlant{*pickedPlant, live.simulation->speciesName(*pickedPlant),
                                         live.simulation->time(), live.plantModules[*pickedPlant], s.light,
                                         s.leafArea, s.height};
        }
        const PanelActions actions = drawPanel(controls, figures);
        if (actions.environmentChanged)
            live.simulation->setEnvironment(environmentOf(controls, live.simulation->environment()));
        if (actions.reset) {
            field::SimulationOptions reset = simulationOptions;
            reset.seed = controls.seed;
            reset.plants = controls.plants;
            reset.density = controls.density;
            try {
                replaceField(live, makeField(context, options, reset));
                live.simulation->setEnvironment(environmentOf(controls, live.simulation->environment()));
                drawAgain(live);
                simulationOptions = reset;
                error.clear();
            } catch (const std::exception& e) {
                error = loadError(e);
                std::fprintf(stderr, "%s\n", error.c_str());
            }
        }

        const VkExtent2D extent = swapchain.extent();
        const std::optional<glm::dvec2> at =
            steering.steer(orbit, overlay.wantsMouse(), overlay.wantsKeyboard(), float(extent.height));
        if (at) click = at;

        // The field grows by the viewer's clock, a scripted view's (--frames) by a second a frame, so that it grows
        // alike on every device; paused, a step at a time. Its organs are drawn again once the frames reading them
        // are done.
        const double clockSeconds = options.frames > 0 ? 1.0 : std::min(frameSeconds, 1.0);
        const std::uint32_t ticks = controls.paused ? (actions.step ? 1u : 0u)
                                                    : growth.ticksAfter(clockSeconds, controls.timeScale);
        if (ticks > 0) {
            waitForFrames();
            tickField(live, ticks);
        }
        growthRate.add(secondsSince(opened), live.simulation->time());

        if (extent.width == 0 || extent.height == 0) { // minimised
            overlay.cancel();
            glfwWaitEventsTimeout(0.1);
            continue;
        }
        FrameSlot& slot = slots[frames % slots.size()];
        waitFor(device, slot);
        const std::optional<std::uint32_t> image = swapchain.acquire(slot.acquired.get());
        if (!image) {
            overlay.cancel();
            swapchain.recreate(window.framebufferSize());
            overlay.resize(swapchain);
            continue;
        }
        draw::RenderSettings settings = live.settings;
        settings.width = std::max(1u, std::uint32_t(std::lround(float(extent.width) * controls.renderScale)));
        settings.height = std::max(1u, std::uint32_t(std::lround(float(extent.height) * controls.renderScale)));
        settings.antialias = 1; // the render scale supersamples, the presenter's scaling averages
        settings.samples = controls.samples;
        settings.camera = orbit.camera();
        settings.shadows = controls.shadows ? draw::Shadows::Volume : draw::Shadows::None;
        settings.style = controls.style;
        settings.sunDirection = sunDirection(controls.sunAzimuth, controls.sunElevation);
        settings.sunColor = live.settings.sunColor * controls.sunIntensity;
        if (!slot.target || slot.target->width() != settings.width || slot.target->height() != settings.height ||
            slot.target->samples() != settings.samples)
            slot.target = live.renderer->makeTarget(settings.width, settings.height, settings.samples);
        const std::vector<draw::OrganPart> parts = field::organParts(live.organs);
        slot.setup = live.renderer->prepare(parts, live.framed, settings);

        VK_CHECK(vkResetCommandBuffer(slot.cmd, 0));
        VkCommandBufferBeginInfo begin{};
        begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
        begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
        VK_CHECK(vkBeginCommandBuffer(slot.cmd, &begin));
        live.renderer->record(slot.cmd, *slot.target, parts, slot.setup);
        presenter.record(slot.cmd, draw::Renderer::finalColor(*slot.target, slot.setup), settings.width,
                         settings.height, swapchain, *image);
        overlay.record(slot.cmd, *image);
        VK_CHECK(vkEndCommandBuffer(slot.cmd));

        const VkFence fence = slot.fence.get();
        VK_CHECK(vkResetFences(device, 1, &fence));
        const VkSemaphore acquired = slot.acquired.get();
        const VkSemaphore drawn = swapchain.drawn(*image);
        const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
        VkSubmitInfo submit{};
        submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
        submit.waitSemaphoreCount = 1;
        submit.pWaitSemaphores = &acquired;
        submit.pWaitDstStageMask = &waitStage;
        submit.commandBufferCount = 1;
        submit.pCommandBuffers = &slot.cmd;
        submit.signalSemaphoreCount = 1;
        submit.pSignalSemaphores = &drawn;
        VK_CHECK(vkQueueSubmit(context.queue(), 1, &submit, fence));
        if (!swapchain.present(*image)) {
            swapchain.recreate(window.framebufferSize());
            overlay.resize(swapchain);
        }
        ++frames;
        if (frames == 1) std::fprintf(stderr, "%s: the first frame is drawn\n", simulationOptions.file.c_str());

        // A click picks the plant under it, read from the frame's plant ids once it is drawn.
        if (click) {
            waitFor(device, slot);
            int windowWidth = 1, windowHeight = 1;
            glfwGetWindowSize(window.handle(), &windowWidth, &windowHeight);
            const std::uint32_t w = slot.target->width(), h = slot.target->height();
            const auto px = std::uint32_t(std::clamp(click->x * w / std::max(windowWidth, 1), 0.0, double(w - 1)));
            const auto py = std::uint32_t(std::clamp(click->y * h / std::max(windowHeight, 1), 0.0, double(h - 1)));
            const auto* ids = reinterpret_cast<const std::uint32_t*>(slot.target->plant().mapped());
            const std::uint32_t plant = ids[size_t(py) * w + px];
            pickedPlant = plant == draw::Frame::kNoId ? std::nullopt : std::optional<std::uint32_t>(plant);
            if (pickedPlant)
                std::fprintf(stderr, "picked plant %u (%s)\n", plant, live.simulation->speciesName(plant).c_str());
            else
                std::fprintf(stderr, "picked no plant\n");
            click.reset();
        }
        const bool last = (options.frames > 0 && frames >= options.frames) ||
                          (options.seconds > 0 && secondsSince(opened) >= options.seconds);
        if ((actions.screenshot || last) && !options.screenshot.empty()) {
            waitFor(device, slot);
            writeScreenshot(nextScreenshot(options.screenshot, screenshots),
                            live.renderer->readBack(*slot.target, slot.setup));
        }
        if (last) break;
    }
    std::sort(frameTimes.begin(), frameTimes.end());
    const double median = frameTimes.empty() ? 0.0 : frameTimes[frameTimes.size() / 2];
    std::printf("%s: %llu frames, %.1f s of growth, %u plants, %llu modules, median frame %.1f ms (%.2f frames/s)\n",
                simulationOptions.file.c_str(), static_cast<unsigned long long>(frames), live.simulation->time(),
                live.simulation->standingPlants(), static_cast<unsigned long long>(live.simulation->modules()),
                median * 1e3, median > 0 ? 1.0 / median : 0.0);
}

} // namespace simeco::view
