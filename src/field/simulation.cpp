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

namespace simeco::field {

namespace {

using Clock = std::chrono::steady_clock;
double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

// The drawn modules a batch of plants may hold, by the grown plants' count: one interpretation's (kBatchModules,
// half a binding), the other half of the binding left to plants that grow larger than the one grown before the
// field.
constexpr uint64_t kBatchDrawnModules = kBatchModules;

// The gravity relative to which a scene's Gravity bends its plants (grow::GrowingSpecies::relativeGravity).
constexpr float kEarthGravity = 9.81f;

template <typename T> std::vector<T> slice(const std::vector<T>& v, uint32_t first, uint32_t count) {
    return std::vector<T>(v.begin() + first, v.begin() + first + count);
}

} // namespace

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
    // since): the next drawing records the turtle within it, in one submission with the grown sizes, the light and
    // the statistics of every such batch, and reads nothing back between them.
    std::optional<turtle::TurtleRoom> room;
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
    // The plants whose step falls due by the clock, flagged in `due`, their next steps a DeriveTime on; whether any.
    bool takeDue(std::vector<uint8_t>& due);
    bool anyDue() const;
    // Every batch's due plants derive a step, batch by batch; returns how many derived.
    uint32_t deriveDue(const std::vector<uint8_t>& due);
    // Every particle of the field grows a tick: on the device every batch's in one submission.
    void growEveryParticle();
    // The due plants' steps and every particle's growth after them, on the device, all batches in one submission
    // that the host waits for once: each batch's step and its homomorphism within its streams' room, its growth on
    // the string the step writes. A batch whose step or homomorphism outgrew its room writes it again with the host
    // between its passes (counted in `rederived`), and grows again after a step derived again. Returns how many
    // plants derived.
    uint32_t deriveAndGrowInOneSubmission(const std::vector<uint8_t>& due, uint32_t& rederived);
    // The room batch b's drawing records the turtle in after a step derived its string anew from `modulesBefore`
    // modules (with its homomorphism, so that the drawing after the tick records it as it records a string drawn
    // again): the last drawing's organs grown as the derived string grew (the target holds half again), twice its
    // levels and four more, and its marks. None before a first drawing.
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

void Simulation::Impl::makeBatches(uint32_t plantsPerBatch) {
    const uint32_t species = uint32_t(g.species.size());
    if (plantsPerBatch == 0) {
        // As many plants as the grown plants' drawn modules allow.
        uint64_t perRound = 0;
        for (uint64_t m : grown.drawnModules)
            perRound += std::max<uint64_t>(m, 1);
        plantsPerBatch =
            uint32_t(std::min<uint64_t>(std::max<uint64_t>(1, kBatchDrawnModules / perRound), 1u << 24)) * species;
    }
    // Whole rounds of the species, so that plant p of a batch is of the field's species of p.
    plantsPerBatch = std::max(species, plantsPerBatch / species * species);
    for (uint32_t first = 0; first < derive.plants; first += plantsPerBatch) {
        Batch b;
        b.first = first;
        b.count = std::min(plantsPerBatch, derive.plants - first);
        b.deriveTimes = slice(deriveTimes, first, b.count);
        b.field.placements = slice(placements, first, b.count);
        if (!vigour.empty()) b.vigour = slice(vigour, first, b.count);
        stream::DeriveOptions batch = derive;
        batch.plants = b.count;
        batch.firstPlant = first; // its plants draw what they draw in the whole field
        if (!absent.empty()) batch.absent = slice(absent, first, b.count);
        // The field's module budget shared by its batches as their plants.
        if (batch.maxModules > 0) batch.maxModules = std::max<uint64_t>(1, derive.maxModules / derive.plants * b.count);
        b.deriverOptions = batch;
        if (options.backend == Backend::Gpu) {
            b.deriver = std::make_unique<gpu::GpuDeriver>(*context, g.species, gpu::GpuStrategy::Parallel);
            b.deriver->begin(batch);
            b.growth = std::make_unique<grow::GpuGrowth>(*context, tables, b.deriveTimes, b.vigour, b.field.placements);
            b.modules = b.deriver->current().count;
        } else {
            b.reference = std::make_unique<cpu::SteppedDerivation>(g.species, batch);
            b.modules = b.reference->current().size();
        }
        batches.push_back(std::move(b));
    }
}

Simulation::Simulation(const SimulationOptions& options, const vk::Context* context) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.context = context;
    m.options = options;
    if (!(options.dt > 0) || !std::isfinite(options.dt)) throw std::invalid_argument("the tick's dt must be positive");
    if (!(options.density > 0) || !std::isfinite(options.density))
        throw std::invalid_argument("the populations' density factor must be positive");
    if (options.backend == Backend::Gpu && !context)
        throw std::logic_error("the GPU backend grows the field on a Vulkan device");
    std::vector<ir::EcoWarning> warnings;
    if (options.sceneText.empty()) {
        m.g = grow::loadGrowingSpecies(options.file, &warnings);
    } else {
        ir::EcoScene scene = lang::parseEcoText(options.sceneText, options.file);
        warnings = scene.warnings;
        m.g = grow::growingSpecies(std::move(scene), &warnings);
    }
    if (!options.colormap.empty()) lang::useColorMap(m.g.species, options.colormap);
    m.seed = options.seed >= 0 ? uint32_t(options.seed) : m.g.species.front().seed;
    FieldLayout layout;
    if (hasPopulations(m.g)) {
        if (options.plants)
            throw ir::InputError({options.file, 0, 0},
                                 "the scene places its plants in populations: it takes no count of plants");
        layout = layoutPopulations(m.g, m.seed, warnings, options.density);
        m.absent = layout.absent;
        m.vigour = layout.vigour;
        m.derive.absent = layout.absent;
    }
    if (!hasPopulations(m.g) && options.density != 1.0f)
        throw ir::InputError({options.file, 0, 0},
                             "the scene has no populations for a density to scale: a count of plants sets its field");
    m.derive.plants = hasPopulations(m.g) ? uint32_t(layout.placements.size())
                      : options.plants    ? options.plants
                                          : uint32_t(m.g.species.size());
    m.plantVigour = m.vigour;
    m.derive.maxModules = options.maxModules;
    m.derive.maxSeconds = options.maxSeconds;
    m.derive.particles = true;
    m.derive.seed = m.seed;
    m.tables = grow::growthTables(m.g.species, m.g.ecoPlants);
    m.sceneTables = m.tables;
    m.startEnvironment();
    m.chooseLight();
    m.derive.lightScale = m.openLight > 0.0f ? 1.0f / m.openLight : 0.0f;
    m.deriveTimes = grow::plantDeriveTimes(m.g.ecoPlants, m.derive.plants, m.seed);
    m.nextStep = m.deriveTimes;
    const ir::Alphabet& alphabet = m.g.species.front().alphabet;
    m.commands = turtle::turtleCommands(alphabet);
    m.answersQueries = m.commands.query != turtle::kNoSymbol &&
                       std::count(m.commands.afterQuery.begin(), m.commands.afterQuery.end(),
                                  shared::kTurtleQueryEnvironment) > 0;
    for (const ir::Grammar& grammar : m.g.species)
        m.turtles.push_back(turtle::turtleSettings(grammar, alphabet));
    m.grown = growOneOfEach(m.g, m.tables, m.derive, m.seed, m.deriveTimes,
                            latestGrowth(m.g.species, m.tables, m.deriveTimes, m.derive.steps), m.commands, m.turtles);
    // A field of many: grown neighbours touch but do not overlap (turtle::fieldSpacing).
    const float spacing =
        placedAsScene(m.g, m.derive.plants) ? 0.0f : turtle::fieldSpacing({options.spacing, {}}, m.grown.bounds);
    m.placements = hasPopulations(m.g) ? layout.placements : placeField(m.g, m.derive.plants, m.seed, spacing);
    for (const ir::EcoWarning& w : warnings)
        std::fprintf(stderr, "%s:%d:%d: warning: %s\n", w.loc.file.c_str(), w.loc.line, w.loc.col, w.message.c_str());
    m.makeBatches(options.plantsPerBatch);
}

