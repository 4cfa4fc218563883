// A field that grows over simulated time: each tick the plants whose DeriveTime is due derive one step, then every
// particle ages and grows; the field is drawn from the derived string under its homomorphism, its organs sized by
// their particles. On the device (the GPU backend: the strings and particles stay there) or by the CPU
// references. A large field runs in batches of plants, each stage batch by batch, so that no buffer binds more
// than a batch's modules; the batches' organs are merged into one field to draw.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "compute/shared/organ_layout.h"
#include "compute/shared/plant_statistics_layout.h"
#include "draw/bounds.h"
#include "draw/renderer.h"
#include "ir/eco_field.h"
#include "field/backend.h"
#include "field/light_view.h"
#include "grow/growing_species.h"
#include "stream/derive_options.h"
#include "stream/stepped_state.h"
#include "turtle/turtle_gpu.h"

namespace simeco::vk {
class Context;
}

namespace simeco::field {

struct SimulationOptions {
    std::string file;      // a scene or grammar file, or the name `sceneText` goes by in messages
    std::string sceneText; // a scene's text, read instead of `file` when not empty
    uint32_t plants = 0;   // 0: one plant of each species where the scene puts it, or its populations
    // A factor on every population's plants (its Count, or its Density); the scene must have populations unless 1.
    float density = 1.0f;
    int64_t seed = -1;     // -1: the grammar's `seed:` (or 0)
    float dt = 1.0f;       // simulated seconds per tick
    float spacing = 0.0f;  // between neighbouring plants of a field of many; 0: from the plants' grown size
    // Plants derived, grown and interpreted together; 0: as many as a storage binding of the device holds
    // (batchDrawnModules in simulation_impl.h). The field is the same however it is batched: each plant draws from
    // the random stream of its place in the field, which steps at every advance of the field.
    uint32_t plantsPerBatch = 0;
    uint64_t maxModules = 0;
    double maxSeconds = stream::kDefaultMaxSeconds;
    uint64_t maxPartBytes = 0; // of the organs' parts (turtle::OrganMerge); 0: one buffer binding's
    Backend backend = Backend::Gpu;
    std::string colormap; // a cpfg colour map (.map) in place of the grammars' own; empty: theirs
};

// What may change while a field grows (`simeco view`'s panel): the light it grows by, its climate and soil (the
// scene's EcoSystem block), gravity, and factors on each species' stage properties. A change acts from the next
// tick and drawing on, on either backend.
struct LiveEnvironment {
    ir::EcoLight light; // the sun's direction and intensity, the sky's light (ground size is not read)
    float dayLight = 12.0f; // hours
    float rainRate = 0.9f;
    float soilPH = 7.0f;
    float gravity = 9.81f; // m/s², pulling down
    struct SpeciesFactors {
        float growRate = 1.0f, geotropism = 1.0f, strength = 1.0f;
        bool operator==(const SpeciesFactors&) const = default;
    };
    std::vector<SpeciesFactors> species; // per species of the field
};

// What a tick did.
struct TickReport {
    uint32_t tick = 0;    // ticks before this one
    double time = 0;      // simulated seconds after it
    uint32_t derived = 0; // plants that derived a step in it
    uint64_t modules = 0; // of the derived string, after it
    // Batches whose step or its homomorphism, recorded with every other batch's in one submission, outgrew its
    // streams and was written again with the host waiting between its passes (the streams then grow ahead of the
    // next steps).
    uint32_t rederived = 0;
};

// Wall-clock seconds each stage took, summed since the field began. Every stage's call waits for the device, so on
// a CPU device this is the device's time and on a GPU it includes the submissions' overhead.
struct StageSeconds {
    double derive = 0;     // the due plants' derivation steps
    double grow = 0;       // the particles' tick
    double interpret = 0;  // the homomorphism, the grown sizes, the turtle and the batches' merge
    double light = 0;      // the light grid: the organs given its light, splatted into it, the light propagated
    double statistics = 0; // each plant's statistics
};

// The whole state of a field: the clock, when each plant derives next, and the derivation of its plants (their
// string with its particles, their variables and the random streams' step), however the field is batched. The light
// grid is not kept: it is made from the organs of this state, so resume() splats them again.
struct SimulationState {
    uint32_t ticks = 0;
    std::vector<float> nextStep; // per plant
    stream::SteppedState plants; // every plant's, in plant order
};

class Simulation {
public:
    // Loads the file (lang::EcoDrawing::Grown for a scene), places the plants and starts them from their axioms.
    // `context` is used by the GPU backend, and by interpret() with either.
    Simulation(const SimulationOptions& options, const vk::Context* context);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    TickReport tick();

    // The field's state, and back to it: a state saved from a field made with the same options (on either
    // backend, on any device, in any batches) goes on exactly as that field would have. Refused where the plants
    // differ.
    SimulationState save(); // completes what the device has yet to do first
    void resume(const SimulationState& state);

    double time() const;
    uint32_t ticks() const;
    uint32_t plants() const;
    // Whether a plant stands in the field: a field of populations has empty slots (field_placement.h).
    bool present(uint32_t plant) const;
    uint32_t standingPlants() const;
    uint32_t batches() const;
    uint64_t modules() const;
    // When every plant has derived its steps and every organ's growth has ended, at the latest.
    double grownBy() const;
    // Before the first tick: ticks of `dt` simulated seconds (an animation's, once it knows how long the field
    // grows). Throws std::logic_error after it.
    void setTickSeconds(float dt);
    // The environment the field grows in now (at first the scene's), and a new one for the ticks after. Throws
    // std::invalid_argument for factors of another count of species than the field's.
    const LiveEnvironment& environment() const;
    void setEnvironment(const LiveEnvironment& environment);
    // Where the field will reach when grown, as one plant of each species grows on the CPU (a plant's own random
    // draws may take it a little further): what a camera that stays put while the field grows frames.
    draw::Bounds grownBounds() const;
    // The light grid as the last drawing left it (read back from the device); empty before one.
    LightVolume lightVolume() const;
    const grow::GrowingSpecies& species() const;
    const StageSeconds& stageSeconds() const;
    // The name of a plant's species: its scene plant's, else the grammar file's.
    std::string speciesName(uint32_t plant) const;
    // Each plant's modules in the derived string (read back from the device's plant table).
    std::vector<uint64_t> plantModules() const;
    const std::vector<shared::PlantPlacement>& placements() const;

    // The field's organs as they are now, on the device: the turtle kernels' (or with the CPU backend the
    // reference turtle's, uploaded), in parts where they need more than one buffer binding (turtle::OrganMerge),
    // valid until the next interpretation.
    std::vector<const turtle::DeviceOrgans*> interpretParts();
    // The same for a field of one part; throws ir::LimitError where it needs more.
    const turtle::DeviceOrgans& interpret();
    // Each plant's statistics, in plant order, counted with the organs interpret() drew after the last tick (the
    // host reads back a few words per plant).
    std::vector<shared::PlantStatistics> statistics() const;
    // Batches the last drawing on the device interpreted with the host reading back between the turtle's passes,
    // rather than recorded in the one submission of every batch: at the first drawing, after a resume, and where
    // a batch's string outgrew the room it was recorded in (which then grows to it).
    uint32_t reinterpretedBatches() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The parts of a field's organs as the renderer draws them.
std::vector<draw::OrganPart> organParts(const std::vector<const turtle::DeviceOrgans*>& parts);

} // namespace simeco::field
