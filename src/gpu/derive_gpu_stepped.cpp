// Derivation step by step over simulated time: the growth simulation derives a plant whenever its DeriveTime is
// due, so the string stays on the device between steps, its particle state updated in place, and the
// homomorphism is drawn from it without ending the derivation.
#include <stdexcept>
#include <string>

#include "gpu/derive_gpu_impl.h"
#include "vk/barriers.h"

namespace simeco::gpu {
namespace {

// A string's symbols and parameters copied from one pair of buffers to another, ordered after and before the rest.
void recordStringCopy(VkCommandBuffer cmd, const vk::Buffer& fromSymbols, const vk::Buffer& fromParams,
                      const vk::Buffer& toSymbols, const vk::Buffer& toParams, VkDeviceSize symbolBytes,
                      VkDeviceSize paramBytes) {
    vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
    const VkBufferCopy symbols{0, 0, symbolBytes}, params{0, 0, paramBytes};
    vkCmdCopyBuffer(cmd, fromSymbols.handle(), toSymbols.handle(), 1, &symbols);
    vkCmdCopyBuffer(cmd, fromParams.handle(), toParams.handle(), 1, &params);
    vk::memoryBarrier(cmd, vk::Hazard::TransferToAny);
}

} // namespace

GpuDeriver::Impl::Stepped& GpuDeriver::Impl::steppedState(const char* call) const {
    if (!stepped) throw std::logic_error(std::string("GpuDeriver::") + call + " before begin()");
    return *stepped;
}

int GpuDeriver::Impl::runSteppedBatch(std::vector<RecordedStep>& batch, int stepsAfterBatch) {
    Stepped& s = *stepped;
    int cur = s.cur;
    GpuDeriveStats stats;
    for (size_t done = 0; done < batch.size();)
        done = runBatch(batch, done, cur, s.seed, s.budget, false, stepsAfterBatch, stats);
    // The next batch builds its bracket tree afresh: partners carried from this one would describe its input.
    partnersStream = -1;
    partnersLive = false;
    return cur;
}

void GpuDeriver::Impl::beginStepped(const stream::DeriveOptions& asked, const stream::SteppedState* from) {
    if (!recordsSteps()) throw std::logic_error("GpuDeriver::begin: stepping needs the parallel strategy");
    if (!recordings.empty())
        throw std::logic_error("GpuDeriver::begin: a recorded derivation is not read yet (recorded())");
    stream::DeriveOptions options = asked;
    if (options.maxModules == 0) options.maxModules = defaultModuleBudget(options.particles);
    stepped.reset();
    stream::PlantControl control(species, options);
    if (from) {
        if (from->plants.size() != control.plants() || from->string.plantStart.size() != control.plants() + 1 ||
            from->string.particles.size() != (options.particles ? from->string.size() : 0))
            throw std::invalid_argument("GpuDeriver::resume: the state is not of this derivation's plants");
    }
    startDerivation(control, options, from ? &from->string : nullptr);
    if (from)
        for (uint32_t plant = 0; plant < control.plants(); ++plant) control.restore(plant, from->plants[plant]);
    const uint32_t seed = control.seed();
    const uint64_t budget = control.budget();
    stepped = std::make_unique<Stepped>(Stepped{std::move(control), options, seed, budget, from ? from->fieldStep : 0, 0});
    prepareRecorded(false);
    makeRoom(0, streams[0].count);
    SubmissionEnd submission{*this};
    ctx.submitAndWait([&](VkCommandBuffer cmd) { recordPendingCopies(cmd); });
    lastStream = 0;
}

void GpuDeriver::begin(const stream::DeriveOptions& options) {
    impl_->beginStepped(options, nullptr);
}

void GpuDeriver::resume(const stream::DeriveOptions& options, const stream::SteppedState& state) {
    impl_->beginStepped(options, &state);
}

stream::SteppedState GpuDeriver::save() const {
    const Impl& m = *impl_;
    const Impl::Stepped& s = m.steppedState("save");
    stream::SteppedState state{m.readBack(m.streams[s.cur], m.carriesParticles), s.fieldStep, {}};
    for (uint32_t plant = 0; plant < m.plants; ++plant) state.plants.push_back(s.control.variables(plant));
    return state;
}

uint32_t GpuDeriver::advance(const std::vector<uint8_t>& due) {
    Impl& m = *impl_;
    Impl::Stepped& s = m.steppedState("advance");
    if (due.size() != m.plants) throw std::invalid_argument("GpuDeriver::advance: one flag per plant");
    std::vector<uint8_t> growing(m.plants, 0);
    uint32_t deriving = 0;
    for (uint32_t plant = 0; plant < m.plants; ++plant) {
        growing[plant] = due[plant] && s.control.beginStep(plant, s.control.stepsDerived(plant) + 1);
        deriving += growing[plant];
    }
    if (deriving == 0) return 0;
    ++s.fieldStep;
    bool frozen = m.writePlantState(s.control, growing, reinterpret_cast<double*>(m.host().batchGlobals.mapped()),
                                    reinterpret_cast<double*>(m.host().batchArrays.mapped()),
                                    reinterpret_cast<uint32_t*>(m.host().batchFrozen.mapped()));
    for (uint32_t plant = 0; plant < m.plants; ++plant)
        if (growing[plant]) s.control.endStep(plant, s.control.stepsDerived(plant) + 1);
    std::vector<Impl::RecordedStep> batch{{s.fieldStep, frozen}};
    s.cur = m.runSteppedBatch(batch, 1);
    m.lastStream = s.cur;
    s.drawnStands = false;
    return deriving;
}

stream::DeviceModules GpuDeriver::current() const {
    const Impl& m = *impl_;
    const Stream& s = m.streams[m.steppedState("current").cur];
    return stream::DeviceModules{&s.sym,
                                 &s.par,
                                 &s.plantStart,
                                 s.count,
                                 m.plants,
                                 static_cast<uint32_t>(m.stride),
                                 m.carriesParticles ? &s.particles : nullptr};
}

stream::DeviceModules GpuDeriver::drawn() {
    Impl& m = *impl_;
    Impl::Stepped& s = m.steppedState("drawn");
    s.drawnStands = true;
    if (!m.homomorphismMatch) return current();
    // The homomorphism sees the globals as the Start block sets them; the steps go on with their own.
    stream::PlantControl control(m.species, s.options);
    std::vector<Impl::RecordedStep> batch;
    m.planHomomorphism(control, batch);
    m.lastStream = m.runSteppedBatch(batch, 0);
    // Kept as written, for drawing it again (recordDrawnAgain()).
    const Stream& out = m.streams[m.lastStream];
    const VkDeviceSize symbolBytes = bytes(out.count, 4), paramBytes = bytes(out.count, 4ull * uint64_t(m.stride));
    if (!m.drawnSymbols || m.drawnSymbols.size() < symbolBytes)
        m.drawnSymbols = vk::Buffer(m.ctx, symbolBytes + symbolBytes / 2, vk::MemoryUsage::DeviceLocal);
    if (!m.drawnParams || m.drawnParams.size() < paramBytes)
        m.drawnParams = vk::Buffer(m.ctx, paramBytes + paramBytes / 2, vk::MemoryUsage::DeviceLocal);
    m.ctx.submitAndWait([&](VkCommandBuffer cmd) {
        recordStringCopy(cmd, out.sym, out.par, m.drawnSymbols, m.drawnParams, symbolBytes, paramBytes);
    });
    return lastDrawn();
}

bool GpuDeriver::drawnStands() const {
    return impl_->steppedState("drawnStands").drawnStands;
}

void GpuDeriver::recordDrawnAgain(VkCommandBuffer cmd) {
    Impl& m = *impl_;
    Impl::Stepped& s = m.steppedState("recordDrawnAgain");
    if (!s.drawnStands) throw std::logic_error("GpuDeriver::recordDrawnAgain: a step derived since drawn()");
    if (!m.homomorphismMatch) return;
    const Stream& out = m.streams[m.lastStream];
    if (out.count == 0) return;
    recordStringCopy(cmd, m.drawnSymbols, m.drawnParams, out.sym, out.par, bytes(out.count, 4),
                     bytes(out.count, 4ull * uint64_t(m.stride)));
    if (!m.carriesParticles) return;
    m.recordParticleGather(cmd, s.cur, m.lastStream);
    vk::memoryBarrier(cmd, vk::Hazard::ComputeToCompute);
}

stream::DeviceModules GpuDeriver::lastDrawn() const {
    const Impl& m = *impl_;
    if (!m.steppedState("lastDrawn").drawnStands)
        throw std::logic_error("GpuDeriver::lastDrawn: a step derived since drawn()");
    if (!m.homomorphismMatch) return current();
    stream::DeviceModules modules = lastString();
    modules.origins = &m.streams[m.lastStream].origin; // the particle gather's: where each module came from
    return modules;
}

} // namespace simeco::gpu
