// Derivation on the GPU: every step is match/count -> exclusive scan -> write over the whole module stream of
// all plants, with kernels generated from the grammar (see derive_codegen.h). The result is identical to the
// CPU reference engine's (cpu/derive.h): same modules, parameters within float rounding, same random draws.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <vulkan/vulkan.h>

#include "codegen/derive_support.h"
#include "ir/grammar.h"
#include "stream/derive_options.h"
#include "stream/device_modules.h"
#include "stream/stepped_state.h"

namespace simeco::vk {
class Context;
}

namespace simeco::gpu {

// How the device rewrites: every module at once (match/count, scan, write over the whole stream), or one
// invocation per plant walking its string in order, for grammars whose productions depend on the order of
// application (global writes, carried-over locals, stop()). Auto takes the parallel passes when every species
// allows them.
enum class GpuStrategy { Auto, Parallel, Sequential };

// How the kernels read the string and what earlier passes wrote for each module: through storage buffers, or
// through uniform texel buffers, which CPU implementations gather several times faster (lavapipe runs a loop
// over the subgroup for every storage buffer load) but which hold at most maxTexelBufferElements values, so
// streams are kept within that. Auto takes texel buffers on CPU devices and storage buffers on GPUs.
enum class GpuLoads { Auto, StorageBuffers, TexelBuffers };

// How a step's match pass finds the first context modules its productions read: a walk for each module, or each
// invocation matching a chunk of consecutive modules in order, finding each module's context modules from its
// neighbour's (compute/derive/context_chunks.glsl). Chunks spare a CPU implementation, which runs a subgroup's
// walks as one loop as long as the longest and gathers every module they pass, most of the walking; a GPU
// loads consecutive modules together when each invocation matches one. Chunks are taken only where every module
// of some symbol walks; where the productions' conditions let only modules with given parameters walk, the walks
// stay. Auto takes chunks on CPU devices and walks on GPUs.
enum class GpuContextMatch { Auto, Walks, Chunks };

struct GpuDeriveStats {
    uint64_t modules = 0;            // modules of all plants after the last step
    double seconds = 0;              // wall time of the derivation (without kernel compilation)
    double compileSeconds = 0;       // generating and compiling (or loading from the cache) the kernels
    uint64_t bytesMoved = 0;         // bytes the passes read and wrote, as counted by the host
    std::vector<double> stepMillis;  // GPU time of each step from timestamps (empty if unsupported)
    uint64_t peakModules = 0;
    uint32_t bracketTrees = 0;       // bracket trees built: once, when each step's write carries the partners
    uint32_t waits = 0;              // submissions the host waited for, the string's read-back included
};

class GpuDeriver {
public:
    // Generates and compiles the grammar's kernels (cached on disk by content hash).
    GpuDeriver(const vk::Context& context, const ir::Grammar& g, GpuStrategy strategy = GpuStrategy::Auto,
               GpuLoads loads = GpuLoads::Auto, GpuContextMatch contexts = GpuContextMatch::Auto);
    // Plants of several species in one stream: the grammars share one alphabet (ir::unifySpecies), plant p is
    // of species p mod species.size(), and each species derives its own derivation length.
    GpuDeriver(const vk::Context& context, std::vector<ir::Grammar> species, GpuStrategy strategy = GpuStrategy::Auto,
               GpuLoads loads = GpuLoads::Auto, GpuContextMatch contexts = GpuContextMatch::Auto);
    ~GpuDeriver();
    GpuDeriver(const GpuDeriver&) = delete;
    GpuDeriver& operator=(const GpuDeriver&) = delete;

    // Whether derive() gives the string under the homomorphism when options.homomorphism asks for it: the
    // parallel passes can run every species' homomorphism (or none has one). Otherwise derive() throws when
    // asked; callers read the string back and apply cpu::applyHomomorphismCpu instead.
    bool appliesHomomorphism() const;

    // Derives options.plants plants in one buffer (copies of the grammar, or the species in turn). The string is read
    // back only when `readBack`; otherwise the result's string is empty and `stats` tells the sizes.
    stream::DeriveResult derive(const stream::DeriveOptions& options, bool readBack = true,
                                GpuDeriveStats* stats = nullptr);

    // The string the last derive() left on the device (read back or not), or the derivation recorded() read last,
    // valid until the next derive(), the submission of a recording still in flight, or the deriver's end: what the
    // turtle kernels interpret without a round trip through the host.
    stream::DeviceModules lastString() const;

