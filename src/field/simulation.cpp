#include "field/simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "compute/shared/growth_layout.h"
#include "compute/shared/random.h"
#include "cpu/derive.h"
#include "field/plant_statistics.h"
#include "gpu/derive_gpu.h"
#include "grow/growth_tables.h"
#include "grow/tick_cpu.h"
#include "grow/tick_gpu.h"
#include "ir/species.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_settings.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace simeco::field {

namespace {

constexpr float kTwoPi = 6.28318530717958647692f;
// The random draws of a plant's placement: module key 1 of the growth property pass, one draw per number.
constexpr uint32_t kPlacementKey = 1;

float drawn(const ir::EcoNumber& n, uint32_t seed, uint32_t plant, uint32_t draw) {
    if (!n.random) return n.min;
    return n.min + (n.max - n.min) * shared::randomUnit(seed, plant, shared::kGrowPropertyPass, kPlacementKey, draw);
}

glm::vec3 drawn(const ir::EcoVector& v, uint32_t seed, uint32_t plant, uint32_t firstDraw) {
    return {drawn(v.x, seed, plant, firstDraw), drawn(v.y, seed, plant, firstDraw + 1),
            drawn(v.z, seed, plant, firstDraw + 2)};
}

// The latest a plant is done: its steps, one DeriveTime each, then the longest growth of any stage.
double latestGrowth(const std::vector<ir::Grammar>& species, const grow::GrowthTables& tables,
               const std::vector<float>& deriveTimes, int fixedSteps) {
    float longestGrowth = 0;
    for (size_t r = 0; r < tables.rows.size(); r += shared::kStageRowFloats)
        longestGrowth = std::max(longestGrowth, tables.rows[r + shared::propertyMax(shared::kGrowTime)]);
    double latest = 0;
    for (uint32_t p = 0; p < deriveTimes.size(); ++p) {
        const ir::Grammar& g = species[ir::speciesOfPlant(p, species.size())];
        const int steps = fixedSteps >= 0 ? fixedSteps : g.derivationLength;
        latest = std::max(latest, double(deriveTimes[p]) * steps);
    }
    return latest + longestGrowth;
}

} // namespace

struct Simulation::Impl {
    const vk::Context* context = nullptr;
    SimulationOptions options;
    grow::GrowingSpecies g;
    stream::DeriveOptions derive;
    uint32_t seed = 0;
    grow::GrowthTables tables;
    std::vector<float> deriveTimes;
    std::vector<float> nextStep;
    double time = 0;
    uint32_t ticks = 0;
    uint64_t modules = 0;
    turtle::TurtleCommands commands;
    std::vector<turtle::TurtleSettings> turtles;
    turtle::FieldOptions field;

    // The GPU backend: the stepped derivation, the growth kernels and the turtle kernels.
    std::unique_ptr<gpu::GpuDeriver> deriver;
    std::unique_ptr<grow::GpuGrowth> growth;
    std::unique_ptr<turtle::GpuTurtle> turtle;
    // The CPU backend: the references, and their organs uploaded for drawing.
    std::unique_ptr<cpu::SteppedDerivation> reference;
    turtle::DeviceOrgans uploaded;
    // What interpret() drew last: the drawn string's particle state and the organs, where statistics() reads them.
    const vk::Buffer* drawnParticles = nullptr;
    const turtle::DeviceOrgans* drawnOrgans = nullptr;
    std::vector<shared::ParticleState> hostParticles;
    turtle::Interpretation hostOrgans;
    std::unique_ptr<GpuPlantStatistics> statistics;

    std::vector<float> baseHeights() const {
        std::vector<float> bases;
        for (const shared::PlantPlacement& p : field.placements) bases.push_back(turtle::plantOrigin(p).y);
        return bases;
    }

