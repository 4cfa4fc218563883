// Derivation step by step over simulated time: the growth simulation derives a plant whenever its DeriveTime is
// due, so the string stays on the device between steps, its particle state updated in place, and the
// homomorphism is drawn from it without ending the derivation.
#include <algorithm>
#include <stdexcept>
#include <string>

#include "gpu/derive_gpu_impl.h"
#include "vk/barriers.h"

namespace simeco::gpu {
namespace {

// The steps a stepped derivation makes room for when a step outgrows its streams: the plants go on deriving, and a
// recorded step that outgrows its room must be derived again with the host waiting.
constexpr int kStepsToCome = 4;

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

GpuDeriver::Impl::Stepped& GpuDeriver::Impl::settledState(const char* call) const {
    Stepped& s = steppedState(call);
    if (s.pending) throw std::logic_error(std::string("GpuDeriver::") + call + ": a recorded step is not read yet");
    return s;
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

void GpuDeriver::Impl::beginStepped(const stream::DeriveOptions& asked, const stream::SteppedState* from,
                                    uint64_t room) {
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
    const uint32_t fieldStep = from ? from->fieldStep : 0;
    stepped =
        std::make_unique<Stepped>(Stepped{std::move(control), options, seed, budget, fieldStep, 0, false, {}, false});
    prepareRecorded(false);
    makeRoom(0, std::max<uint64_t>(streams[0].count, std::min(room, budget)));
    SubmissionEnd submission{*this};
    ctx.submitAndWait([&](VkCommandBuffer cmd) { recordPendingCopies(cmd); });
    lastStream = 0;
}

void GpuDeriver::begin(const stream::DeriveOptions& options, uint64_t room) {
    impl_->beginStepped(options, nullptr, room);
}

void GpuDeriver::resume(const stream::DeriveOptions& options, const stream::SteppedState& state) {
    impl_->beginStepped(options, &state);
}

stream::SteppedState GpuDeriver::save() const {
    const Impl& m = *impl_;
    const Impl::Stepped& s = m.settledState("save");
    stream::SteppedState state{m.readBack(m.streams[s.cur], m.carriesParticles), s.fieldStep, {}};
    for (uint32_t plant = 0; plant < m.plants; ++plant) state.plants.push_back(s.control.variables(plant));
    return state;
}

uint32_t GpuDeriver::Impl::planAdvance(const std::vector<uint8_t>& due, std::vector<RecordedStep>& batch) {
    Stepped& s = *stepped;
    if (due.size() != plants) throw std::invalid_argument("GpuDeriver::advance: one flag per plant");
    std::vector<uint8_t> growing(plants, 0);
    uint32_t deriving = 0;
    for (uint32_t plant = 0; plant < plants; ++plant) {
        growing[plant] = due[plant] && s.control.beginStep(plant, s.control.stepsDerived(plant) + 1);
        deriving += growing[plant];
    }
    ++s.fieldStep; // counted where none derives too, as in every batch of the field
    if (deriving == 0) return 0;
    bool frozen = writePlantState(s.control, growing, reinterpret_cast<double*>(host().batchGlobals.mapped()),
                                  reinterpret_cast<double*>(host().batchArrays.mapped()),
                                  reinterpret_cast<uint32_t*>(host().batchFrozen.mapped()));
    for (uint32_t plant = 0; plant < plants; ++plant)
        if (growing[plant]) s.control.endStep(plant, s.control.stepsDerived(plant) + 1);
    batch = {{s.fieldStep, frozen}};
    s.drawnStands = false;
    return deriving;
}

uint32_t GpuDeriver::advance(const std::vector<uint8_t>& due) {
    Impl& m = *impl_;
    Impl::Stepped& s = m.settledState("advance");
    std::vector<Impl::RecordedStep> batch;
    const uint32_t deriving = m.planAdvance(due, batch);
    if (deriving == 0) return 0;
    s.cur = m.runSteppedBatch(batch, kStepsToCome);
    m.lastStream = s.cur;
    return deriving;
}

uint32_t GpuDeriver::recordAdvance(VkCommandBuffer cmd, const std::vector<uint8_t>& due) {
    Impl& m = *impl_;
    Impl::Stepped& s = m.settledState("recordAdvance");
    Impl::PendingStep pending;
    pending.deriving = m.planAdvance(due, pending.batch);
    if (pending.deriving == 0) return 0;
    pending.out = (s.cur + 1) % 3;
    // The homomorphism follows in the same submission, where the batch has a slot for it, with the globals as the
    // Start block sets them (as drawn() writes it): the string is drawn from it until the next step.
    if (m.homomorphismMatch && pending.batch.size() < m.batchSteps()) {
        stream::PlantControl control(m.species, s.options);
        m.planHomomorphism(control, pending.batch);
    }
    // A step that outgrows its room before its write leaves its output's plant table as cleared here, so that what
    // the caller records after it reads nothing; one that stops among its depths leaves a string of its own.
    vk::memoryBarrier(cmd, vk::Hazard::AnyToTransfer);
    vk::cmdFill(cmd, m.streams[pending.out].plantStart, 0);
    m.recordBatch(cmd, pending.batch, 0, s.cur, s.seed, s.budget, nullptr);
    pending.retired = m.endRecording();
    s.pending = std::move(pending);
    m.lastStream = -1; // until advanced() knows the string is there
    return s.pending->deriving;
}

GpuDeriver::Advanced GpuDeriver::advanced() {
    Impl& m = *impl_;
    Impl::Stepped& s = m.steppedState("advanced");
    if (!s.pending) throw std::logic_error("GpuDeriver::advanced() without recordAdvance()");
    Impl::PendingStep pending = std::move(*s.pending);
    s.pending.reset();
    GpuDeriveStats stats;
    std::vector<Impl::RecordedStep>& batch = pending.batch;
    int cur = s.cur;
    size_t done = m.completeBatch(batch, 0, cur, s.budget, nullptr, stats);
    // The step fit where the batch went past it: a homomorphism that outgrew its room after it leaves it standing.
    const Advanced outcome = done == batch.size() ? Advanced::Recorded
                             : done > 0           ? Advanced::DrawnAgain
                                                  : Advanced::DerivedAgain;
    if (done < batch.size()) { // as advance() goes on after a step that stopped its submission
        m.prepareToGoOn(batch, done, cur, s.budget, kStepsToCome);
        while (done < batch.size())
            done = m.runBatch(batch, done, cur, s.seed, s.budget, false, kStepsToCome, stats);
    }
    // The next batch builds its bracket tree afresh, as after runSteppedBatch().
    m.partnersStream = -1;
    m.partnersLive = false;
    // The homomorphism wrote the stream after the derived string's; its string is saved for drawing it again when
    // it is first drawn (recordDrawnAgain()).
    const bool drawnToo = batch.back().homomorphism;
    s.cur = drawnToo ? (cur + 2) % 3 : cur;
    m.lastStream = cur;
    s.drawnStands = drawnToo || !m.homomorphismMatch;
    s.drawnSaved = !drawnToo;
    return outcome;
}

stream::DeviceModules GpuDeriver::current() const {
    const Impl& m = *impl_;
    const Impl::Stepped& stepped = m.steppedState("current");
    const Stream& s = m.streams[stepped.pending ? stepped.pending->out : stepped.cur];
    stream::DeviceModules modules{&s.sym,
                                  &s.par,
                                  &s.plantStart,
                                  stepped.pending ? uint32_t(m.recordedCapacity(s)) : s.count,
                                  m.plants,
                                  static_cast<uint32_t>(m.stride),
                                  m.carriesParticles ? &s.particles : nullptr};
    modules.countOnDevice = stepped.pending.has_value();
    return modules;
}

stream::DeviceModules GpuDeriver::drawn() {
    Impl& m = *impl_;
    Impl::Stepped& s = m.settledState("drawn");
    s.drawnStands = true;
    if (!m.homomorphismMatch) return current();
    // The homomorphism sees the globals as the Start block sets them; the steps go on with their own.
    stream::PlantControl control(m.species, s.options);
    std::vector<Impl::RecordedStep> batch;
    m.planHomomorphism(control, batch);
    m.lastStream = m.runSteppedBatch(batch, 0);
    // Kept as written, for drawing it again (recordDrawnAgain()).
    m.ctx.submitAndWait([&](VkCommandBuffer cmd) { m.recordDrawnSave(cmd); });
    s.drawnSaved = true;
    return lastDrawn();
}

void GpuDeriver::Impl::recordDrawnSave(VkCommandBuffer cmd) {
    const Stream& out = streams[lastStream];
    const VkDeviceSize symbolBytes = bytes(out.count, 4), paramBytes = bytes(out.count, 4ull * uint64_t(stride));
    if (!drawnSymbols || drawnSymbols.size() < symbolBytes)
        drawnSymbols = vk::Buffer(ctx, symbolBytes + symbolBytes / 2, vk::MemoryUsage::DeviceLocal);
    if (!drawnParams || drawnParams.size() < paramBytes)
        drawnParams = vk::Buffer(ctx, paramBytes + paramBytes / 2, vk::MemoryUsage::DeviceLocal);
    recordStringCopy(cmd, out.sym, out.par, drawnSymbols, drawnParams, symbolBytes, paramBytes);
}

bool GpuDeriver::drawnStands() const {
    return impl_->steppedState("drawnStands").drawnStands;
}

void GpuDeriver::recordDrawnAgain(VkCommandBuffer cmd) {
    Impl& m = *impl_;
    Impl::Stepped& s = m.settledState("recordDrawnAgain");
    if (!s.drawnStands) throw std::logic_error("GpuDeriver::recordDrawnAgain: a step derived since drawn()");
    if (!m.homomorphismMatch) return;
    const Stream& out = m.streams[m.lastStream];
    if (out.count == 0) return;
    if (s.drawnSaved) {
        recordStringCopy(cmd, m.drawnSymbols, m.drawnParams, out.sym, out.par, bytes(out.count, 4),
                         bytes(out.count, 4ull * uint64_t(m.stride)));
    } else { // first drawn since a recorded step wrote it: as written, it is saved instead
        m.recordDrawnSave(cmd);
        s.drawnSaved = true;
    }
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