Simulation::~Simulation() = default;

TickReport Simulation::tick() {
    Impl& m = *impl_;
    TickReport report;
    report.tick = m.ticks;
    m.drawn = false; // what was drawn before describes the field before the tick
    m.time = double(m.ticks + 1) * m.options.dt;
    // Every step that falls due within the tick: a tick longer than a plant's DeriveTime (a time-lapse of a few
    // frames) derives as many, so that the plant is where its time has brought it. Until no plant derives more.
    std::vector<uint8_t> due;
    bool grown = false;
    while (m.takeDue(due)) {
        const Clock::time_point start = Clock::now();
        // The last round of steps, on the device, in one submission with the growth of every particle.
        grown = m.options.backend == Backend::Gpu && !m.anyDue();
        const uint32_t derived = grown ? m.deriveAndGrowInOneSubmission(due, report.rederived) : m.deriveDue(due);
        m.seconds.derive += secondsSince(start);
        report.derived = std::max(report.derived, derived);
        if (derived == 0) break; // every due plant has derived all its steps
    }
    if (!grown) m.growEveryParticle();
    for (const Batch& b : m.batches) report.modules += b.modules;
    ++m.ticks;
    report.time = m.time;
    return report;
}

std::optional<turtle::TurtleRoom> Simulation::Impl::roomAfterStep(const Batch& b, uint64_t modulesBefore) const {
    if (!b.room) return std::nullopt;
    const uint64_t modulesAfter = b.deriver->current().count;
    const double growth = std::max(1.0, double(modulesAfter) / double(std::max<uint64_t>(modulesBefore, 1)));
    // Seedlings that drew nothing yet: an organ for every drawn module, as many as most strings draw.
    const double organs = b.room->organs > 0 ? std::ceil(double(b.room->organs) * growth)
                          : b.deriver->drawnStands() ? double(b.deriver->lastDrawn().count)
                                                     : 0.0;
    const double mostOrgans = double(context->limits().maxStorageBufferRange / sizeof(shared::OrganInstance));
    turtle::TurtleRoom room;
    room.organs = uint32_t(std::min(organs, mostOrgans));
    // The levels of branches within branches: a step may double them (a branch on every branch), and a seedling's
    // first branches bring a few.
    room.levels = 2 * b.room->levels + 4;
    // The marks the string had: one that brings others (a first curve, say) does not fit, and is drawn again.
    room.marks = b.room->marks;
    return room;
}