    grow::TickSettings settings(uint32_t tick) const {
        return {&tables, uint32_t(g.species.size()), options.dt, tick, seed};
    }
    std::vector<shared::PlantPlacement> placeField(uint32_t plants, float spacing) const;
    std::vector<turtle::Bounds> grownPlants() const;
    std::vector<turtle::Bounds> speciesBounds; // grownPlants()
};

std::vector<shared::PlantPlacement> Simulation::Impl::placeField(uint32_t plants, float spacing) const {
    std::vector<shared::PlantPlacement> placements;
    const size_t species = g.species.size();
    // One plant of each species of a scene stands where the scene puts it.
    const bool asScene = g.scene && plants == species;
    for (uint32_t p = 0; p < plants; ++p) {
        const ir::EcoPlant* eco = g.ecoPlants[ir::speciesOfPlant(p, species)];
        const float yaw = kTwoPi * shared::randomUnit(seed, p, shared::kGrowPropertyPass, kPlacementKey, 6);
        const glm::vec3 direction = eco ? drawn(eco->direction, seed, p, 3) : glm::vec3(0, 1, 0);
        glm::vec3 position = eco ? drawn(eco->position, seed, p, 0) : glm::vec3(0);
        if (!asScene) {
            // A jittered grid: rows and columns `spacing` apart, each plant moved by up to 0.3 of it.
            const float jx = shared::randomUnit(seed, p, shared::kGrowPropertyPass, kPlacementKey, 7) - 0.5f;
            const float jz = shared::randomUnit(seed, p, shared::kGrowPropertyPass, kPlacementKey, 8) - 0.5f;
            const glm::vec3 cell = turtle::fieldCell(p, plants);
            position = glm::vec3(cell.x + 0.6f * jx, 0.0f, cell.z + 0.6f * jz) * spacing;
        }
        placements.push_back(turtle::placementAt(position, direction, yaw));
    }
    return placements;
}

// Each species' plant grown to the end on the CPU, in its own frame: what a field of many spaces its plants by and
// what a camera that does not move while the field grows frames.
std::vector<turtle::Bounds> Simulation::Impl::grownPlants() const {
    stream::DeriveOptions one = derive;
    one.plants = uint32_t(g.species.size());
    cpu::SteppedDerivation plant(g.species, one);
    std::vector<float> times(deriveTimes.begin(), deriveTimes.begin() + std::min(deriveTimes.size(), g.species.size()));
    times.resize(one.plants, grow::kDefaultDeriveTime);
    const double until = latestGrowth(g.species, tables, times, derive.steps);
    std::vector<float> next = times;
    grow::TickSettings ts = settings(0);
    ts.dt = std::max(0.25f, *std::min_element(times.begin(), times.end()) / 2);
    for (double t = 0; t < until + ts.dt; t += ts.dt, ++ts.tick) {
        std::vector<uint8_t> due(one.plants, 0);
        for (uint32_t p = 0; p < one.plants; ++p)
            if (t + ts.dt >= next[p]) due[p] = 1, next[p] += times[p];
        plant.advance(due);
        grow::tickCpu(ts, plant.current());
    }
    stream::ModuleString drawn = plant.drawn();
    if (tables.drawsGrowth()) grow::growSizesCpu(ts, times, drawn);
    std::vector<turtle::Bounds> bounds(one.plants);
    turtle::Interpretation organs = turtle::interpretCpu(drawn, commands, turtles, {});
    for (const shared::OrganInstance& o : organs.organs) {
        const turtle::Bounds box = turtle::organBounds(o);
        bounds[o.plant].add(box.min - organs.plantOrigins[o.plant]);
        bounds[o.plant].add(box.max - organs.plantOrigins[o.plant]);
    }
    return bounds;
}

