// The growing field's state, shared by the files that implement field::Simulation: its construction, environment
// and saved state (simulation.cpp), its tick (simulation_tick.cpp) and its drawing (simulation_drawing.cpp).
// Private to src/field/.
#pragma once

#include "field/simulation.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "compute/shared/growth_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "cpu/derive.h"
#include "field/field_parts.h"
#include "field/field_placement.h"
#include "field/grown_plants.h"
#include "field/obstacles.h"
#include "field/plant_statistics.h"
#include "gpu/derive_gpu.h"
#include "grow/environment.h"
#include "grow/growth_tables.h"
#include "grow/light_grid.h"
#include "grow/tick_cpu.h"
#include "grow/tick_gpu.h"
#include "ir/source_loc.h"
#include "ir/species.h"
#include "lang/color_map.h"
#include "lang/eco_parser.h"
#include "turtle/organ_merge.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_settings.h"
#include "vk/buffer.h"
#include "vk/context.h"
#include "vk/region_clock.h"

namespace simeco::field {

using Clock = std::chrono::steady_clock;
inline double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The drawn modules a batch of plants may hold, by the grown plants' count: half of what the turtle's largest
// per-module buffer (TurtleStep) holds in one storage binding of the device (kBatchModules where it binds what
// every device binds, 128 MiB; 32 times as many where it binds 4 GiB, as GPUs commonly do), the other half left to
// plants that grow larger than the one grown before the field. The field goes on alike however it is batched, and
// its saved state is every plant's, so each device takes batches as large as it binds.
inline uint64_t batchDrawnModules(const vk::Context* context) {
    if (!context) return kBatchModules;
    return context->limits().maxStorageBufferRange / sizeof(shared::TurtleStep) / 2;
}

// The gravity relative to which a scene's Gravity bends its plants (grow::GrowingSpecies::relativeGravity).
constexpr float kEarthGravity = 9.81f;

template <typename T> std::vector<T> slice(const std::vector<T>& v, uint32_t first, uint32_t count) {
    return std::vector<T>(v.begin() + first, v.begin() + first + count);
}

// Plants [first, first + count) of the field, derived and grown on their own: each stage of the field runs batch by
// batch, so that no buffer binds more than a batch's modules.
struct Batch {
    uint32_t first = 0, count = 0;
    std::vector<float> deriveTimes;
    turtle::FieldOptions field; // its plants' placements
    std::unique_ptr<gpu::GpuDeriver> deriver;
    std::unique_ptr<grow::GpuGrowth> growth;
    std::unique_ptr<cpu::SteppedDerivation> reference;
    stream::DeriveOptions deriverOptions; // its plants, seed and budget
    std::vector<float> vigour;            // per plant (empty: 1)
    uint64_t modules = 0;
    // What the batch's last interpretation took, while its drawn string is the one interpreted then (no step derived
    // since), or before the first a seedling's room: the next drawing records the turtle within it, in one submission
    // with the grown sizes, the light and the statistics of every such batch, and reads nothing back between them.
    std::optional<turtle::TurtleRoom> room;
    // Whether `room` is roomAfterStep()'s guess, not yet drawn in: a step after it gets none (guesses on guesses
    // would double the levels at every step not drawn).
    bool roomGuessed = false;
    // Where that recording leaves its organs and its status, and where an interpretation's organs are kept: the
    // batch's own, until the field's merge.
    turtle::TurtleTarget target;
    // Its plants' statistics on the device (each batch its own: their base heights stay uploaded).
    std::unique_ptr<GpuPlantStatistics> statistics;
};

struct Simulation::Impl {
    const vk::Context* context = nullptr;
    SimulationOptions options;
    grow::GrowingSpecies g;
    stream::DeriveOptions derive;
    uint32_t seed = 0;
    grow::GrowthTables tables;
    std::vector<float> deriveTimes;
    std::vector<float> nextStep;
    std::vector<shared::PlantPlacement> placements;
    std::vector<uint8_t> absent; // per plant: an empty slot of a field of populations
    std::vector<float> vigour;   // per plant: the factor on its growth rates (empty: 1)
    // The populations' per-plant variation of the vigour, before the climate's factor; the stage rows before the
    // live environment's factors.
    std::vector<float> plantVigour;
    grow::GrowthTables sceneTables;
    LiveEnvironment live;
    GrownPlants grown;
    double time = 0;
    uint32_t ticks = 0;
    turtle::TurtleCommands commands;
    std::vector<turtle::TurtleSettings> turtles;
    std::vector<Batch> batches;