bool Simulation::Impl::takeDue(std::vector<uint8_t>& due) {
    due.assign(derive.plants, 0);
    bool any = false;
    for (uint32_t p = 0; p < derive.plants; ++p)
        if (time >= nextStep[p]) {
            due[p] = 1;
            any = true;
            nextStep[p] += deriveTimes[p];
        }
    return any;
}

bool Simulation::Impl::anyDue() const {
    for (uint32_t p = 0; p < derive.plants; ++p)
        if (time >= nextStep[p]) return true;
    return false;
}

uint32_t Simulation::Impl::deriveDue(const std::vector<uint8_t>& due) {
    uint32_t derived = 0;
    for (Batch& b : batches) {
        const std::vector<uint8_t> batchDue = slice(due, b.first, b.count);
        const uint32_t batchDerived = b.deriver ? b.deriver->advance(batchDue) : b.reference->advance(batchDue);
        if (batchDerived > 0) b.room.reset();
        derived += batchDerived;
    }
    return derived;
}

void Simulation::Impl::growEveryParticle() {
    const Clock::time_point start = Clock::now();
    if (options.backend == Backend::Gpu) {
        context->submitAndWait([&](VkCommandBuffer cmd) {
            for (Batch& b : batches) {
                const stream::DeviceModules derived = b.deriver->current();
                b.growth->recordTick(cmd, derived, settings(b, ticks));
                b.modules = derived.count;
            }
        });
    } else {
        for (Batch& b : batches) {
            grow::tickCpu(settings(b, ticks), b.reference->current());
            b.modules = b.reference->current().size();
        }
    }
    seconds.grow += secondsSince(start);
}

uint32_t Simulation::Impl::deriveAndGrowInOneSubmission(const std::vector<uint8_t>& due, uint32_t& rederived) {
    std::vector<uint8_t> stepped(batches.size(), 0);
    std::vector<uint64_t> modulesBefore;
    for (const Batch& b : batches)
        modulesBefore.push_back(b.modules);
    uint32_t derived = 0;
    context->submitAndWait([&](VkCommandBuffer cmd) {
        for (size_t k = 0; k < batches.size(); ++k) {
            Batch& b = batches[k];
            const uint32_t batchDerived = b.deriver->recordAdvance(cmd, slice(due, b.first, b.count));
            stepped[k] = batchDerived > 0 ? 1 : 0;
            derived += batchDerived;
            b.growth->recordTick(cmd, b.deriver->current(), settings(b, ticks));
        }
    });
    // Every recorded step is read, even after one that fails, so that the derivers take calls again.
    std::exception_ptr failure;
    std::vector<Batch*> outgrown;
    for (size_t k = 0; k < batches.size(); ++k) {
        if (!stepped[k]) continue;
        Batch& b = batches[k];
        try {
            const gpu::GpuDeriver::Advanced outcome = b.deriver->advanced();
            if (outcome == gpu::GpuDeriver::Advanced::DerivedAgain) outgrown.push_back(&b);
            if (outcome != gpu::GpuDeriver::Advanced::Recorded) ++rederived;
            b.room = roomAfterStep(b, modulesBefore[k]);
        } catch (...) {
            b.room.reset();
            if (!failure) failure = std::current_exception();
        }
    }
    if (failure) std::rethrow_exception(failure);
    // A batch whose step outgrew its streams derived it again, waiting: its particles grow on that string.
    if (!outgrown.empty())
        context->submitAndWait([&](VkCommandBuffer cmd) {
            for (Batch* b : outgrown)
                b->growth->recordTick(cmd, b->deriver->current(), settings(*b, ticks));
        });
    for (Batch& b : batches)
        b.modules = b.deriver->current().count;
    return derived;
}