Simulation::Simulation(const SimulationOptions& options, const vk::Context* context) : impl_(std::make_unique<Impl>()) {
    Impl& m = *impl_;
    m.context = context;
    m.options = options;
    if (!(options.dt > 0) || !std::isfinite(options.dt)) throw std::invalid_argument("the tick's dt must be positive");
    std::vector<ir::EcoWarning> warnings;
    m.g = grow::loadGrowingSpecies(options.file, &warnings);
    for (const ir::EcoWarning& w : warnings)
        std::fprintf(stderr, "%s:%d:%d: warning: %s\n", w.loc.file.c_str(), w.loc.line, w.loc.col, w.message.c_str());
    m.derive.plants = options.plants ? options.plants : uint32_t(m.g.species.size());
    m.derive.seed = options.seed;
    m.derive.maxModules = options.maxModules;
    m.derive.maxSeconds = options.maxSeconds;
    m.derive.particles = true;
    m.seed = options.seed >= 0 ? uint32_t(options.seed) : m.g.species.front().seed;
    m.tables = grow::growthTables(m.g.species, m.g.ecoPlants);
    m.deriveTimes = grow::plantDeriveTimes(m.g.ecoPlants, m.derive.plants, m.seed);
    m.nextStep = m.deriveTimes;
    const ir::Alphabet& alphabet = m.g.species.front().alphabet;
    m.commands = turtle::turtleCommands(alphabet);
    for (const ir::Grammar& grammar : m.g.species) m.turtles.push_back(turtle::turtleSettings(grammar, alphabet));
    const bool asScene = m.g.scene && m.derive.plants == m.g.species.size();
    m.speciesBounds = m.grownPlants();
    // A field of many: grown neighbours touch but do not overlap (turtle::fieldSpacing).
    const float spacing = asScene ? 0.0f : turtle::fieldSpacing({options.spacing, {}}, m.speciesBounds);
    m.field.placements = m.placeField(m.derive.plants, spacing);

    if (options.backend == Backend::Gpu) {
        if (!context) throw std::logic_error("the GPU backend grows the field on a Vulkan device");
        m.deriver = std::make_unique<gpu::GpuDeriver>(*context, m.g.species, gpu::GpuStrategy::Parallel);
        m.deriver->begin(m.derive);
        m.growth = std::make_unique<grow::GpuGrowth>(*context, m.tables, m.deriveTimes);
        m.modules = m.deriver->current().count;
    } else {
        m.reference = std::make_unique<cpu::SteppedDerivation>(m.g.species, m.derive);
        m.modules = m.reference->current().size();
    }
}

Simulation::~Simulation() = default;

TickReport Simulation::tick() {
    Impl& m = *impl_;
    TickReport report;
    report.tick = m.ticks;
    m.drawnOrgans = nullptr; // the organs drawn before describe the field before the tick
    m.time = double(m.ticks + 1) * m.options.dt;
    std::vector<uint8_t> due(m.derive.plants, 0);
    for (uint32_t p = 0; p < m.derive.plants; ++p)
        if (m.time >= m.nextStep[p]) {
            due[p] = 1;
            m.nextStep[p] += m.deriveTimes[p];
        }
    const grow::TickSettings ts = m.settings(m.ticks);
    if (m.deriver) {
        report.derived = m.deriver->advance(due);
        const stream::DeviceModules derived = m.deriver->current();
        m.growth->tick(derived, ts);
        m.modules = derived.count;
    } else {
        report.derived = m.reference->advance(due);
        grow::tickCpu(ts, m.reference->current());
        m.modules = m.reference->current().size();
    }
    ++m.ticks;
    report.time = m.time;
    report.modules = m.modules;
    return report;
}