    // Drawing: the turtle kernels, the batches' organs merged, each plant's statistics of the last interpret().
    std::unique_ptr<turtle::GpuTurtle> turtle;
    std::unique_ptr<turtle::OrganMerge> merge;
    turtle::DeviceOrgans uploaded;  // the CPU backend's organs
    turtle::DeviceOrgans obstacles; // the scene's, uploaded once where it has any
    bool hasObstacles() const { return g.scene && !g.scene->obstacles.empty(); }
    // The obstacles' organs, uploaded at the first call.
    const turtle::DeviceOrgans& obstacleOrganBuffers();
    std::vector<shared::PlantStatistics> lastStatistics;
    bool drawn = false;
    StageSeconds seconds;
    // The light grid (grow/light_grid.h) over the field's grown extent, made at the first interpretation: each
    // interpretation gives the organs the light of the last one's grid, then splats them for the next.
    std::unique_ptr<grow::GpuLightGrid> lightGpu;
    std::unique_ptr<grow::LightGridCpu> lightCpu;
    std::vector<shared::LightDirection> lightFrom; // the sun's and the sky's, as the scene sets them
    float openLight = 0.0f;                        // their light in the open, which organs grow by in full
    bool answersQueries = false; // the alphabet spells cpfg's `?E`
    // The drawing of a resumed state: its organs are splatted into the grid, as the saved run's last drawing left
    // it, and its particles and queries keep the light they were saved with (that drawing's, from the grid before).
    bool splatsOnly = false;
    void chooseLight();
    void startEnvironment();
    void applyClimate();
    // cpfg's ?E queries of the field's drawn string (the batches' one after the other, from `drawnStarts`, each
    // module's derived one in `origins`), answered from the last drawing's light grid into the derived strings.
    void answerQueriesOnHost(const stream::ModuleString& field, const std::vector<size_t>& drawnStarts,
                             const std::vector<std::vector<uint32_t>>& origins);
    void prepareLight(const draw::Bounds& extent, uint32_t standing);