const LiveEnvironment& Simulation::environment() const { return impl_->live; }

void Simulation::setEnvironment(const LiveEnvironment& environment) {
    Impl& m = *impl_;
    if (environment.species.size() != m.g.species.size())
        throw std::invalid_argument(fmt::format("the environment has factors for {} species, the field {}",
                                                environment.species.size(), m.g.species.size()));
    const bool speciesChanged = environment.species != m.live.species;
    m.live = environment;
    m.applyClimate();
    m.chooseLight();
    if (m.lightGpu) m.lightGpu->setDirections(m.lightFrom);
    if (m.lightCpu) m.lightCpu->setDirections(m.lightFrom);
    if (speciesChanged) {
        m.tables = m.sceneTables;
        for (uint32_t s = 0; s < m.live.species.size(); ++s) {
            const LiveEnvironment::SpeciesFactors& f = m.live.species[s];
            grow::scaleSpeciesProperty(m.tables, s, shared::kGrowRate, f.growRate);
            grow::scaleSpeciesProperty(m.tables, s, shared::kGeotropism, f.geotropism);
            grow::scaleSpeciesProperty(m.tables, s, shared::kStrength, f.strength);
        }
    }
    for (Batch& b : m.batches) {
        b.vigour = m.vigour.empty() ? std::vector<float>{} : slice(m.vigour, b.first, b.count);
        if (!b.growth) continue;
        b.growth->setVigour(b.vigour);
        if (speciesChanged) b.growth->setRows(m.tables);
    }
}

SimulationState Simulation::save() const {
    const Impl& m = *impl_;
    SimulationState state{m.ticks, m.nextStep, {}};
    for (const Batch& b : m.batches) state.batches.push_back(b.deriver ? b.deriver->save() : b.reference->save());
    return state;
}

void Simulation::resume(const SimulationState& state) {
    Impl& m = *impl_;
    if (state.nextStep.size() != m.derive.plants || state.batches.size() != m.batches.size())
        throw std::invalid_argument(fmt::format("the saved field has {} plants in {} batches, this one {} in {}",
                                                state.nextStep.size(), state.batches.size(), m.derive.plants,
                                                m.batches.size()));
    for (size_t k = 0; k < m.batches.size(); ++k) {
        Batch& b = m.batches[k];
        const stream::SteppedState& saved = state.batches[k];
        if (saved.plants.size() != b.count)
            throw std::invalid_argument(fmt::format("the saved field's batch {} has {} plants, this one's {}", k,
                                                    saved.plants.size(), b.count));
        if (b.deriver) {
            b.deriver->resume(b.deriverOptions, saved);
            b.modules = b.deriver->current().count;
        } else {
            b.reference->resume(saved);
            b.modules = b.reference->current().size();
        }
        b.room.reset();
    }
    m.ticks = state.ticks;
    m.time = double(state.ticks) * m.options.dt;
    m.nextStep = state.nextStep;
    m.drawn = false;
    // The light grid as the saved run left it: splatted from the organs of the state saved.
    if (m.context) interpretParts();
}

void Simulation::Impl::chooseLight() {
    lightFrom = sceneLightDirections(live.light, openLight);
}

// The scene's environment, as the field starts.
void Simulation::Impl::startEnvironment() {
    live.species.assign(g.species.size(), {});
    live.gravity = g.relativeGravity() * kEarthGravity;
    if (!g.scene) return;
    live.light = g.scene->light;
    live.dayLight = g.scene->dayLight.typical();
    live.rainRate = g.scene->rainRate.typical();
    live.soilPH = g.scene->soilPH.typical();
    applyClimate();
}

