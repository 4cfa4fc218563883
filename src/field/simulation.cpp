// The growing field: its batches, its environment, its saved state and what it tells of itself.

#include "field/simulation_impl.h"

namespace simeco::field {

uint64_t Simulation::Impl::firstStepsRoom(const Batch& b) const {
    uint64_t room = 0;
    for (uint32_t p = b.first; p < b.first + b.count; ++p)
        if (absent.empty() || !absent[p]) room += grown.firstStepsModules[ir::speciesOfPlant(p, g.species.size())];
    return room;
}

void Simulation::Impl::makeBatches(uint32_t plantsPerBatch) {
    const uint32_t species = uint32_t(g.species.size());
    if (plantsPerBatch == 0) {
        // As many plants as the grown plants' drawn modules allow.
        uint64_t perRound = 0;
        for (uint64_t m : grown.drawnModules)
            perRound += std::max<uint64_t>(m, 1);
        const uint64_t rounds = std::max<uint64_t>(1, batchDrawnModules(context) / perRound);
        plantsPerBatch = uint32_t(std::min<uint64_t>(rounds, 1u << 24)) * species;
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
            b.deriver->begin(batch, firstStepsRoom(b));
            // The seedlings' drawn string, and a room for it (a few levels, an organ for every drawn module, every
            // mark's searches): the field's first drawing records the turtle as later ones do.
            b.deriver->drawn();
            b.room = turtle::TurtleRoom{4, b.deriver->lastDrawn().count, ~0u};
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
    if (options.backend == Backend::Gpu) m.growthClock = std::make_unique<vk::RegionClock>(*context, 1);
}

Simulation::~Simulation() = default;


const LiveEnvironment& Simulation::environment() const { return impl_->live; }

void Simulation::setEnvironment(const LiveEnvironment& environment) {
    Impl& m = *impl_;
    if (environment.species.size() != m.g.species.size())
        throw std::invalid_argument(fmt::format("the environment has factors for {} species, the field {}",
                                                environment.species.size(), m.g.species.size()));
    m.submitGrowthWaiting(); // the last tick's, in the environment it grew in
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

SimulationState Simulation::save() {
    Impl& m = *impl_;
    m.submitGrowthWaiting();
    std::vector<stream::SteppedState> batches;
    for (const Batch& b : m.batches) batches.push_back(b.deriver ? b.deriver->save() : b.reference->save());
    return {m.ticks, m.nextStep, stream::joinPlants(batches)};
}

void Simulation::resume(const SimulationState& state) {
    Impl& m = *impl_;
    if (state.nextStep.size() != m.derive.plants || state.plants.plants.size() != m.derive.plants)
        throw std::invalid_argument(fmt::format("the saved field has {} plants, this one {}",
                                                state.plants.plants.size(), m.derive.plants));
    m.growthToRecord.clear(); // the state saved has grown all it grew
    for (Batch& b : m.batches) {
        const stream::SteppedState saved = stream::plantsOf(state.plants, b.first, b.count);
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
    if (!m.context) return;
    m.splatsOnly = true;
    try {
        interpretParts();
    } catch (...) {
        m.splatsOnly = false;
        throw;
    }
    m.splatsOnly = false;
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

} // namespace simeco::field
