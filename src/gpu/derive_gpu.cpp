#include "gpu/derive_gpu.h"

#include <algorithm>
#include <chrono>
#include <span>

#include <fmt/format.h>

#include "compute/shared/particle_layout.h"
#include "cpu/evaluator.h"
#include "gpu/derive_gpu_impl.h"
#include "ir/species.h"

namespace simeco::gpu {

namespace {

// Whether every plant's `[` and `]` pair up within the plant.
bool bracketsBalanced(const cpu::ModuleString& s) {
    for (size_t plant = 0; plant < s.plants(); ++plant) {
        int64_t depth = 0;
        for (uint64_t i = s.plantStart[plant]; i < s.plantStart[plant + 1]; ++i) {
            depth += s.sym[i] == ir::kBranchOpen ? 1 : s.sym[i] == ir::kBranchClose ? -1 : 0;
            if (depth < 0) return false;
        }
        if (depth != 0) return false;
    }
    return true;
}

} // namespace

GpuDeriver::GpuDeriver(const vk::Context& context, const ir::Grammar& g, GpuStrategy strategy, GpuLoads loads,
                       GpuContextMatch contexts)
    : impl_(std::make_unique<Impl>(context, std::vector<ir::Grammar>{g}, strategy, loads, contexts)) {}

GpuDeriver::GpuDeriver(const vk::Context& context, std::vector<ir::Grammar> species, GpuStrategy strategy,
                       GpuLoads loads, GpuContextMatch contexts)
    : impl_(std::make_unique<Impl>(context, std::move(species), strategy, loads, contexts)) {}

GpuStrategy GpuDeriver::strategy() const { return impl_->strategy; }

GpuLoads GpuDeriver::loads() const { return impl_->texelInputs ? GpuLoads::TexelBuffers : GpuLoads::StorageBuffers; }

GpuContextMatch GpuDeriver::contextMatch() const {
    return impl_->contextChunks ? GpuContextMatch::Chunks : GpuContextMatch::Walks;
}

GpuDeriver::~GpuDeriver() = default;

cpu::DeriveResult GpuDeriver::derive(const cpu::DeriveOptions& options, bool readBack, GpuDeriveStats* statsOut) {
    Impl& m = *impl_;
    GpuDeriveStats stats;
    stats.compileSeconds = m.compileSeconds;
    auto start = std::chrono::steady_clock::now();
    uint32_t seed = options.seed >= 0 ? uint32_t(options.seed) : m.species.front().seed;
    m.plants = std::max<uint32_t>(options.plants, 1);
    uint64_t budget = options.maxModules ? options.maxModules : cpu::defaultModuleBudget(m.stride);
    m.carriesParticles = options.particles;
    // The plant tables are sized by the plant count, which may change between derivations.
    for (Stream& s : m.streams) {
        s.plantStart = vk::Buffer(m.ctx, bytes(m.plants + 1, 4), vk::MemoryUsage::DeviceLocal);
        s.count = 0;
    }
    m.partnersStream = -1;
    m.bracketTrees = 0;
    auto speciesOf = [&](uint32_t plant) -> const ir::Grammar& {
        return m.species[ir::speciesOfPlant(plant, m.species.size())];
    };
    auto stepsOf = [&](uint32_t plant) { return options.steps >= 0 ? options.steps : speciesOf(plant).derivationLength; };
    int steps = 0;
    for (uint32_t plant = 0; plant < std::min<uint32_t>(m.plants, uint32_t(m.species.size())); ++plant)
        steps = std::max(steps, stepsOf(plant));

    // Host side: each plant's control blocks and axiom, exactly as the CPU reference evaluates them.
    std::vector<cpu::PlantState> states(m.plants);
    auto runBlock = [&](uint32_t plant, const std::vector<ir::Stmt>& block, uint32_t step, cpu::ControlBlock which) {
        cpu::Evaluator evaluator(speciesOf(plant), states[plant]);
        evaluator.key = cpu::controlBlockKey(seed, plant, step, which);
        evaluator.exec(block, nullptr);
    };
    cpu::ModuleString initial;
    initial.stride = m.stride;
    initial.plantStart.push_back(0);
    std::vector<float> values;
    for (uint32_t plant = 0; plant < m.plants; ++plant) {
        const ir::Grammar& g = speciesOf(plant);
        states[plant].reset(g);
        cpu::Evaluator evaluator(g, states[plant]);
        evaluator.key = cpu::controlBlockKey(seed, plant, 0, cpu::ControlBlock::Start);
        evaluator.exec(g.startBlock, nullptr);
        for (const ir::SuccessorModule& mod : g.axiom) {
            values.clear();
            for (const ir::Expr& e : mod.args) values.push_back(static_cast<float>(evaluator.eval(e, nullptr)));
            initial.push(mod.sym, values.data(), values.size());
        }
        initial.plantStart.push_back(initial.size());
    }
    if (initial.size() > budget)
        throw ir::LimitError(fmt::format("the axioms alone exceed the module budget of {} modules", budget));
    m.axiomsBalanced = bracketsBalanced(initial);

    int cur = 0;
    {
        Stream& s = m.streams[cur];
        m.ensureStream(s, initial.size());
        std::vector<uint32_t> words(initial.size());
        for (size_t i = 0; i < initial.size(); ++i) words[i] = initial.sym[i] | (uint32_t(initial.paramCount[i]) << 24);
        if (!words.empty()) {
            vk::upload(m.ctx, s.sym, std::as_bytes(std::span<const uint32_t>(words)));
            vk::upload(m.ctx, s.par, std::as_bytes(std::span<const float>(initial.params)));
        }
        std::vector<uint32_t> table(initial.plantStart.begin(), initial.plantStart.end());
        vk::upload(m.ctx, s.plantStart, std::as_bytes(std::span<const uint32_t>(table)));
        s.count = static_cast<uint32_t>(initial.size());
        if (options.particles) {
            std::vector<shared::ParticleState> particles;
            for (std::vector<shared::ParticleState>& plant :
                 cpu::splitAxiomParticles(m.species, m.plants, options.initialParticles))
                particles.insert(particles.end(), plant.begin(), plant.end());
            m.ensureParticles(s);
            if (!particles.empty())
                vk::upload(m.ctx, s.particles, std::as_bytes(std::span<const shared::ParticleState>(particles)));
        }
    }

    m.globals = vk::Buffer(m.ctx, bytes(uint64_t(m.plants) * std::max<uint32_t>(m.globalStride, 1), 8), vk::MemoryUsage::Upload);
    m.arrays = vk::Buffer(m.ctx, bytes(uint64_t(m.plants) * std::max<uint32_t>(m.arrayStride, 1), 8), vk::MemoryUsage::Upload);
    m.plantFrozen = vk::Buffer(m.ctx, bytes(m.plants, 4), vk::MemoryUsage::Upload);
    const bool sequential = m.strategy == GpuStrategy::Sequential;
    if (sequential) {
        m.prepareSequential();
        m.hostPlantTable.assign(initial.plantStart.begin(), initial.plantStart.end());
    }
    // The sequential kernel's productions write the state; the host reads it back after each step.
    auto downloadState = [&] {
        const double* gp = reinterpret_cast<const double*>(m.globals.mapped());
        const double* ap = reinterpret_cast<const double*>(m.arrays.mapped());
        const uint32_t* fp = reinterpret_cast<const uint32_t*>(m.plantFrozen.mapped());
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            std::vector<double>& globals = states[plant].globals;
            std::copy(gp + uint64_t(plant) * m.globalStride, gp + uint64_t(plant) * m.globalStride + globals.size(),
                      globals.begin());
            const double* at = ap + uint64_t(plant) * m.arrayStride;
            for (std::vector<double>& a : states[plant].arrays) {
                std::copy(at, at + a.size(), a.begin());
                at += a.size();
            }
            if (fp[plant] == shared::kPlantStopRequested) states[plant].stopRequested = true;
        }
    };
    // A plant freezes once it has derived its species' length, or after the step in which it called stop().
    std::vector<int> derived(m.plants, 0);
    std::vector<uint8_t> growing(m.plants, 0);
    auto uploadState = [&] {
        double* gp = reinterpret_cast<double*>(m.globals.mapped());
        double* ap = reinterpret_cast<double*>(m.arrays.mapped());
        uint32_t* fp = reinterpret_cast<uint32_t*>(m.plantFrozen.mapped());
        m.anyFrozen = false;
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            std::copy(states[plant].globals.begin(), states[plant].globals.end(), gp + uint64_t(plant) * m.globalStride);
            uint64_t at = uint64_t(plant) * m.arrayStride;
            for (const std::vector<double>& a : states[plant].arrays) {
                std::copy(a.begin(), a.end(), ap + at);
                at += a.size();
            }
            fp[plant] = growing[plant] ? shared::kPlantGrowing : shared::kPlantFrozen;
            m.anyFrozen = m.anyFrozen || !growing[plant];
        }
    };

    std::optional<vk::Timestamps> timer;
    if (m.ctx.timestampValidBits() > 0) timer.emplace(m.ctx, 2);

    for (int step = 1; step <= steps; ++step) {
        bool anyGrowing = false;
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            growing[plant] = step <= stepsOf(plant) && !states[plant].stopRequested;
            if (!growing[plant]) continue;
            anyGrowing = true;
            const ir::Grammar& g = speciesOf(plant);
            if (!g.globalNames.empty() && g.globalNames.front() == "Q") states[plant].globals[0] = step;
            runBlock(plant, g.startEachBlock, uint32_t(step), cpu::ControlBlock::StartEach);
        }
        if (!anyGrowing) break;
        uploadState();
        vk::Timestamps* stepTimer = timer ? &*timer : nullptr;
        if (sequential) {
            cur = m.stepSequential(cur, uint32_t(step), seed, budget, stepTimer, stats);
            downloadState();
        } else {
            cur = m.step(cur, uint32_t(step), seed, budget, stepTimer, stats);
        }
        stats.peakModules = std::max<uint64_t>(stats.peakModules, m.streams[cur].count);
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            if (!growing[plant]) continue;
            ++derived[plant];
            runBlock(plant, speciesOf(plant).endEachBlock, uint32_t(step), cpu::ControlBlock::EndEach);
        }
    }
    for (uint32_t plant = 0; plant < m.plants; ++plant)
        runBlock(plant, speciesOf(plant).endBlock, 0, cpu::ControlBlock::End);

    if (options.homomorphism && m.homomorphismMatch) {
        // As the CPU reference: the homomorphism sees the globals as the Start block sets them, in every plant.
        for (uint32_t plant = 0; plant < m.plants; ++plant) {
            const ir::Grammar& g = speciesOf(plant);
            states[plant].reset(g);
            cpu::Evaluator evaluator(g, states[plant]);
            evaluator.key = cpu::controlBlockKey(seed, plant, 0, cpu::ControlBlock::Start);
            evaluator.exec(g.startBlock, nullptr);
            growing[plant] = 1;
        }
        uploadState();
        cur = m.applyHomomorphism(cur, seed, budget, timer ? &*timer : nullptr, stats);
    } else if (options.homomorphism && m.homomorphismHostReason) {
        throw std::logic_error("the homomorphism cannot run on the device: " + *m.homomorphismHostReason);
    }

    cpu::DeriveResult result;
    result.steps = *std::max_element(derived.begin(), derived.end());
    Stream& final = m.streams[cur];
    m.lastStream = cur;
    stats.modules = final.count;
    stats.bracketTrees = m.bracketTrees;
    result.string.stride = m.stride;
    std::vector<uint32_t> table = vk::downloadVector<uint32_t>(m.ctx, final.plantStart, m.plants + 1);
    result.string.plantStart.assign(table.begin(), table.end());
    if (readBack && final.count > 0) {
        std::vector<uint32_t> words = vk::downloadVector<uint32_t>(m.ctx, final.sym, final.count);
        result.string.params = vk::downloadVector<float>(m.ctx, final.par, size_t(final.count) * size_t(m.stride));
        result.string.sym.resize(words.size());
        result.string.paramCount.resize(words.size());
        for (size_t i = 0; i < words.size(); ++i) {
            result.string.sym[i] = words[i] & shared::kSymbolMask;
            result.string.paramCount[i] = static_cast<uint8_t>(words[i] >> shared::kSymbolBits);
        }
        if (options.particles)
            result.string.particles = vk::downloadVector<shared::ParticleState>(m.ctx, final.particles, final.count);
        // Unused parameter slots are whatever the device left there; the CPU's are zero.
        for (size_t i = 0; i < words.size(); ++i)
            for (size_t k = result.string.paramCount[i]; k < size_t(m.stride); ++k)
                result.string.params[i * size_t(m.stride) + k] = 0.0f;
    }
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (statsOut) *statsOut = stats;
    return result;
}

bool GpuDeriver::appliesHomomorphism() const { return !impl_->homomorphismHostReason; }

DeviceModules GpuDeriver::lastString() const {
    const Impl& m = *impl_;
    if (m.lastStream < 0) throw std::logic_error("lastString() before derive()");
    const Stream& s = m.streams[m.lastStream];
    return DeviceModules{&s.sym,   &s.par, &s.plantStart, s.count, m.plants, static_cast<uint32_t>(m.stride),
                         m.carriesParticles ? &s.particles : nullptr};
}

} // namespace simeco::gpu