// The climate and soil scale every plant's growth rates (grow/environment.h).
void Simulation::Impl::applyClimate() {
    const float climate = grow::climateGrowthFactor(live.dayLight, live.rainRate, live.soilPH);
    vigour = plantVigour;
    if (climate == 1.0f) return;
    if (vigour.empty()) vigour.assign(derive.plants, 1.0f);
    for (float& v : vigour) v *= climate;
}

void Simulation::Impl::prepareLight(const draw::Bounds& extent, uint32_t standing) {
    if (lightGpu || lightCpu) return;
    const grow::LightGridSpec spec = grow::lightGridOver(extent.min, extent.max, standing);
    std::vector<uint32_t> blocked = hasObstacles() ? obstacleVoxels(spec, g.scene->obstacles) : std::vector<uint32_t>{};
    if (options.backend == Backend::Gpu)
        lightGpu = std::make_unique<grow::GpuLightGrid>(*context, spec, lightFrom, blocked,
                                                        leafShapeAreas(g.assets.models));
    else
        lightCpu = std::make_unique<grow::LightGridCpu>(spec, lightFrom, std::move(blocked));
}

std::vector<const turtle::DeviceOrgans*> Simulation::Impl::interpretOnDevice() {
    if (!turtle) turtle = std::make_unique<turtle::GpuTurtle>(*context, commands, turtles);
    if (!batches.front().statistics) {
        const std::vector<float> areas = leafShapeAreas(g.assets.models);
        for (Batch& b : batches) b.statistics = std::make_unique<GpuPlantStatistics>(*context, areas);
    }
    const bool merged = batches.size() > 1 || hasObstacles();
    if (merged) organMerge().begin();
    lastStatistics.clear();
    // The batches whose drawn strings stand draw again, every one in one submission with the light grid's
    // clearing, each into organ buffers of its own: the host reads nothing between them, and after them only their
    // statistics, their organs' tables and whether each fit its room. Between derivation steps that is the
    // drawing of the whole field.
    std::vector<uint8_t> again(batches.size(), 0);
    uint32_t modules = 0, plants = 0; // the largest string and plants of them
    turtle::TurtleRoom room;
    for (size_t k = 0; k < batches.size(); ++k) {
        const Batch& b = batches[k];
        if (!drawsAgain(b)) continue;
        again[k] = 1;
        modules = std::max({modules, b.deriver->lastDrawn().count, 1u});
        plants = std::max(plants, b.count);
        room.levels = std::max(room.levels, b.room->levels);
    }
    std::vector<std::optional<stream::DeviceModules>> drawnAgain(batches.size());
    Clock::time_point start = Clock::now();
    if (modules > 0) turtle->reserveTargets(modules, plants, room);
    context->submitAndWait([&](VkCommandBuffer cmd) {
        lightGpu->recordClear(cmd);
        for (size_t k = 0; k < batches.size(); ++k)
            if (again[k]) drawnAgain[k] = recordDrawingAgain(cmd, batches[k]);
    });
    seconds.interpret += secondsSince(start);
    uint64_t firstModule = 0;
    const turtle::DeviceOrgans* organs = nullptr;
    reinterpreted = 0;
    for (size_t k = 0; k < batches.size(); ++k) {
        Batch& b = batches[k];
        const std::optional<turtle::RecordedInterpretation> found =
            again[k] ? std::optional(turtle::GpuTurtle::recordedInto(b.target)) : std::nullopt;
        const bool fit = found && found->fit;
        reinterpreted += fit ? 0 : 1;
        if (fit) { // the string drawn again until the next step needs no more than it found
            b.room->levels = found->levels;
            b.room->marks = found->marks;
        }
        // Else, or where it outgrew its room, the batch is drawn with the host reading between the turtle's passes.
        const Drawing drawing = fit ? Drawing{*drawnAgain[k], &b.target.organs} : drawInterpreting(b, drawnAgain[k]);
        organs = drawing.organs;
        start = Clock::now();
        const std::vector<shared::PlantStatistics> s = b.statistics->read();
        lastStatistics.insert(lastStatistics.end(), s.begin(), s.end());
        seconds.statistics += secondsSince(start);
        start = Clock::now();
        if (merged) merge->keepInPlace(*organs, b.statistics->organTable(), b.first, firstModule);
        firstModule += drawing.modules.count;
        seconds.interpret += secondsSince(start);
    }
    Clock::time_point lightStart = Clock::now();
    context->submitAndWait([&](VkCommandBuffer cmd) { lightGpu->recordPropagate(cmd); });
    seconds.light += secondsSince(lightStart);
    if (!merged) return {organs};
    start = Clock::now();
    if (hasObstacles()) merge->keep(obstacleOrganBuffers(), derive.plants, firstModule);
    std::vector<const turtle::DeviceOrgans*> parts = merge->mergeParts();
    seconds.interpret += secondsSince(start);
    return parts;
}