    // Records deriving options.plants plants into `cmd` for the caller to submit, with no wait: the axioms'
    // copy, every step with its sizes on the device (decomposition included) and the homomorphism where asked,
    // into streams with room for `room` modules (the field's size, as the last derive() found it, say). Needs
    // recordsSteps() and at most kMostRecordedSteps steps (fewer where they rewrite by many depths). Returns the
    // string the submission writes, counted only on the device (the turtle's record() reads it so), until the
    // next recording's submission runs. Two recordings may be in flight: the second is recorded (and submitted)
    // before the first is read, with its own host-side buffers, and must fit the device buffers the first one
    // uses (its room no larger). Throws std::logic_error for a derivation it cannot record, a third in flight, or
    // a second that would grow those buffers; derive() refuses while a recording is not yet read by recorded().
    stream::DeviceModules record(VkCommandBuffer cmd, const stream::DeriveOptions& options, uint64_t room);
    // Once the oldest recording's submission has completed: its result (the plant table; the string stays on the
    // device, lastString()), or nullopt when a step outgrew the room, or its decomposition the depths recorded,
    // which the next record() then has (read the other recording in flight, then derive() or record() again).
    // Throws as derive() does when a step passed the module budget.
    std::optional<stream::DeriveResult> recorded(GpuDeriveStats* stats = nullptr);

    // Derivation step by step over simulated time, for the growth simulation, which derives a plant whenever its
    // DeriveTime is due: begin() starts every plant from its axiom (options.steps, else each species' derivation
    // length, bounds the steps a plant derives; the particle state is carried when options.particles asks);
    // advance() derives one more step of the plants `due` flags that have steps left (the others are copied,
    // as frozen plants are) and returns how many derived; current() is the derived string, on the device, whose
    // particle state the simulation updates in place between steps; drawn() is that string under the
    // homomorphism (the globals as the Start block sets them), written into another stream and valid until the
    // next advance() or drawn(), or current() where no species has a homomorphism. A plant's random draws in a
    // step are keyed by the count of advance() calls, not by its own steps, on both engines
    // (cpu::SteppedDerivation). Needs recordsSteps(); derive() and record() end the stepped derivation. `room`: the
    // modules the streams hold from the start, within the module budget (a field's estimate of its first steps, so
    // that they need not be derived again for want of room); 0: the axioms'.
    void begin(const stream::DeriveOptions& options, uint64_t room = 0);
    uint32_t advance(const std::vector<uint8_t>& due);
    // advance() recorded into `cmd` for the caller to submit, with no wait, within the streams' room (no buffer
    // grows), and the homomorphism of the string it derives after it: returns how many plants derive (0: nothing is
    // recorded). Until advanced(), current() is the string the submission writes, counted only on the device (its
    // `count` bounds it), and what the caller records after the step may read it; other calls are refused. Once the
    // submission has completed, advanced() reads the step's sizes. Where the step outgrew its room it leaves in
    // current() no string or one short of the step's, and advanced() derives it again, waiting (DerivedAgain), so
    // that what the caller recorded on current() must be done again (it read a string of its own bounds, nothing
    // past them). Either way the drawn string then stands (drawnStands(), lastDrawn()) where the homomorphism had a
    // slot in the step's batch (it has, unless it rewrites by many depths); one that outgrew its room is written
    // again, waiting, without touching current() (DrawnAgain).
    uint32_t recordAdvance(VkCommandBuffer cmd, const std::vector<uint8_t>& due);
    enum class Advanced {
        Recorded,     // the step and its homomorphism fit their rooms
        DrawnAgain,   // the homomorphism outgrew its room and was written again, waiting
        DerivedAgain, // the step outgrew its room and was derived again, waiting (its homomorphism too)
    };
    Advanced advanced();
    stream::DeviceModules current() const;
    // Its `origins` say which module of current() each drawn module comes from.
    stream::DeviceModules drawn();
    // Whether the last drawn() string still stands: no step derived since (nor begin() or resume()). The
    // homomorphism reads no particle state (its light() is 1), so it would write the same string again.
    // recordDrawnAgain() records into `cmd` what drawn() would do then: the string's symbols and parameters as the
    // homomorphism wrote them (the drawing grows them in place), and the particles the growth tick changed gathered
    // anew; nothing where there is no homomorphism. lastDrawn() is that string. Both throw std::logic_error where
    // the drawn string does not stand.
    bool drawnStands() const;
    void recordDrawnAgain(VkCommandBuffer cmd);
    stream::DeviceModules lastDrawn() const;
    // Where the stepped derivation stands (read back from the device), and begin() from there instead of the
    // axioms: a state saved from a derivation of the same species and options, on either engine, goes on as it
    // would have.
    stream::SteppedState save() const;
    void resume(const stream::DeriveOptions& options, const stream::SteppedState& state);
    // Whether derive() records its steps one after the other with their sizes on the device, waiting once per batch
    // of steps (the parallel strategy: cuts, predecessors of several modules, decomposition and particle state
    // included), rather than stepping the sequential strategy's kernel from the host. The homomorphism is recorded
    // after any derivation.
    bool recordsSteps() const;

    // Parallel or Sequential: the strategy this deriver uses.
    GpuStrategy strategy() const;
    // StorageBuffers or TexelBuffers: how this deriver's kernels read their inputs.
    GpuLoads loads() const;
    // Walks or Chunks: how this deriver's match passes find context modules, where their productions read any.
    GpuContextMatch contextMatch() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace simeco::gpu
