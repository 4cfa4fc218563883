#include "gpu/derive_gpu.h"

#include <algorithm>
#include <chrono>
#include <span>
#include <stdexcept>

#include <fmt/format.h>

#include "compute/shared/particle_layout.h"
#include "gpu/derive_gpu_impl.h"

namespace simeco::gpu {

namespace {

// Whether every plant's `[` and `]` pair up within the plant.
bool bracketsBalanced(const stream::ModuleString& s) {
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

void GpuDeriver::Impl::reserve(vk::Buffer& buffer, VkDeviceSize size, vk::MemoryUsage usage) {
    if (!buffer || buffer.size() < size) buffer = vk::Buffer(ctx, size, usage);
}

void GpuDeriver::Impl::uploadAxioms(const stream::ModuleString& axioms, const stream::DeriveOptions& options) {
    // Copies a derivation that ended in an error left unrecorded: their buffers may be gone.
    pendingCopies.clear();
    retiredBuffers.clear();
    for (Stream& s : streams) {
        // The plant tables are bound with the plant count's range, which may change between derivations.
        if (!s.plantStart || s.plantStart.size() < bytes(plants + 1, 4)) mayReplace("plant tables");
        reserve(s.plantStart, bytes(plants + 1, 4), vk::MemoryUsage::DeviceLocal);
        s.count = 0;
    }
    Stream& s = streams[0];
    ensureStream(s, axioms.size());
    std::vector<uint32_t> words(axioms.size());
    for (size_t i = 0; i < axioms.size(); ++i) words[i] = axioms.sym[i] | (uint32_t(axioms.paramCount[i]) << 24);
    std::vector<uint32_t> table(axioms.plantStart.begin(), axioms.plantStart.end());
    s.count = static_cast<uint32_t>(axioms.size());
    // The axioms' particles from the options; a string that carries its own (a saved field's) keeps them.
    std::vector<shared::ParticleState> particles;
    if (options.particles) {
        if (axioms.particles.empty()) {
            for (std::vector<shared::ParticleState>& plant :
                 stream::splitAxiomParticles(species, plants, options))
                particles.insert(particles.end(), plant.begin(), plant.end());
        } else {
            particles = axioms.particles;
        }
        ensureParticles(s);
    }
    std::span<const std::byte> parts[] = {std::as_bytes(std::span<const uint32_t>(words)),
                                          std::as_bytes(std::span<const float>(axioms.params)),
                                          std::as_bytes(std::span<const uint32_t>(table)),
                                          std::as_bytes(std::span<const shared::ParticleState>(particles))};
    const vk::Buffer* targets[] = {&s.sym, &s.par, &s.plantStart, &s.particles};
    // Through a staging buffer that the first submission copies from: no submission and wait of their own.
    VkDeviceSize staged = 0;
    for (const std::span<const std::byte>& part : parts) staged += part.size();
    reserve(host().axiomStaging, bytes(staged, 1), vk::MemoryUsage::Upload);
    VkDeviceSize at = 0;
    for (int k = 0; k < 4; ++k) {
        if (parts[k].empty()) continue;
        std::copy(parts[k].begin(), parts[k].end(), host().axiomStaging.mapped() + at);
        pendingCopies.push_back({host().axiomStaging.handle(), targets[k]->handle(), {at, 0, parts[k].size()}});
        at += parts[k].size();
    }
    reserve(globals, bytes(uint64_t(plants) * std::max<uint32_t>(globalStride, 1), 8), vk::MemoryUsage::Upload);
    reserve(arrays, bytes(uint64_t(plants) * std::max<uint32_t>(arrayStride, 1), 8), vk::MemoryUsage::Upload);
    reserve(plantFrozen, bytes(plants, 4), vk::MemoryUsage::Upload);
    if (strategy == GpuStrategy::Sequential) {
        prepareSequential();
        hostPlantTable.assign(axioms.plantStart.begin(), axioms.plantStart.end());
    }
}

void GpuDeriver::Impl::uploadPlantState(const stream::PlantControl& control, const std::vector<uint8_t>& growing) {
    anyFrozen = writePlantState(control, growing, reinterpret_cast<double*>(globals.mapped()),
                                reinterpret_cast<double*>(arrays.mapped()),
                                reinterpret_cast<uint32_t*>(plantFrozen.mapped()));
}

bool GpuDeriver::Impl::writePlantState(const stream::PlantControl& control, const std::vector<uint8_t>& growing,
                                       double* globalsOut, double* arraysOut, uint32_t* frozenOut) const {
    bool frozen = false;
    for (uint32_t plant = 0; plant < plants; ++plant) {
        const stream::PlantState& state = control.state(plant);
        std::copy(state.globals.begin(), state.globals.end(), globalsOut + uint64_t(plant) * globalStride);
        uint64_t at = uint64_t(plant) * arrayStride;
        for (const std::vector<double>& a : state.arrays) {
            std::copy(a.begin(), a.end(), arraysOut + at);
            at += a.size();
        }
        frozenOut[plant] = growing[plant] ? shared::kPlantGrowing : shared::kPlantFrozen;
        frozen = frozen || !growing[plant];
    }
    return frozen;
}

void GpuDeriver::Impl::downloadPlantState(stream::PlantControl& control) const {
    const double* gp = reinterpret_cast<const double*>(globals.mapped());
    const double* ap = reinterpret_cast<const double*>(arrays.mapped());
    const uint32_t* fp = reinterpret_cast<const uint32_t*>(plantFrozen.mapped());
    for (uint32_t plant = 0; plant < plants; ++plant) {
        stream::PlantState& state = control.state(plant);
        std::copy(gp + uint64_t(plant) * globalStride, gp + uint64_t(plant) * globalStride + state.globals.size(),
                  state.globals.begin());
        const double* at = ap + uint64_t(plant) * arrayStride;
        for (std::vector<double>& a : state.arrays) {
            std::copy(at, at + a.size(), a.begin());
            at += a.size();
        }
        if (fp[plant] == shared::kPlantStopRequested) state.stopRequested = true;
    }
}

void GpuDeriver::Impl::startDerivation(stream::PlantControl& control, const stream::DeriveOptions& options,
                                       const stream::ModuleString* from) {
    plants = control.plants();
    carriesParticles = options.particles;
    lightScale = options.particles ? options.lightScale : 0.0f;
    firstPlant = options.firstPlant;
    if (lightScale > 0.0f && kernels.readsLight && strategy == GpuStrategy::Sequential)
        throw std::invalid_argument("light() in a production senses the light grid on the parallel strategy only");
    partnersStream = -1;
    bracketTrees = 0;
    stream::ModuleString axioms = control.startAll();
    if (from) axioms = *from;
    if (axioms.size() > control.budget())
        throw ir::LimitError(fmt::format("the axioms alone exceed the module budget of {} modules", control.budget()));
    axiomsBalanced = bracketsBalanced(axioms);
    tableReadFrom = -1;
    uploadAxioms(axioms, options);
}

stream::ModuleString GpuDeriver::Impl::readBack(const Stream& s, bool particles) const {
    stream::ModuleString string;
    string.stride = stride;
    std::vector<uint32_t> table = vk::downloadVector<uint32_t>(ctx, s.plantStart, plants + 1);
    string.plantStart.assign(table.begin(), table.end());
    if (s.count == 0) return string;
    std::vector<uint32_t> words = vk::downloadVector<uint32_t>(ctx, s.sym, s.count);
    string.params = vk::downloadVector<float>(ctx, s.par, size_t(s.count) * size_t(stride));
    string.sym.resize(words.size());
    string.paramCount.resize(words.size());
    for (size_t i = 0; i < words.size(); ++i) {
        string.sym[i] = words[i] & shared::kSymbolMask;
        string.paramCount[i] = static_cast<uint8_t>(words[i] >> shared::kSymbolBits);
    }
    if (particles) string.particles = vk::downloadVector<shared::ParticleState>(ctx, s.particles, s.count);
    // Unused parameter slots are whatever the device left there; the CPU's are zero.
    for (size_t i = 0; i < words.size(); ++i)
        for (size_t k = string.paramCount[i]; k < size_t(stride); ++k) string.params[i * size_t(stride) + k] = 0.0f;
    return string;
}

uint64_t GpuDeriver::Impl::defaultModuleBudget(bool particles) const {
    uint64_t heap = 0;
    for (const vk::MemoryHeapInfo& h : ctx.deviceInfo().heaps)
        if (h.deviceLocal) heap = std::max<uint64_t>(heap, h.size);
    uint64_t device = stream::deviceBytesPerModule(stride, particles);
    uint64_t host = stream::hostBytesPerDeviceModule(stride);
    VkPhysicalDeviceType type = ctx.deviceInfo().type;
    bool sharesHostMemory = type == VK_PHYSICAL_DEVICE_TYPE_CPU || type == VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU;
    if (sharesHostMemory || heap == 0) return stream::hostMemoryBytes() / 4 / (device + host);
    return std::min(heap / 2 / device, stream::hostMemoryBytes() / 4 / host);
}

stream::DeriveResult GpuDeriver::derive(const stream::DeriveOptions& asked, bool readBack, GpuDeriveStats* statsOut) {
    Impl& m = *impl_;
    GpuDeriveStats stats;
    stats.compileSeconds = m.compileSeconds;
    auto start = std::chrono::steady_clock::now();
    stream::DeriveOptions options = asked;
    if (options.maxModules == 0) options.maxModules = m.defaultModuleBudget(options.particles);

    // Host side: each plant's control blocks and axiom, exactly as the CPU reference evaluates them.
    stream::PlantControl control(m.species, options);
    const uint32_t seed = control.seed();
    const uint64_t budget = control.budget();
    const uint64_t submissionsBefore = m.ctx.submissions();
    // A recorded derivation may still be running on the device with the buffers this one would write.
    if (!m.recordings.empty())
        throw std::logic_error("GpuDeriver: a recorded derivation is not read yet (recorded())");
    m.stepped.reset();
    m.startDerivation(control, options);
    if (options.homomorphism && m.homomorphismHostReason)
        throw std::logic_error("the homomorphism cannot run on the device: " + *m.homomorphismHostReason);
    const bool homomorphism = options.homomorphism && m.homomorphismMatch;

    std::optional<vk::Timestamps> timer;
    if (m.ctx.timestampValidBits() > 0) timer.emplace(m.ctx, 2);
    vk::Timestamps* stepTimer = timer ? &*timer : nullptr;

    // A plant freezes once it has derived its species' length, or after the step in which it called stop().
    std::vector<uint8_t> growing(m.plants, 0);
    int cur = 0;
    if (m.recordsSteps()) {
        cur = m.deriveRecorded(control, cur, seed, budget, stepTimer != nullptr, homomorphism, stats);
    } else {
        for (int step = 1; step <= control.steps(); ++step) {
            if (!control.beginFieldStep(step, growing)) break;
            m.uploadPlantState(control, growing);
            cur = m.stepSequential(cur, uint32_t(step), seed, budget, stepTimer, stats);
            // The sequential kernel's productions write the state; the host reads it back after each step.
            m.downloadPlantState(control);
            stats.peakModules = std::max<uint64_t>(stats.peakModules, m.streams[cur].count);
            control.endFieldStep(step, growing);
        }
        for (uint32_t plant = 0; plant < m.plants; ++plant) control.finish(plant);
        if (homomorphism) cur = m.applyHomomorphism(control, cur, seed, budget, stepTimer != nullptr, stats);
    }

    if (!m.pendingCopies.empty()) { // no pass ran: the axioms still wait in their staging buffer
        GpuDeriver::Impl::SubmissionEnd submission{m};
        m.ctx.submitAndWait([&](VkCommandBuffer cmd) { m.recordPendingCopies(cmd); });
    }

    stream::DeriveResult result;
    result.steps = control.mostStepsDerived();
    const Stream& final = m.streams[cur];
    m.lastStream = cur;
    stats.modules = final.count;
    stats.bracketTrees = m.bracketTrees;
    if (readBack) {
        result.string = m.readBack(final, options.particles);
    } else {
        result.string.stride = m.stride;
        if (m.tableReadFrom == cur) { // the last batch read it back
            const uint32_t* table = reinterpret_cast<const uint32_t*>(m.host().tableReadback.mapped());
            result.string.plantStart.assign(table, table + m.plants + 1);
        } else {
            std::vector<uint32_t> table = vk::downloadVector<uint32_t>(m.ctx, final.plantStart, m.plants + 1);
            result.string.plantStart.assign(table.begin(), table.end());
        }
    }
    stats.waits = static_cast<uint32_t>(m.ctx.submissions() - submissionsBefore);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (statsOut) *statsOut = stats;
    return result;
}

void GpuDeriver::Impl::mayReplace(const char* what) const {
    if (!recordings.empty())
        throw std::logic_error(fmt::format("GpuDeriver::record: the {} would grow while a recorded derivation is in "
                                           "flight; read it first (recorded()), or record within its room",
                                           what));
}

bool GpuDeriver::appliesHomomorphism() const { return !impl_->homomorphismHostReason; }

bool GpuDeriver::recordsSteps() const {
    return impl_->recordsSteps();
}

stream::DeviceModules GpuDeriver::lastString() const {
    const Impl& m = *impl_;
    if (m.lastStream < 0) throw std::logic_error("lastString() before derive()");
    const Stream& s = m.streams[m.lastStream];
    return stream::DeviceModules{&s.sym,   &s.par, &s.plantStart, s.count, m.plants, static_cast<uint32_t>(m.stride),
                         m.carriesParticles ? &s.particles : nullptr};
}

} // namespace simeco::gpu