stream::DeviceModules Simulation::Impl::recordDrawingAgain(VkCommandBuffer cmd, Batch& b) {
    // The string as the homomorphism wrote it, with the particles the tick grew.
    b.deriver->recordDrawnAgain(cmd);
    stream::DeviceModules modules = b.deriver->lastDrawn();
    // A grammar without a homomorphism draws its derived string: its segments shorten a copy.
    if (tables.growsSegments() && modules.symbols == b.deriver->current().symbols)
        modules = b.growth->recordCopyForDrawing(cmd, modules);
    if (growsSizes()) b.growth->recordSizes(cmd, modules, drawingSettings(b));
    recordLight(cmd, b, modules, turtle->recordInto(cmd, modules, b.field, *b.room, b.target));
    return modules;
}

Simulation::Impl::Drawing Simulation::Impl::drawInterpreting(Batch& b,
                                                             std::optional<stream::DeviceModules> drawnAgain) {
    Clock::time_point start = Clock::now();
    stream::DeviceModules modules;
    if (drawnAgain) {
        modules = *drawnAgain; // sized already: a segment shortened twice would be short
    } else {
        modules = b.deriver->drawn();
        if (tables.growsSegments() && modules.symbols == b.deriver->current().symbols)
            modules = b.growth->copyForDrawing(modules);
        if (growsSizes()) b.growth->growSizes(modules, drawingSettings(b));
    }
    const turtle::DeviceOrgans& organs = turtle->interpret(modules, b.field);
    b.room = turtle->lastRoom();
    b.room->marks = turtle->lastMarks(); // the string this batch draws again until it derives
    seconds.interpret += secondsSince(start);
    start = Clock::now();
    context->submitAndWait([&](VkCommandBuffer cmd) {
        recordLight(cmd, b, modules, organs);
        turtle->recordKeep(cmd, b.target);
    });
    seconds.statistics += secondsSince(start);
    return {modules, &b.target.organs};
}

void Simulation::Impl::recordLight(VkCommandBuffer cmd, Batch& b, const stream::DeviceModules& modules,
                                   const turtle::DeviceOrgans& organs) {
    if (modules.particles)
        lightGpu->recordGather(cmd, organs, *modules.particles, modules.origins, b.deriver->current().particles,
                               b.first);
    if (answersQueries) {
        const stream::DeviceModules derived = b.deriver->current();
        lightGpu->recordQueries(cmd, turtle->lastModuleStates(), modules.count,
                                modules.symbols == derived.symbols ? nullptr : modules.origins, *derived.symbols,
                                *derived.params, derived.stride);
    }
    b.statistics->record(cmd, organs, modules.particles, baseHeights(b.field.placements));
    lightGpu->recordSplat(cmd, organs, b.first);
}

const turtle::DeviceOrgans& Simulation::Impl::obstacleOrganBuffers() {
    if (!obstacles.instances) obstacles = turtle::uploadOrgans(*context, obstacleOrgans(g.scene->obstacles));
    return obstacles;
}