const turtle::DeviceOrgans& Simulation::interpret() {
    Impl& m = *impl_;
    if (!m.context) throw std::logic_error("Simulation::interpret: drawing needs a Vulkan device");
    // The sizes of this moment: the last tick's.
    const grow::TickSettings ts = m.settings(m.ticks == 0 ? 0 : m.ticks - 1);
    if (m.deriver) {
        const stream::DeviceModules drawn = m.deriver->drawn();
        if (m.tables.drawsGrowth()) m.growth->growSizes(drawn, ts);
        if (!m.turtle) m.turtle = std::make_unique<turtle::GpuTurtle>(*m.context, m.commands, m.turtles);
        m.drawnParticles = drawn.particles;
        m.drawnOrgans = &m.turtle->interpret(drawn, m.field);
        return *m.drawnOrgans;
    }
    stream::ModuleString drawn = m.reference->drawn();
    if (m.tables.drawsGrowth()) grow::growSizesCpu(ts, m.deriveTimes, drawn);
    m.hostOrgans = turtle::interpretCpu(drawn, m.commands, m.turtles, m.field);
    m.hostParticles = std::move(drawn.particles);
    m.uploaded = turtle::uploadOrgans(*m.context, m.hostOrgans);
    m.drawnOrgans = &m.uploaded;
    return m.uploaded;
}

std::vector<shared::PlantStatistics> Simulation::statistics() {
    Impl& m = *impl_;
    if (!m.drawnOrgans) throw std::logic_error("Simulation::statistics before interpret()");
    if (!m.deriver) return plantStatisticsCpu(m.hostOrgans, m.baseHeights(), m.hostParticles);
    if (!m.statistics) m.statistics = std::make_unique<GpuPlantStatistics>(*m.context);
    m.context->submitAndWait(
        [&](VkCommandBuffer cmd) { m.statistics->record(cmd, *m.drawnOrgans, m.drawnParticles, m.baseHeights()); });
    return m.statistics->read();
}

std::vector<uint64_t> Simulation::plantModules() const {
    const Impl& m = *impl_;
    std::vector<uint64_t> starts;
    if (m.deriver) {
        const stream::DeviceModules derived = m.deriver->current();
        std::vector<uint32_t> table = vk::downloadVector<uint32_t>(*m.context, *derived.plantStarts, derived.plants + 1);
        starts.assign(table.begin(), table.end());
    } else {
        starts.assign(m.reference->current().plantStart.begin(), m.reference->current().plantStart.end());
    }
    std::vector<uint64_t> modules;
    for (size_t p = 0; p + 1 < starts.size(); ++p) modules.push_back(starts[p + 1] - starts[p]);
    return modules;
}

std::string Simulation::speciesName(uint32_t plant) const {
    const Impl& m = *impl_;
    const uint32_t s = ir::speciesOfPlant(plant, m.g.species.size());
    if (m.g.ecoPlants[s]) return m.g.ecoPlants[s]->name;
    return std::filesystem::path(m.options.file).stem().string();
}

draw::Bounds Simulation::grownBounds() const {
    const Impl& m = *impl_;
    draw::Bounds field{glm::vec3(1e30f), glm::vec3(-1e30f)};
    for (uint32_t p = 0; p < m.derive.plants; ++p) {
        const turtle::Bounds& b = m.speciesBounds[ir::speciesOfPlant(p, m.g.species.size())];
        if (b.empty()) continue;
        const shared::PlantPlacement& at = m.field.placements[p];
        for (int corner = 0; corner < 8; ++corner) {
            const glm::vec3 c((corner & 1) ? b.max.x : b.min.x, (corner & 2) ? b.max.y : b.min.y,
                              (corner & 4) ? b.max.z : b.min.z);
            const glm::vec3 q = turtle::placePoint(at, c);
            field.min = glm::min(field.min, q);
            field.max = glm::max(field.max, q);
        }
    }
    return field;
}

double Simulation::time() const { return impl_->time; }
uint32_t Simulation::ticks() const { return impl_->ticks; }
uint32_t Simulation::plants() const { return impl_->derive.plants; }
uint64_t Simulation::modules() const { return impl_->modules; }
double Simulation::grownBy() const {
    return latestGrowth(impl_->g.species, impl_->tables, impl_->deriveTimes, impl_->derive.steps);
}
const grow::GrowingSpecies& Simulation::species() const { return impl_->g; }
const std::vector<shared::PlantPlacement>& Simulation::placements() const { return impl_->field.placements; }

} // namespace simeco::field