    grow::TickSettings settings(const Batch& b, uint32_t tick) const {
        return {&tables,        uint32_t(g.species.size()),
                options.dt,     tick,
                seed,           live.gravity / kEarthGravity,
                b.vigour.empty() ? nullptr : &b.vigour,
                openLight,      &b.field.placements,
                b.first};
    }
    // The settings a drawing sizes batch b's organs by: the last tick's, the sizes of this moment.
    grow::TickSettings drawingSettings(const Batch& b) const { return settings(b, ticks == 0 ? 0 : ticks - 1); }
    // The height each plant stands at.
    static std::vector<float> baseHeights(const std::vector<shared::PlantPlacement>& placements) {
        std::vector<float> bases;
        for (const shared::PlantPlacement& p : placements)
            bases.push_back(turtle::plantOrigin(p).y);
        return bases;
    }
    void makeBatches(uint32_t plantsPerBatch);
    // The modules batch b's streams hold from the start: its plants' first kFirstSteps steps as the grown plants
    // took them, so that the first steps fit, where they would outgrow streams of the seeds' size and be derived
    // again.
    uint64_t firstStepsRoom(const Batch& b) const;
    // The plants whose step falls due by the clock, flagged in `due`, their next steps a DeriveTime on; whether any.
    bool takeDue(std::vector<uint8_t>& due);
    bool anyDue() const;
    // Every batch's due plants derive a step, batch by batch; returns how many derived.
    uint32_t deriveDue(const std::vector<uint8_t>& due);
    // Every particle of the field grows a tick: on the device every batch's, recorded into the submission that next
    // touches the particles (growthToRecord).
    void growEveryParticle();
    // A tick's growth on the device that waits for the next submission touching the particles, each batch's with
    // the settings of its tick: the drawing's most often, so that a tick between steps that is drawn is one
    // submission. Recorded by recordGrowthWaiting() at the start of that submission, or submitted on its own by
    // submitGrowthWaiting() before anything else reads the particles or changes what the growth reads.
    std::vector<grow::TickSettings> growthToRecord; // per batch; empty: none waits
    void recordGrowthWaiting(VkCommandBuffer cmd);
    void submitGrowthWaiting();
    // The GPU time of the growth recorded in a submission of other stages, so that each stage's seconds stay its
    // own: growthRecorded() adds it to the growth's, once the submission has finished, and returns it for the
    // caller to take from the stage around it.
    std::unique_ptr<vk::RegionClock> growthClock;
    double growthRecorded();
    // The due plants' steps and every particle's growth after them, on the device, all batches in one submission
    // that the host waits for once: each batch's step and its homomorphism within its streams' room, its growth on
    // the string the step writes. A batch whose step or homomorphism outgrew its room writes it again with the host
    // between its passes (counted in `rederived`), and grows again after a step derived again. Returns how many
    // plants derived.
    uint32_t deriveAndGrowInOneSubmission(const std::vector<uint8_t>& due, uint32_t& rederived);
    // The room batch b's drawing records the turtle in after a step derived its string anew from `modulesBefore`
    // modules (with its homomorphism, so that the drawing after the tick records it as it records a string drawn
    // again): the last drawing's organs grown as the derived string grew (the target holds half again), twice its
    // levels and four more, and its marks (every one after a seedling, whose room is empty: an organ for every drawn
    // module, four levels). None after a step derived waiting (deriveDue), a resume, or where the room was a guess
    // no drawing took up: that drawing interprets.
    std::optional<turtle::TurtleRoom> roomAfterStep(const Batch& b, uint64_t modulesBefore) const;
    std::vector<const turtle::DeviceOrgans*> interpretOnDevice();
    uint32_t reinterpreted = 0; // batches the last drawing interpreted with the host reading between passes
    // Whether batch b's drawn string stands as its last drawing interpreted it, so that it may be drawn again within
    // that drawing's room.
    bool drawsAgain(const Batch& b) const { return b.room && !answersQueries && b.deriver->drawnStands(); }
    // Records drawing batch b again into its target (drawsAgain()); returns the string drawn.
    stream::DeviceModules recordDrawingAgain(VkCommandBuffer cmd, Batch& b);
    // Batch b drawn with the host reading between the turtle's passes: its drawn string written anew (unless
    // `drawnAgain`, the string a recording drew again and sized, which did not fit its room), sized, interpreted,
    // lit and its organs kept in its target.
    struct Drawing {
        stream::DeviceModules modules;
        const turtle::DeviceOrgans* organs = nullptr;
    };
    Drawing drawInterpreting(Batch& b, std::optional<stream::DeviceModules> drawnAgain);
    // Records the light of the last grid for batch b's drawn particles and its organs, their statistics, and the
    // organs splatted into the grid for the next.
    void recordLight(VkCommandBuffer cmd, Batch& b, const stream::DeviceModules& drawn,
                     const turtle::DeviceOrgans& organs);
    bool growsSizes() const { return tables.drawsGrowth() || tables.growsSegments(); }
    std::vector<const turtle::DeviceOrgans*> interpretOnHost();
    turtle::OrganMerge& organMerge() {
        if (!merge) merge = std::make_unique<turtle::OrganMerge>(*context, options.maxPartBytes);
        return *merge;
    }
};

} // namespace simeco::field