std::vector<const turtle::DeviceOrgans*> Simulation::Impl::interpretOnHost() {
    Clock::time_point start = Clock::now();
    // The batches' drawn strings one after the other: the field's.
    stream::ModuleString field;
    field.plantStart.push_back(0);
    // Where each batch's drawn modules start in the field's, and the module of its derived string each comes from.
    std::vector<size_t> drawnStarts;
    std::vector<std::vector<uint32_t>> origins(batches.size());
    for (Batch& b : batches) {
        drawnStarts.push_back(field.size());
        stream::ModuleString drawnModules = b.reference->drawn(&origins[drawnStarts.size() - 1]);
        if (growsSizes()) grow::growSizesCpu(drawingSettings(b), b.deriveTimes, drawnModules);
        if (b.first == 0) field.stride = drawnModules.stride; // the batches' species, and so their strides, alike
        field.append(drawnModules, 0, drawnModules.size());
        for (size_t p = 1; p < drawnModules.plantStart.size(); ++p)
            field.plantStart.push_back(field.plantStart[b.first] + drawnModules.plantStart[p]);
    }
    turtle::FieldOptions where;
    where.placements = placements;
    const turtle::Interpretation organs = turtle::interpretCpu(field, commands, turtles, where);
    seconds.interpret += secondsSince(start);
    start = Clock::now();
    const std::vector<float> shapeAreas = leafShapeAreas(g.assets.models);
    // The light goes to the drawn modules' particles and to those of the derived modules they come from.
    auto derivedOf = [&](uint32_t module) -> shared::ParticleState* {
        const size_t k = size_t(std::upper_bound(drawnStarts.begin(), drawnStarts.end(), size_t(module)) -
                                drawnStarts.begin()) - 1;
        const std::vector<uint32_t>& from = origins[k];
        const size_t j = module - drawnStarts[k];
        return j < from.size() ? &batches[k].reference->current().particles[from[j]] : nullptr;
    };
    lightCpu->gather(organs, field.particles, derivedOf);
    if (answersQueries) answerQueriesOnHost(field, drawnStarts, origins);
    seconds.light += secondsSince(start);
    start = Clock::now();
    lastStatistics = plantStatisticsCpu(organs, baseHeights(placements), field.particles, shapeAreas);
    seconds.statistics += secondsSince(start);
    start = Clock::now();
    lightCpu->clear();
    lightCpu->splat(organs, shapeAreas);
    lightCpu->propagate();
    seconds.light += secondsSince(start);
    uploaded = turtle::uploadOrgans(*context, organs);
    if (!hasObstacles()) return {&uploaded};
    organMerge().begin();
    merge->keep(uploaded, 0, 0);
    merge->keep(obstacleOrganBuffers(), derive.plants, field.size());
    return merge->mergeParts();
}

void Simulation::Impl::answerQueriesOnHost(const stream::ModuleString& field, const std::vector<size_t>& drawnStarts,
                                           const std::vector<std::vector<uint32_t>>& origins) {
    for (const turtle::EnvironmentQuery& q : turtle::environmentQueries(field, commands, turtles)) {
        const size_t k = size_t(std::upper_bound(drawnStarts.begin(), drawnStarts.end(), q.module) -
                                drawnStarts.begin()) - 1;
        const size_t j = q.module - drawnStarts[k];
        if (j >= origins[k].size()) continue;
        stream::ModuleString& derived = batches[k].reference->current();
        const size_t to = origins[k][j];
        const shared::PlantPlacement& m = placements[q.plant];
        const glm::vec4 l = lightCpu->lightAt(turtle::placePoint(m, q.position));
        // light_queries.comp's answer: the light as a share of the open's, its direction in the plant's frame.
        const glm::vec3 toward = glm::normalize(turtle::turnIntoPlant(m, glm::vec3(l)));
        const float answer[4] = {openLight > 0.0f ? l.w / openLight : 1.0f, toward.x, toward.y, toward.z};
        const uint32_t count = derived.paramCount[to];
        for (uint32_t a = 0; a < std::min(count, count >= 4 ? 4u : 1u); ++a)
            derived.params[to * size_t(derived.stride) + a] = answer[a];
    }
}

std::vector<const turtle::DeviceOrgans*> Simulation::interpretParts() {
    Impl& m = *impl_;
    if (!m.context) throw std::logic_error("Simulation::interpret: drawing needs a Vulkan device");
    m.prepareLight(grownBounds(), standingPlants());
    std::vector<const turtle::DeviceOrgans*> parts =
        m.options.backend == Backend::Gpu ? m.interpretOnDevice() : m.interpretOnHost();
    m.drawn = true;
    return parts;
}

const turtle::DeviceOrgans& Simulation::interpret() {
    const std::vector<const turtle::DeviceOrgans*> parts = interpretParts();
    if (parts.size() > 1)
        throw ir::LimitError(fmt::format("the field's organs come in {} parts, more than one buffer binding holds",
                                         parts.size()));
    return *parts.front();
}

std::vector<shared::PlantStatistics> Simulation::statistics() const {
    if (!impl_->drawn) throw std::logic_error("Simulation::statistics before interpret() after the last tick");
    return impl_->lastStatistics;
}

