// A tick of the growing field: the plants whose DeriveTime is due derive a step, and every particle grows.

#include "field/simulation_impl.h"

namespace simeco::field {

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
        const double grownBefore = m.seconds.grow;
        // The last round of steps, on the device, in one submission with the growth of every particle.
        grown = m.options.backend == Backend::Gpu && !m.anyDue();
        const uint32_t derived = grown ? m.deriveAndGrowInOneSubmission(due, report.rederived) : m.deriveDue(due);
        m.seconds.derive += secondsSince(start) - (m.seconds.grow - grownBefore);
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
    if (!b.room || b.roomGuessed) return std::nullopt;
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
    // The marks the string had: one that brings others (a first curve, say) does not fit, and is drawn again. A
    // seedling's string drew nothing: its first step brings the stems and what else it draws, every mark.
    room.marks = b.room->organs > 0 ? b.room->marks : ~0u;
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
    submitGrowthWaiting(); // a tick before, not drawn, grows before the string it grows is derived on
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
    if (options.backend == Backend::Gpu) {
        submitGrowthWaiting(); // the tick before, not drawn
        for (Batch& b : batches) {
            growthToRecord.push_back(settings(b, ticks));
            b.modules = b.deriver->current().count;
        }
        return;
    }
    const Clock::time_point start = Clock::now();
    for (Batch& b : batches) {
        grow::tickCpu(settings(b, ticks), b.reference->current());
        b.modules = b.reference->current().size();
    }
    seconds.grow += secondsSince(start);
}

void Simulation::Impl::recordGrowthWaiting(VkCommandBuffer cmd) {
    if (growthToRecord.empty()) return;
    growthClock->open(cmd);
    for (size_t k = 0; k < growthToRecord.size(); ++k)
        batches[k].growth->recordTick(cmd, batches[k].deriver->current(), growthToRecord[k]);
    growthClock->close(cmd);
    growthToRecord.clear();
}

void Simulation::Impl::submitGrowthWaiting() {
    if (growthToRecord.empty()) return;
    const Clock::time_point start = Clock::now();
    context->submitAndWait([&](VkCommandBuffer cmd) { recordGrowthWaiting(cmd); });
    growthClock->read(); // the submission's whole time is the growth's
    seconds.grow += secondsSince(start);
}

double Simulation::Impl::growthRecorded() {
    const double gpuSeconds = growthClock->read();
    seconds.grow += gpuSeconds;
    return gpuSeconds;
}

uint32_t Simulation::Impl::deriveAndGrowInOneSubmission(const std::vector<uint8_t>& due, uint32_t& rederived) {
    std::vector<uint8_t> stepped(batches.size(), 0);
    std::vector<uint64_t> modulesBefore;
    for (const Batch& b : batches)
        modulesBefore.push_back(b.modules);
    uint32_t derived = 0;
    // A tick before, not drawn, on its own: a batch's growth recorded twice in one submission could find its buffers
    // grown for the second, the first's gone.
    submitGrowthWaiting();
    context->submitAndWait([&](VkCommandBuffer cmd) {
        for (size_t k = 0; k < batches.size(); ++k) {
            Batch& b = batches[k];
            const uint32_t batchDerived = b.deriver->recordAdvance(cmd, slice(due, b.first, b.count));
            stepped[k] = batchDerived > 0 ? 1 : 0;
            derived += batchDerived;
        }
        // Every batch's growth after every step, timed as one stage.
        for (Batch& b : batches) growthToRecord.push_back(settings(b, ticks));
        recordGrowthWaiting(cmd);
    });
    growthRecorded();
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
            b.roomGuessed = true;
        } catch (...) {
            b.room.reset();
            if (!failure) failure = std::current_exception();
        }
    }
    if (failure) std::rethrow_exception(failure);
    // A batch whose step outgrew its streams derived it again, waiting: its particles grow on that string.
    if (!outgrown.empty()) {
        const Clock::time_point start = Clock::now();
        context->submitAndWait([&](VkCommandBuffer cmd) {
            for (Batch* b : outgrown)
                b->growth->recordTick(cmd, b->deriver->current(), settings(*b, ticks));
        });
        seconds.grow += secondsSince(start);
    }
    for (Batch& b : batches)
        b.modules = b.deriver->current().count;
    return derived;
}

} // namespace simeco::field
