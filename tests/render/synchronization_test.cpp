// The growing field's submissions under the validation layer's synchronization checks: every pass's reads and writes
// ordered against the others' by a barrier. A hazard (a kernel reading what one recorded before it may still be
// writing, or writing what one before it may still be reading) is a race on a device that runs them at once, which
// lavapipe, running them one after another, rarely shows.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "draw/render_pass.h"
#include "draw/renderer.h"
#include "field/simulation.h"
#include "vk/context.h"

namespace simeco::test {
namespace {

TEST(SynchronizationTest, AGrowingFieldDerivedDrawnAndRenderedInBatchesHasNoHazards) {
    vk::ValidationLog log; // outlives the context
    vk::ContextOptions contextOptions;
    contextOptions.validation = true;
    contextOptions.synchronizationValidation = true;
    contextOptions.validationLog = &log;
    vk::Context context(contextOptions);

    field::SimulationOptions options;
    options.file = std::string(SIMECO_SOURCE_DIR) + "/scenes/garden.eco";
    options.plants = 12;
    options.plantsPerBatch = 3; // four batches, recorded one after another in each submission
    options.seed = 3;
    options.dt = 1.5f; // a step every other tick: ticks that derive and ticks that only grow
    field::Simulation simulation(options, &context);
    draw::Renderer renderer(context, simulation.species().assets);
    draw::RenderSettings settings;
    settings.width = 160;
    settings.height = 120;
    settings.shadows = draw::Shadows::Volume;
    uint32_t derived = 0;
    for (int tick = 0; tick < 8; ++tick) {
        derived += simulation.tick().derived;
        const std::vector<const turtle::DeviceOrgans*> parts = simulation.interpretParts();
        // One sample a pixel, then twice multisampled into the same target.
        if (tick % 4 != 3) continue;
        settings.samples = tick == 3 ? 1u : draw::defaultSamples(context);
        for (int frame = 0; frame < (tick == 3 ? 1 : 2); ++frame)
            renderer.render(field::organParts(parts), simulation.grownBounds(), settings);
    }
    EXPECT_GT(derived, 0u);
    const std::vector<std::string> messages = log.messages();
    EXPECT_TRUE(messages.empty()) << messages.size() << " messages, the first: " << messages.front();
}

} // namespace
} // namespace simeco::test