std::vector<uint64_t> Simulation::plantModules() const {
    const Impl& m = *impl_;
    std::vector<uint64_t> modules;
    for (const Batch& b : m.batches) {
        std::vector<uint64_t> starts;
        if (b.deriver) {
            const stream::DeviceModules derived = b.deriver->current();
            std::vector<uint32_t> table = vk::downloadVector<uint32_t>(*m.context, *derived.plantStarts, b.count + 1);
            starts.assign(table.begin(), table.end());
        } else {
            starts.assign(b.reference->current().plantStart.begin(), b.reference->current().plantStart.end());
        }
        for (size_t p = 0; p + 1 < starts.size(); ++p)
            modules.push_back(starts[p + 1] - starts[p]);
    }
    return modules;
}

std::string Simulation::speciesName(uint32_t plant) const {
    const Impl& m = *impl_;
    const uint32_t s = ir::speciesOfPlant(plant, m.g.species.size());
    if (m.g.ecoPlants[s]) return m.g.ecoPlants[s]->name;
    return std::filesystem::path(m.options.file).stem().string();
}

LightVolume Simulation::lightVolume() const {
    const Impl& m = *impl_;
    LightVolume volume;
    if (!m.lightGpu && !m.lightCpu) return volume;
    volume.spec = m.lightGpu ? m.lightGpu->spec() : m.lightCpu->spec();
    volume.light = m.lightGpu ? vk::downloadVector<glm::vec4>(*m.context, m.lightGpu->light(), volume.spec.voxels())
                              : m.lightCpu->light();
    volume.holders = m.lightGpu ? vk::downloadVector<uint32_t>(*m.context, m.lightGpu->holders(), volume.spec.voxels())
                                : m.lightCpu->holders();
    volume.open = m.openLight;
    return volume;
}

draw::Bounds Simulation::grownBounds() const {
    const Impl& m = *impl_;
    draw::Bounds field{glm::vec3(1e30f), glm::vec3(-1e30f)};
    for (uint32_t p = 0; p < m.derive.plants; ++p) {
        const turtle::Bounds& b = m.grown.bounds[ir::speciesOfPlant(p, m.g.species.size())];
        if (b.empty() || !present(p)) continue;
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 c((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                              (corner & 4) ? b.max.z : b.min.z);
            const glm::vec3 q = turtle::placePoint(m.placements[p], c);
            field.min = glm::min(field.min, q);
            field.max = glm::max(field.max, q);
        }
    }
    if (m.hasObstacles())
        for (const ir::EcoObstacle& o : m.g.scene->obstacles)
            for (const glm::vec3& corner : obstacleCorners(o)) {
                field.min = glm::min(field.min, corner);
                field.max = glm::max(field.max, corner);
            }
    return field;
}

uint32_t Simulation::standingPlants() const {
    return uint32_t(std::count(impl_->absent.begin(), impl_->absent.end(), 0)) +
           (impl_->absent.empty() ? impl_->derive.plants : 0);
}
bool Simulation::present(uint32_t plant) const {
    return plant >= impl_->absent.size() || !impl_->absent[plant];
}
double Simulation::time() const {
    return impl_->time;
}
uint32_t Simulation::ticks() const {
    return impl_->ticks;
}
uint32_t Simulation::plants() const {
    return impl_->derive.plants;
}
uint32_t Simulation::batches() const {
    return uint32_t(impl_->batches.size());
}
uint64_t Simulation::modules() const {
    uint64_t modules = 0;
    for (const Batch& b : impl_->batches)
        modules += b.modules;
    return modules;
}
double Simulation::grownBy() const {
    return latestGrowth(impl_->g.species, impl_->tables, impl_->deriveTimes, impl_->derive.steps);
}
void Simulation::setTickSeconds(float dt) {
    if (impl_->ticks > 0) throw std::logic_error("a field's ticks keep their length once it has ticked");
    if (!(dt > 0) || !std::isfinite(dt)) throw std::invalid_argument("the tick's dt must be positive");
    impl_->options.dt = dt;
}
const grow::GrowingSpecies& Simulation::species() const {
    return impl_->g;
}
const StageSeconds& Simulation::stageSeconds() const { return impl_->seconds; }

uint32_t Simulation::reinterpretedBatches() const {
    return impl_->reinterpreted;
}
const std::vector<shared::PlantPlacement>& Simulation::placements() const {
    return impl_->placements;
}

std::vector<draw::OrganPart> organParts(const std::vector<const turtle::DeviceOrgans*>& parts) {
    std::vector<draw::OrganPart> drawn;
    for (const turtle::DeviceOrgans* part : parts) drawn.push_back({&part->instances, &part->table});
    return drawn;
}

} // namespace simeco::field
