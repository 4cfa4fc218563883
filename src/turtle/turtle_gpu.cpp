#include "turtle/turtle_gpu.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <deque>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

#include "compute/shared/derive_layout.h"
#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "draw/bounds.h"
#include "gpu/bracket_tree.h"
#include "gpu/scan.h"
#include "ir/source_loc.h"
#include "vk/barriers.h"
#include "vk/context.h"
#include "vk/pipeline.h"

namespace simeco::turtle {

using namespace shared;
using vk::Hazard;

namespace {

VkDeviceSize bytes(std::uint64_t count, std::uint64_t size) { return std::max<VkDeviceSize>(count * size, 4); }

// Whether the alphabet can spell an elasticity command: then a segment may bend even where the view file
// gives no elasticity.
bool hasElasticityCommands(const turtle::TurtleCommands& c) {
    auto elastic = [](std::uint32_t command) {
        return command == kTurtleElasticitySet || command == kTurtleElasticityUp || command == kTurtleElasticityDown ||
               command == kTurtleTropism || command == kTurtleElasticityStep;
    };
    if (std::any_of(c.plain.begin(), c.plain.end(), elastic)) return true;
    if (c.at == turtle::kNoSymbol) return false;
    return std::any_of(c.afterAt.begin(), c.afterAt.end(), elastic) ||
           std::any_of(c.pairs.begin(), c.pairs.end(), elastic);
}

// The commands of every symbol, then each species' surfaces (TurtleSpecies::surfaces), whose start in the table
// it records in `species`.
std::vector<std::uint32_t> commandTableOf(const turtle::TurtleCommands& c,
                                          const std::vector<turtle::TurtleSettings>& settings,
                                          std::vector<TurtleSpecies>& species) {
    std::vector<std::uint32_t> table;
    for (const auto* row : {&c.plain, &c.afterAt, &c.afterQuery, &c.pairPrefix, &c.pairs})
        table.insert(table.end(), row->begin(), row->end());
    for (size_t k = 0; k < settings.size(); ++k) {
        const turtle::TurtleSettings& t = settings[k];
        species[k].surfaces = static_cast<std::uint32_t>(table.size());
        for (std::uint32_t s = 0; s < c.symbols; ++s) {
            const bool known = s < t.surfaceDrawn.size();
            const std::uint32_t drawn = known ? t.surfaceDrawn[s] : kSurfaceNone;
            const glm::vec3 end = known ? t.surfaceEnd[s] : glm::vec3(0.0f);
            table.insert(table.end(), {std::bit_cast<std::uint32_t>(end.x), std::bit_cast<std::uint32_t>(end.y),
                                       std::bit_cast<std::uint32_t>(end.z), drawn});
        }
    }
    return table;
}

TurtleSpecies speciesOf(const turtle::TurtleSettings& t, bool elasticityCommands) {
    TurtleSpecies s{};
    s.angleDegrees = t.angleDegrees;
    s.step = t.step;
    s.width = t.width;
    s.widthIncrement = t.widthIncrement;
    s.colorIncrement = t.colorIncrement;
    s.initialColor = t.initialColor;
    s.elasticity = t.elasticity;
    s.elasticityIncrement = t.elasticityIncrement;
    s.initialScale = t.initialScale;
    bool mayBend = t.elasticity != 0.0f || elasticityCommands;
    s.tropism = {t.tropism.x, t.tropism.y, t.tropism.z, mayBend ? 1.0f : 0.0f};
    s.torque = {t.torque.x, t.torque.y, t.torque.z, t.torque != glm::vec3(0.0f) ? 1.0f : 0.0f};
    s.taperedLines = t.taperedLines ? 1u : 0u;
    s.dollar = t.dollarRolls ? kDollarRolls : t.subLsystems ? kDollarReturns : kDollarIgnored;
    s.tropismRule = t.tropismRule == ir::TropismRule::CpfgDirection ? kTropismCpfgDirection
                    : t.tropismRule == ir::TropismRule::CpfgTropism ? kTropismCpfgTropism
                                                                     : kTropismTorque;
    s.lineStyle = turtle::lineStyleCode(t.lineStyle);
    s.cylinders = (t.cylinderMeshes ? kCylinderMeshes : 0u) | (t.cylinderTwist ? kCylinderTwist : 0u) |
                  (t.cpfgTubes ? kCylinderCpfgTubes : 0u) |
                  (std::min(std::uint32_t(t.cylinderSides), kMostCylinderSides) << kCylinderSidesShift) |
                  (std::uint32_t(t.contourIds.size()) << kCylinderContoursShift);
    return s;
}

// Every species' contour rings (TurtleSpecies::contourFirst), each point's w its contour's id.
std::vector<shared::vec4> contourRingsOf(const std::vector<turtle::TurtleSettings>& species,
                                         std::vector<TurtleSpecies>& table) {
    std::vector<shared::vec4> rings;
    for (size_t s = 0; s < species.size(); ++s) {
        const turtle::TurtleSettings& t = species[s];
        table[s].contourFirst = std::uint32_t(rings.size());
        const size_t stride = size_t(t.cylinderSides) + 1;
        for (size_t k = 0; k < t.contourRings.size(); ++k) {
            const glm::vec3& p = t.contourRings[k];
            rings.push_back({p.x, p.y, p.z, float(t.contourIds[k / stride])});
        }
    }
    return rings;
}


// Rounds of pointer jumping that resolve any path of up to `count` modules (each round doubles the reach),
// made odd so that a ping-pong starting in the first buffer ends in the second.
std::uint32_t jumpRounds(std::uint32_t count) {
    std::uint32_t rounds = std::bit_width(std::max(count, 1u)) + 1;
    return rounds | 1u;
}

} // namespace

UploadedModules::UploadedModules(const vk::Context& context, const stream::ModuleString& s)
    : count_(static_cast<std::uint32_t>(s.size())),
      plants_(static_cast<std::uint32_t>(s.plants())),
      stride_(static_cast<std::uint32_t>(s.stride)) {
    std::vector<std::uint32_t> words(s.size());
    for (size_t i = 0; i < s.size(); ++i) words[i] = s.sym[i] | (std::uint32_t(s.paramCount[i]) << kSymbolBits);
    std::vector<std::uint32_t> starts(s.plantStart.begin(), s.plantStart.end());
    symbols_ = vk::deviceBufferWith(context, std::span<const std::uint32_t>(words));
    params_ = vk::deviceBufferWith(context, std::span<const float>(s.params));
    plantStarts_ = vk::deviceBufferWith(context, std::span<const std::uint32_t>(starts));
}

stream::DeviceModules UploadedModules::view() const {
    return stream::DeviceModules{&symbols_, &params_, &plantStarts_, count_, plants_, stride_};
}

struct GpuTurtle::Impl {
    const vk::Context& ctx;
    gpu::GpuScan scan;
    gpu::BracketTree brackets;
    vk::ComputePipeline setup, polygons, chunkSteps, jumpSteps, chunkSearch, jumpSearch, searchFinish, jumpLevels,
        levelCount, levelLayout, levelScatter, resolveLevel, states, classify, emit, links, taper, field, place,
        passSizes, listGroups;
    bool tapers = false; // some species narrows its segments (TurtleSettings::taperedLines)
    // For strings counted only on the device: the workgroups of the bracket tree's dispatches, as a recorded
    // derivation step sizes them (made on the first such recording).
    std::optional<vk::ComputePipeline> stepSizes;
    vk::Buffer commandTable, speciesTable, palettes, surfaceScales, surfaceShapes, contourRings;
    // Some species draws its generalized cylinders along cpfg's curves (meshes, or cpfg's tubes), which read the
    // settings each control point was made with.
    bool cylinderCurves = false;
    // Each plant's placement in the field, where the caller gives them (FieldOptions::placements).
    vk::Buffer placements;
    // Takes the field's placements, kept while they are the same; refused when they change under a recording.
    void setPlacements(const turtle::FieldOptions& options, std::uint32_t plants);
    // Whether `buffer` holds the placements already (`out.placements` says which it holds); checks their count.
    static bool placedAlready(const turtle::FieldOptions& options, std::uint32_t plants, DeviceOrgans& out,
                              const vk::Buffer& buffer);
    static std::span<const PlantPlacement> placementsToUpload(const turtle::FieldOptions& options);
    void uploadPlacements(const turtle::FieldOptions& options, DeviceOrgans& out, vk::Buffer& buffer) const;
    // The same for a target, recorded into `cmd` (the host writes them into a staging buffer of the target's): a
    // submission of many recordings waits for no uploads of their own.
    void recordPlacementsUpload(VkCommandBuffer cmd, const turtle::FieldOptions& options, TurtleTarget& target) const;
    TurtlePush base{};
    std::uint32_t levels = 0;
    std::uint64_t bytesMoved = 0;

    // The passes' per-module arrays, allocated once and grown (by half again) when a stream outgrows them.
    struct Scratch {
        vk::Buffer commands, parents, plantOf, marks, kinds, slots, lastSlots;
        vk::Buffer steps[2], pointers[2];
        vk::Buffer states;
        vk::Buffer triangleFirst, trianglePrevious;
        vk::Buffer stemBelow, tubeBelow, cylinderAnchors, cylinderStarts;
        // Each module's nearest `@#`, `@Gt(...)`, `@Gr(s)` and `@Gr(a, l, ...)` above it, for cylinder meshes.
        vk::Buffer contourSetters, tangentSetters, radiusScaleSetters, radiusTangentSetters;
        vk::Buffer taperBelow; // the segment whose end may still narrow: a search over every command that ends it
        vk::Buffer stepTargets, searchTargets, searchChunk;
        vk::Buffer searchJumps[2];
        vk::Buffer levels[2];
        vk::Buffer counts, order;
        vk::Buffer flags, offsets;
        // The work lists of the pointer jumping (jump_list.glsl): round r walks lists[r % 2] and hands on to the
        // other; the chunk passes start lists[0].
        vk::Buffer lists[2];
        std::uint64_t modules = 0; // capacity
    } scratch;
    vk::Buffer plantBounds, present;
    // The levels' cursors and the workgroups of their dispatches (level_layout.comp).
    vk::Buffer cursors, levelArguments;
    std::uint64_t plantCapacity = 0, levelCapacity = 0;
    // The status words (compute/shared/turtle_state_layout.h), a host-visible copy a recording ends with, and
    // the words step_sizes writes the bracket tree's workgroups into.
    vk::Buffer status, treeArguments;
    // Recordings submitted and not yet read (recorded()), oldest first: each copies its status words into a
    // readback buffer of its own, and what it had room for.
    struct Pending {
        std::uint32_t slot;
        TurtleRoom room;
    };
    std::deque<Pending> pending;
    vk::Buffer statusReadback[kRecordingsInFlight];
    std::uint32_t nextSlot = 0;
    // The most modules and plants the buffers were sized for.
    std::uint64_t reservedModules = 0, reservedPlants = 0;
    // A recording's workgroups of its passes (pass_sizes.comp).
    vk::Buffer passArguments;
    // What the last interpretation left: its instances grow like the scratch arrays.
    DeviceOrgans organs;

    Impl(const vk::Context& c, const turtle::TurtleCommands& commands, const std::vector<turtle::TurtleSettings>& species)
        : ctx(c),
          scan(c),
          brackets(c, scan),
          setup(vk::ComputePipeline::embedded(c, "turtle/setup")),
          polygons(vk::ComputePipeline::embedded(c, "turtle/polygons")),
          chunkSteps(vk::ComputePipeline::embedded(c, "turtle/chunk_steps")),
          jumpSteps(vk::ComputePipeline::embedded(c, "turtle/jump_steps")),
          chunkSearch(vk::ComputePipeline::embedded(c, "turtle/chunk_search")),
          jumpSearch(vk::ComputePipeline::embedded(c, "turtle/jump_search")),
          searchFinish(vk::ComputePipeline::embedded(c, "turtle/search_finish")),
          jumpLevels(vk::ComputePipeline::embedded(c, "turtle/jump_levels")),
          levelCount(vk::ComputePipeline::embedded(c, "turtle/level_count")),
          levelLayout(vk::ComputePipeline::embedded(c, "turtle/level_layout")),
          levelScatter(vk::ComputePipeline::embedded(c, "turtle/level_scatter")),
          resolveLevel(vk::ComputePipeline::embedded(c, "turtle/resolve_level")),
          states(vk::ComputePipeline::embedded(c, "turtle/states")),
          classify(vk::ComputePipeline::embedded(c, "turtle/classify")),
          emit(vk::ComputePipeline::embedded(c, "turtle/emit")),
          links(vk::ComputePipeline::embedded(c, "turtle/links")),
          taper(vk::ComputePipeline::embedded(c, "turtle/taper")),
          field(vk::ComputePipeline::embedded(c, "turtle/field")),
          place(vk::ComputePipeline::embedded(c, "turtle/place")),
          passSizes(vk::ComputePipeline::embedded(c, "turtle/pass_sizes")),
          listGroups(vk::ComputePipeline::embedded(c, "turtle/list_groups")) {
        bool elastic = hasElasticityCommands(commands);
        std::vector<TurtleSpecies> table;
        std::vector<float> scales;
        std::vector<std::uint32_t> shapes;
        std::vector<shared::vec4> colors;
        for (const turtle::TurtleSettings& t : species) {
            table.push_back(speciesOf(t, elastic));
            tapers = tapers || t.taperedLines;
            cylinderCurves = cylinderCurves || t.cylinderMeshes || t.cpfgTubes;
            std::vector<float> s = t.surfaceScale;
            std::vector<std::uint32_t> k = t.surfaceShape;
            s.resize(commands.symbols, 1.0f);
            k.resize(commands.symbols, 0u);
            scales.insert(scales.end(), s.begin(), s.end());
            shapes.insert(shapes.end(), k.begin(), k.end());
            for (std::uint32_t e = 0; e < kPaletteEntries; ++e) {
                glm::vec4 v = e < t.palette.size() ? t.palette[e] : glm::vec4(1.0f);
                colors.push_back({v.r, v.g, v.b, v.a});
            }
        }
        const std::vector<shared::vec4> rings = contourRingsOf(species, table);
        contourRings = vk::deviceBufferWith(c, std::span<const shared::vec4>(rings));
        std::vector<std::uint32_t> commandWords = commandTableOf(commands, species, table);
        commandTable = vk::deviceBufferWith(c, std::span<const std::uint32_t>(commandWords));
        speciesTable = vk::deviceBufferWith(c, std::span<const TurtleSpecies>(table));
        palettes = vk::deviceBufferWith(c, std::span<const shared::vec4>(colors));
        surfaceScales = vk::deviceBufferWith(c, std::span<const float>(scales));
        surfaceShapes = vk::deviceBufferWith(c, std::span<const std::uint32_t>(shapes));
        base.species = static_cast<std::uint32_t>(species.size());
        base.symbols = commands.symbols;
        base.atSymbol = commands.at;
        base.tildeSymbol = commands.tilde;
        base.querySymbol = commands.query;
        base.maxGroupsX = c.limits().maxComputeWorkGroupCount[0];
        status = vk::Buffer(c, kTurtleStatusWords * 4, vk::MemoryUsage::DeviceLocal);
        for (vk::Buffer& readback : statusReadback)
            readback = vk::Buffer(c, kTurtleStatusWords * 4, vk::MemoryUsage::Readback);
        passArguments = vk::Buffer(c, kGates * kGateWords * 4, vk::MemoryUsage::DeviceLocal,
                                   VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
    }

    void checkRange(std::uint64_t count, std::uint64_t size, const char* what) const {
        std::uint64_t limit = ctx.limits().maxStorageBufferRange;
        if (count * size > limit)
            throw ir::LimitError(fmt::format("the device binds at most {} MiB per buffer; the turtle's {} for {} "
                                             "modules need {} MiB (interpret fewer steps or plants)",
                                             limit >> 20, what, count, (count * size) >> 20));
    }

    vk::Buffer deviceBuffer(std::uint64_t count, std::uint64_t size) const {
        return vk::Buffer(ctx, bytes(count, size), vk::MemoryUsage::DeviceLocal);
    }

    // Room for n modules of `plants` plants (n within the device's binding limit: checkRange).
    void reserve(std::uint64_t n, std::uint64_t plants);
    // Room for the organ instances (half again as many, within the binding), and the organ table and field
    // spacing, in the turtle's own buffers (kept between interpretations) or a target's.
    void reserveOrgans(std::uint64_t count) { sizeOrgans(organs, count); }
    void sizeOrgans(DeviceOrgans& out, std::uint64_t count) const;

    const DeviceOrgans& interpret(const stream::DeviceModules& m, const turtle::FieldOptions& options);
    const DeviceOrgans& record(VkCommandBuffer cmd, const stream::DeviceModules& m,
                               const turtle::FieldOptions& options, TurtleRoom room);
    const DeviceOrgans& recordInto(VkCommandBuffer cmd, const stream::DeviceModules& m,
                                   const turtle::FieldOptions& options, TurtleRoom room, TurtleTarget& target);
    void reserveTargets(std::uint32_t modules, std::uint32_t plants, TurtleRoom room);
    // The target's buffers, its instances for `organCount` organs and half again.
    void sizeTarget(TurtleTarget& target, std::uint64_t organCount) const;
    void recordKeep(VkCommandBuffer cmd, TurtleTarget& target);
    // The turtle's own buffers for recording `bound` modules of `plants` plants within `levelsResolved` levels.
    void reserveRecording(std::uint32_t bound, std::uint32_t plants, std::uint32_t levelsResolved);
    // The most recordInto() records without growing the turtle's buffers (reserveTargets()).
    TurtleRoom targetRoom{};
    std::uint32_t targetModules = 0, targetPlants = 0;

    // What one interpretation's passes share: the stream, the bound on its modules (their count is in the
    // status words) and the push constants, the marks searched for and the levels laid out and resolved.
    struct Run {
        Run(const vk::Buffer& s, const vk::Buffer& p, const vk::Buffer& t) : symbols(s), params(p), starts(t) {}

        const vk::Buffer& symbols;
        const vk::Buffer& params;
        const vk::Buffer& starts;
        std::uint32_t n = 0, plants = 0, rounds = 0;
        std::uint64_t groups = 0, chunkGroups = 0;
        TurtlePush push{};
        DeviceOrgans* out = nullptr;          // where the organs go: the turtle's own, or a target's
        const vk::Buffer* placed = nullptr;   // the plants' placements
        bool countedOnDevice = false; // the host has not read the count: the bracket tree is sized on the device
        std::uint32_t marked = 0;     // the marks that occur, or every mark where the host did not read them
        std::uint32_t levels = 0;     // levels of non-linear modules laid out and resolved
    };

    // Empties the list a chunk pass starts (a fill: a transfer-to-compute barrier must follow).
    void startList(VkCommandBuffer cmd) const;
    // Round r of pointer jumping: the workgroups that walk its list, then `pipeline` over them.
    void dispatchRound(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline,
                       std::initializer_list<vk::BufferRange> buffers, std::span<const std::byte> push,
                       const Run& run, std::uint32_t r) const;
    // Nearest strict ancestor with a hit or stop mark, into `result`: within chunks, then among the targets the
    // chunks point at (searchChunk -> searchJumps[0] -> [1] -> [0] ...; the last round writes [0]), then for all.
    void recordSearch(VkCommandBuffer cmd, const Run& run, std::uint32_t gate, std::uint32_t hit,
                      std::uint32_t stop, const vk::Buffer& result);
    // Dispatches a pass over the modules or over their chunks: with the host's workgroups, or in a recording with
    // those pass_sizes.comp wrote for `gate` (none where the gate's marks do not occur).
    enum class Over { Modules, Chunks };
    void dispatchPass(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline,
                      std::initializer_list<vk::BufferRange> buffers, const TurtlePush& push, const Run& run,
                      std::uint32_t gate, Over over) const;
    // Pass 1: the module count from the plant table into the status words; the bracket tree; commands, parents,
    // steps and marks; polygons; which marks occur at all (into `present`).
    void recordSetup(VkCommandBuffer cmd, const Run& run);
    // Pass 2: steps composed up to the anchors; the searches that need only marks; the levels of the non-linear
    // modules and their counts. Searches for marks no module carries are skipped (their readers never look).
    void recordComposition(VkCommandBuffer cmd, const Run& run);
    // Pass 3: the levels laid out and their non-linear modules resolved one level after another, then every
    // state; organs classified and counted (a tube may draw several segments) and placed by a scan, whose total
    // sizes the instance buffer.
    void recordStates(VkCommandBuffer cmd, const Run& run);
    // Pass 4: organs written, joined, and moved to their plants' places in the field; `organGroups` workgroups
    // cover the organs.
    void recordOrgans(VkCommandBuffer cmd, const Run& run, std::uint64_t organGroups);

    // A run over the first `m.count` modules at most, before the host has read anything.
    Run begin(const stream::DeviceModules& m, const turtle::FieldOptions& options);
    // A run of a recording, which reads nothing back, within `room`, into `out`.
    Run beginRecording(const stream::DeviceModules& m, const turtle::FieldOptions& options, TurtleRoom room,
                       DeviceOrgans& out, const vk::Buffer& placed);
    // The passes of a recording, ending with a copy of the status words into `statusCopy` for the host.
    void recordPasses(VkCommandBuffer cmd, const Run& run, const vk::Buffer& statusCopy);
    // Room for `levels` levels of non-linear modules.
    void reserveLevels(std::uint32_t levels);
    // What the last interpretation needed, and the marks that occurred in its string.
    TurtleRoom needed{};
    std::uint32_t neededMarks = ~0u;
    // The main arrays each pass reads and writes, per module (organs counted as if every module drew one, the
    // buffers' capacity): a model of the traffic, not a measurement.
    static std::uint64_t trafficOf(std::uint64_t n, std::uint64_t stride, std::uint64_t rounds,
                                   std::uint64_t nonlinear) {
        const std::uint64_t step = sizeof(TurtleStep), state = sizeof(TurtleState), organ = sizeof(OrganInstance);
        std::uint64_t perModule = 0;
        perModule += 4 * 9;                                 // bracket depths: deltas, scan, leaves, levels
        perModule += 4 + 4 * stride + 4 * 5 + step;         // setup: module in; command, parent, plant, marks,
                                                            // pointer and step out
        perModule += 4;                                     // polygons: commands
        // Chunk passes (step composition and four searches) and the jumps among their targets, counted as one
        // target per chunk (the chunk boundary) in every round, an upper bound: the lists drop targets once done.
        perModule += 2 * (step + 4) + 4 * 4 * 4;
        perModule += rounds * (3 * (step + 4) + 4 * (3 * 4 + 4) + 5 * 2 * 4) / kTurtleChunk;
        perModule += 4 * 4 * 3;                             // searches' final answers
        perModule += 4 + 2 * 4;                             // levels: marks; counting and scattering
        perModule += 4 + step + 4 + 2 * state;              // states: marks, step, anchor, anchor's and own state
        perModule += 4 * 4 + state + 4 * kOrganKinds;       // classify: commands, marks, polygon, cylinders; flags
        perModule += 3 * 4 * kOrganKinds;                   // scan of the flags
        perModule += 4 * 3 + 2 * state + 4 + organ + 4;     // emit: kinds, commands, parents; states; offset,
                                                            // instance and slot
        perModule += 4 * 4 + organ;                         // links: kinds, commands, marks, slots; instance
        perModule += 2 * organ;                             // place: instance read and written
        std::uint64_t perNonlinear = 4 * 3 + step + 4 + 2 * state; // resolve: order, parent, command, step,
                                                                   // anchor, anchor's and own state
        perNonlinear += rounds * (3 * 8 + 2 * 4);                   // levels' jumps: own, up, out; the lists
        return n * perModule + nonlinear * perNonlinear;
    }
};

const DeviceOrgans& GpuTurtle::Impl::interpret(const stream::DeviceModules& m, const turtle::FieldOptions& options) {
    if (m.countOnDevice) throw std::logic_error("GpuTurtle::interpret: a string not yet derived (record() it)");
    if (!pending.empty()) throw std::logic_error("GpuTurtle::interpret: recordings in flight (read them first)");
    const std::uint32_t n = m.count;
    levels = 0;
    bytesMoved = 0;
    if (n == 0) { // nothing to interpret: an empty table, as the CPU turtle leaves
        turtle::Interpretation empty;
        empty.spacing = options.spacing > 0 ? options.spacing : 1.0f;
        organs = uploadOrgans(ctx, empty);
        needed = TurtleRoom{};
        neededMarks = ~0u;
        return organs;
    }
    checkRange(n, sizeof(TurtleStep), "steps");
    checkRange(std::uint64_t(n) * kOrganKinds, 4, "organ flags");
    reserve(n, m.plants);
    if (scan.capacity() < n * kOrganKinds) scan.reserve(n * kOrganKinds);
    setPlacements(options, m.plants);
    Run run = begin(m, options);

    // The host reads three things between the passes: which marks occur (to skip the searches nothing needs),
    // the levels' count (to dispatch them in turn) and the organs' count (to size the instances).
    ctx.submitAndWait([&](VkCommandBuffer cmd) { recordSetup(cmd, run); });
    std::memcpy(&run.marked, present.mapped(), sizeof run.marked);
    ctx.submitAndWait([&](VkCommandBuffer cmd) { recordComposition(cmd, run); });
    std::uint64_t nonlinear = 0;
    if (run.marked & kMarkNonlinear) {
        run.levels = vk::downloadVector<std::uint32_t>(ctx, scratch.counts, 1)[0];
        // The levels' sizes, for the traffic model only: a few words.
        std::vector<std::uint32_t> counts = vk::downloadVector<std::uint32_t>(ctx, scratch.counts, run.levels + 1);
        for (std::uint32_t level = 1; level <= run.levels; ++level) nonlinear += counts[level];
    }
    levels = run.levels;
    run.push.items = run.levels;
    reserveLevels(run.levels);
    bytesMoved = trafficOf(n, m.stride, run.rounds, nonlinear);
    ctx.submitAndWait([&](VkCommandBuffer cmd) { recordStates(cmd, run); });
    std::uint32_t organCount = vk::downloadVector<std::uint32_t>(ctx, scan.totalBuffer(), 1)[0];
    checkRange(organCount, sizeof(OrganInstance), "organ instances");
    reserveOrgans(organCount);
    run.push.organCapacity = organs.capacity;
    ctx.submitAndWait([&](VkCommandBuffer cmd) { recordOrgans(cmd, run, place.groupsFor(organCount)); });
    needed = TurtleRoom{run.levels, organCount};
    neededMarks = run.marked;
    return organs;
}

GpuTurtle::Impl::Run GpuTurtle::Impl::begin(const stream::DeviceModules& m, const turtle::FieldOptions& options) {
    Run run(*m.symbols, *m.params, *m.plantStarts);
    run.out = &organs;
    run.placed = &placements;
    run.n = m.count;
    run.plants = m.plants;
    run.push = base;
    run.push.count = m.count;
    run.push.plants = m.plants;
    run.push.stride = m.stride;
    run.push.spacing = options.spacing;
    run.push.placed = !options.placements.empty() ? kFieldPlaced : options.scattered ? kFieldScattered : kFieldOnGrid;
    run.groups = setup.groupsFor(m.count);
    run.chunkGroups = setup.groupsFor((std::uint64_t(m.count) + kTurtleChunk - 1) / kTurtleChunk);
    // Chains of targets are at most n long; odd, so that the jumps end in the second buffer of each pair.
    run.rounds = jumpRounds(m.count);
    return run;
}

const DeviceOrgans& GpuTurtle::Impl::record(VkCommandBuffer cmd, const stream::DeviceModules& m,
                                            const turtle::FieldOptions& options, TurtleRoom room) {
    const std::uint32_t bound = std::max(m.count, 1u);
    if (pending.size() >= kRecordingsInFlight)
        throw std::logic_error("GpuTurtle::record: as many recordings in flight as it keeps (read one first)");
    // Buffers in use by a recording in flight must not be replaced by larger ones.
    if (!pending.empty() && (bound > reservedModules || m.plants > reservedPlants || room.levels >= levelCapacity ||
                             room.organs > organs.capacity))
        throw std::logic_error("GpuTurtle::record: more room than its buffers hold while recordings are in flight");
    checkRange(room.organs, sizeof(OrganInstance), "organ instances");
    reserveRecording(bound, m.plants, room.levels);
    reserveOrgans(room.organs);
    setPlacements(options, m.plants);
    const std::uint32_t slot = nextSlot;
    nextSlot = (nextSlot + 1) % kRecordingsInFlight;
    recordPasses(cmd, beginRecording(m, options, room, organs, placements), statusReadback[slot]);
    pending.push_back({slot, TurtleRoom{room.levels, organs.capacity, room.marks}});
    return organs;
}

void GpuTurtle::Impl::reserveRecording(std::uint32_t bound, std::uint32_t plants, std::uint32_t levelsResolved) {
    checkRange(bound, sizeof(TurtleStep), "steps");
    checkRange(std::uint64_t(bound) * kOrganKinds, 4, "organ flags");
    reserve(bound, plants);
    if (scan.capacity() < bound * kOrganKinds) scan.reserve(bound * kOrganKinds);
    reserveLevels(levelsResolved);
    if (!stepSizes) stepSizes = vk::ComputePipeline::embedded(ctx, "derive/step_sizes");
    if (!treeArguments)
        treeArguments = vk::Buffer(ctx, (shared::kStepBlocks + shared::kStepBlockWords) * 4,
                                   vk::MemoryUsage::DeviceLocal, VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
    (void)brackets.reserve(bound); // the turtle reads no partners: nothing to carry over
}

void GpuTurtle::Impl::reserveTargets(std::uint32_t modules, std::uint32_t plants, TurtleRoom room) {
    if (!pending.empty()) throw std::logic_error("GpuTurtle::reserveTargets: recordings in flight (read them first)");
    const std::uint32_t bound = std::max(modules, 1u);
    reserveRecording(bound, plants, room.levels);
    targetModules = bound;
    targetPlants = plants;
    targetRoom = room;
}

const DeviceOrgans& GpuTurtle::Impl::recordInto(VkCommandBuffer cmd, const stream::DeviceModules& m,
                                                const turtle::FieldOptions& options, TurtleRoom room,
                                                TurtleTarget& target) {
    if (std::max(m.count, 1u) > targetModules || m.plants > targetPlants || room.levels > targetRoom.levels)
        throw std::logic_error("GpuTurtle::recordInto: a string or room past what reserveTargets() made room for");
    checkRange(room.organs, sizeof(OrganInstance), "organ instances");
    sizeTarget(target, room.organs);
    DeviceOrgans& out = target.organs;
    if (!placedAlready(options, m.plants, out, target.placements)) recordPlacementsUpload(cmd, options, target);
    recordPasses(cmd, beginRecording(m, options, room, out, target.placements), target.status);
    target.room = TurtleRoom{room.levels, out.capacity, room.marks};
    return out;
}

void GpuTurtle::Impl::sizeTarget(TurtleTarget& target, std::uint64_t organCount) const {
    if (!target.status) target.status = vk::Buffer(ctx, kTurtleStatusWords * 4, vk::MemoryUsage::Readback);
    sizeOrgans(target.organs, organCount);
}

void GpuTurtle::Impl::recordKeep(VkCommandBuffer cmd, TurtleTarget& target) {
    sizeTarget(target, needed.organs);
    vk::memoryBarrier(cmd, Hazard::AnyToTransfer);
    const VkBufferCopy instances{0, 0, bytes(needed.organs, sizeof(OrganInstance))};
    if (needed.organs > 0)
        vkCmdCopyBuffer(cmd, organs.instances.handle(), target.organs.instances.handle(), 1, &instances);
    const VkBufferCopy table{0, 0, sizeof(OrganTable)}, spacing{0, 0, 4};
    vkCmdCopyBuffer(cmd, organs.table.handle(), target.organs.table.handle(), 1, &table);
    vkCmdCopyBuffer(cmd, organs.field.handle(), target.organs.field.handle(), 1, &spacing);
    vk::memoryBarrier(cmd, Hazard::TransferToAny);
    target.organs.placements = organs.placements;
    target.organs.scattered = organs.scattered;
    target.room = TurtleRoom{needed.levels, target.organs.capacity, neededMarks};
}

GpuTurtle::Impl::Run GpuTurtle::Impl::beginRecording(const stream::DeviceModules& m,
                                                     const turtle::FieldOptions& options, TurtleRoom room,
                                                     DeviceOrgans& out, const vk::Buffer& placed) {
    stream::DeviceModules bounded = m;
    bounded.count = std::max(m.count, 1u);
    Run run = begin(bounded, options);
    run.out = &out;
    run.placed = &placed;
    run.countedOnDevice = true;
    run.marked = room.marks;
    run.levels = room.levels;
    run.push.items = room.levels;
    run.push.organCapacity = out.capacity;
    levels = 0;
    bytesMoved = 0;
    return run;
}

void GpuTurtle::Impl::recordPasses(VkCommandBuffer cmd, const Run& run, const vk::Buffer& statusCopy) {
    // The stream, and this turtle's buffers, may be in use by what was recorded before.
    vk::memoryBarrier(cmd, Hazard::AnyToAny);
    recordSetup(cmd, run);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    recordComposition(cmd, run);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    recordStates(cmd, run);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    recordOrgans(cmd, run, place.groupsFor(run.out->capacity));
    vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
    VkBufferCopy words{0, 0, kTurtleStatusMarks * 4}, marks{0, kTurtleStatusMarks * 4, 4};
    vkCmdCopyBuffer(cmd, status.handle(), statusCopy.handle(), 1, &words);
    vkCmdCopyBuffer(cmd, present.handle(), statusCopy.handle(), 1, &marks);
    vk::memoryBarrier(cmd, Hazard::TransferToHost);
}

void GpuTurtle::Impl::dispatchPass(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline,
                                   std::initializer_list<vk::BufferRange> buffers, const TurtlePush& push,
                                   const Run& run, std::uint32_t gate, Over over) const {
    std::span<const vk::BufferRange> bound(buffers.begin(), buffers.size());
    std::span<const std::byte> bytes = std::as_bytes(std::span(&push, 1));
    if (run.countedOnDevice) {
        VkDeviceSize offset = 4ull * (gate * kGateWords + (over == Over::Chunks ? 0 : 3));
        pipeline.dispatchIndirectBytes(cmd, bound, bytes, passArguments, offset);
    } else {
        pipeline.dispatchBytes(cmd, bound, bytes, over == Over::Chunks ? run.chunkGroups : run.groups);
    }
}

void GpuTurtle::Impl::startList(VkCommandBuffer cmd) const {
    vkCmdFillBuffer(cmd, scratch.lists[0].handle(), 4 * kJumpListCount, 4, 0);
}

void GpuTurtle::Impl::dispatchRound(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline,
                                    std::initializer_list<vk::BufferRange> buffers, std::span<const std::byte> push,
                                    const Run& run, std::uint32_t r) const {
    const vk::Buffer& walked = scratch.lists[r % 2];
    listGroups.dispatch(cmd, {walked, scratch.lists[1 - r % 2]}, run.push, 1);
    vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
    pipeline.dispatchIndirectBytes(cmd, std::span<const vk::BufferRange>(buffers.begin(), buffers.size()), push,
                                   walked, 0);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
}

void GpuTurtle::Impl::recordSearch(VkCommandBuffer cmd, const Run& run, std::uint32_t gate, std::uint32_t hit,
                                   std::uint32_t stop, const vk::Buffer& result) {
    const Scratch& b = scratch;
    TurtlePush p = run.push;
    p.hitMask = hit;
    p.stopMask = stop;
    vk::memoryBarrier(cmd, Hazard::ComputeToTransfer);
    vkCmdFillBuffer(cmd, b.searchTargets.handle(), 0, VK_WHOLE_SIZE, 0);
    startList(cmd);
    vk::memoryBarrier(cmd, Hazard::TransferToCompute);
    dispatchPass(cmd, chunkSearch, {b.marks, b.parents, b.searchChunk, b.searchTargets, status, b.lists[0]}, p, run,
                 gate, Over::Chunks);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    for (std::uint32_t r = 0; r < run.rounds; ++r) {
        TurtlePush round = p;
        round.first = r;
        const vk::Buffer& in = r == 0 ? b.searchChunk : b.searchJumps[r % 2 == 1 ? 0 : 1];
        dispatchRound(cmd, jumpSearch,
                      {b.marks, in, b.searchJumps[r % 2 == 1 ? 1 : 0], b.lists[r % 2], b.lists[1 - r % 2]},
                      std::as_bytes(std::span(&round, 1)), run, r);
    }
    dispatchPass(cmd, searchFinish, {b.marks, b.searchChunk, b.searchJumps[0], result, status}, p, run, gate,
                 Over::Modules);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
}

void GpuTurtle::Impl::recordSetup(VkCommandBuffer cmd, const Run& run) {
    const Scratch& b = scratch;
    vkCmdFillBuffer(cmd, present.handle(), 0, VK_WHOLE_SIZE, 0);
    vkCmdFillBuffer(cmd, b.triangleFirst.handle(), 0, VK_WHOLE_SIZE, kNoModule);
    vkCmdFillBuffer(cmd, b.stepTargets.handle(), 0, VK_WHOLE_SIZE, 0);
    startList(cmd);
    vkCmdFillBuffer(cmd, b.counts.handle(), 0, VK_WHOLE_SIZE, 0);
    VkDeviceSize half = std::uint64_t(run.plants) * 16;
    if (run.plants > 0) {
        vkCmdFillBuffer(cmd, plantBounds.handle(), 0, half, 0x7FFFFFFFu);
        vkCmdFillBuffer(cmd, plantBounds.handle(), half, half, 0x80000000u);
    }
    // The count is the plant table's last entry, whoever wrote the table.
    vkCmdFillBuffer(cmd, status.handle(), 4, (kTurtleStatusWords - 1) * 4, 0);
    VkBufferCopy count{std::uint64_t(run.plants) * 4, kTurtleStatusModules * 4, 4};
    vkCmdCopyBuffer(cmd, run.starts.handle(), status.handle(), 1, &count);
    if (run.countedOnDevice) vkCmdFillBuffer(cmd, treeArguments.handle(), 0, VK_WHOLE_SIZE, 0);
    vk::memoryBarrier(cmd, Hazard::TransferToCompute);
    if (run.countedOnDevice) {
        // The bracket tree's levels and workgroups as a recorded derivation step sizes its own tree.
        shared::StepSizesPush sizes{};
        sizes.mode = shared::kSizeStep;
        sizes.plants = run.plants;
        sizes.tileSize = shared::kScanTileSize;
        sizes.capacity = run.n;
        sizes.budget = ~0u;
        sizes.maxGroupsX = run.push.maxGroupsX;
        sizes.brackets = 1;
        sizes.inputBound = run.n;
        stepSizes->dispatch(cmd, {run.starts, scan.totalBuffer(), treeArguments, brackets.levelInfo()}, sizes, 1);
        vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
        brackets.recordCountedOnDevice(cmd, run.symbols, run.n, treeArguments, shared::kStepBlocks * 4);
    } else {
        brackets.record(cmd, run.symbols, run.n);
    }
    setup.dispatch(cmd,
                   {run.symbols, run.params, run.starts, commandTable, speciesTable, brackets.tree(),
                    brackets.levelInfo(), b.commands, b.parents, b.steps[0], b.pointers[0], b.marks, b.plantOf,
                    present, status},
                   run.push, run.groups);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    if (run.countedOnDevice) {
        passSizes.dispatch(cmd, {status, present, passArguments}, run.push, 1);
        vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
    }
    dispatchPass(cmd, polygons, {b.commands, b.plantOf, b.marks, b.triangleFirst, b.trianglePrevious, status},
                 run.push, run, kGateModules, Over::Modules);
    vk::memoryBarrier(cmd, Hazard::ComputeToHost);
}

void GpuTurtle::Impl::recordComposition(VkCommandBuffer cmd, const Run& run) {
    const Scratch& b = scratch;
    dispatchPass(cmd, chunkSteps,
                 {b.marks, b.parents, b.steps[0], b.pointers[0], b.stepTargets, status, b.lists[0]}, run.push, run,
                 kGateModules, Over::Chunks);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    // The targets' entries alternate between the buffers; the other modules' stay in the first (chunks).
    for (std::uint32_t r = 0; r < run.rounds; ++r) {
        std::uint32_t from = r % 2, to = 1 - from;
        dispatchRound(cmd, jumpSteps,
                      {b.marks, b.steps[from], b.pointers[from], b.steps[to], b.pointers[to], b.lists[from],
                       b.lists[to]},
                      {}, run, r);
    }
    if (run.marked & kMarkStem) recordSearch(cmd, run, kGateStems, kMarkStem, kMarkStemBreak, b.stemBelow);
    if ((run.marked & kMarkStem) && tapers)
        recordSearch(cmd, run, kGateStems, kMarkStem, kMarkStemBreak | kMarkBranchClose, b.taperBelow);
    if (run.marked & (kMarkCylinderStart | kMarkCylinderPoint)) {
        recordSearch(cmd, run, kGateCylinders, kMarkCylinderStart | kMarkCylinderPoint, 0, b.cylinderAnchors);
        recordSearch(cmd, run, kGateCylinders, kMarkCylinderStart, 0, b.cylinderStarts);
        // The settings the control points were made with, where some species draws along cpfg's curves.
        if (cylinderCurves) {
            recordSearch(cmd, run, kGateCylinders, kMarkContour, 0, b.contourSetters);
            recordSearch(cmd, run, kGateCylinders, kMarkCylinderTangents, 0, b.tangentSetters);
            recordSearch(cmd, run, kGateCylinders, kMarkRadiusScale, 0, b.radiusScaleSetters);
            recordSearch(cmd, run, kGateCylinders, kMarkRadiusTangents, 0, b.radiusTangentSetters);
        }
    }
    if (run.marked & kMarkNonlinear) {
        // Round 0 walks the modules and lists the non-linear ones; the later rounds walk the lists.
        for (std::uint32_t r = 0; r < run.rounds; ++r) {
            TurtlePush p = run.push;
            p.first = r;
            const std::initializer_list<vk::BufferRange> buffers = {
                run.symbols, run.params, run.starts, commandTable, speciesTable, b.marks, b.parents, b.stepTargets,
                b.steps[0], b.pointers[0], b.steps[1], b.pointers[1], b.plantOf, b.states, b.levels[(r + 1) % 2],
                b.levels[r % 2], status, b.lists[r % 2], b.lists[1 - r % 2]};
            if (r == 0) {
                listGroups.dispatch(cmd, {b.lists[0], b.lists[1]}, run.push, 1); // empties the list round 0 fills
                vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
                dispatchPass(cmd, jumpLevels, buffers, p, run, kGateNonlinear, Over::Modules);
                vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
            } else {
                dispatchRound(cmd, jumpLevels, buffers, std::as_bytes(std::span(&p, 1)), run, r);
            }
        }
        dispatchPass(cmd, levelCount, {b.marks, b.levels[0], b.counts, status}, run.push, run, kGateNonlinear,
                     Over::Modules);
    }
    vk::memoryBarrier(cmd, Hazard::ComputeToHost);
}

void GpuTurtle::Impl::reserveLevels(std::uint32_t count) {
    if (levelCapacity >= std::uint64_t(count) + 1 && cursors) return;
    levelCapacity = std::max<std::uint64_t>(std::uint64_t(count) + 1, 64);
    cursors = deviceBuffer(levelCapacity, 4);
    levelArguments = vk::Buffer(ctx, bytes(3 * levelCapacity, 4), vk::MemoryUsage::DeviceLocal,
                                VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
}

void GpuTurtle::Impl::recordStates(VkCommandBuffer cmd, const Run& run) {
    const Scratch& b = scratch;
    if (run.levels > 0 || run.countedOnDevice) { // a recording learns the deepest level from the layout
        TurtlePush p = run.push;
        levelLayout.dispatch(cmd, {b.counts, cursors, levelArguments, status}, p, 1);
        vk::memoryBarrier(cmd, Hazard::ComputeToIndirect);
        dispatchPass(cmd, levelScatter, {b.marks, b.levels[0], cursors, b.order, status}, p, run, kGateNonlinear,
                     Over::Modules);
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        for (std::uint32_t level = 1; level <= run.levels; ++level) {
            p.first = level;
            resolveLevel.dispatchIndirect(cmd,
                                          {run.symbols, run.params, run.starts, commandTable, speciesTable, b.marks,
                                           b.parents, b.stepTargets, b.steps[0], b.pointers[0], b.steps[1],
                                           b.pointers[1], b.plantOf, b.states, b.commands, b.order, b.counts,
                                           cursors},
                                          p, levelArguments, 12ull * (level - 1));
            vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        }
    }
    dispatchPass(cmd, states,
                 {run.symbols, run.params, run.starts, commandTable, speciesTable, b.marks, b.stepTargets, b.steps[0],
                  b.pointers[0], b.steps[1], b.pointers[1], b.plantOf, b.states, status},
                 run.push, run, kGateModules, Over::Modules);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    // Over the whole bound: the flags past the count are zeroed for the scan.
    classify.dispatch(cmd,
                      {run.symbols, run.params, run.starts, commandTable, speciesTable, b.commands, b.marks,
                       b.triangleFirst, b.cylinderAnchors, b.cylinderStarts, b.states, b.kinds, b.flags, status},
                      run.push, run.groups);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    if (run.marked & kMarkCylinderStart) recordSearch(cmd, run, kGateTubes, kMarkTube, kMarkTubeBreak, b.tubeBelow);
    scan.record(cmd, b.flags, b.offsets, run.n * kOrganKinds);
    vk::memoryBarrier(cmd, Hazard::ComputeToHost);
}

void GpuTurtle::Impl::recordOrgans(VkCommandBuffer cmd, const Run& run, std::uint64_t organGroups) {
    const Scratch& b = scratch;
    dispatchPass(cmd, emit,
                 {run.symbols, run.params, run.starts, commandTable, speciesTable, b.commands, b.parents, b.plantOf,
                  b.states, b.kinds, b.offsets, b.triangleFirst, b.trianglePrevious, b.cylinderAnchors, palettes,
                  surfaceScales, surfaceShapes, run.out->instances, b.slots, plantBounds, b.lastSlots, status, b.marks,
                  contourRings, b.contourSetters, b.tangentSetters, b.radiusScaleSetters, b.radiusTangentSetters},
                 run.push, run, kGateModules, Over::Modules);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    dispatchPass(cmd, links,
                 {b.commands, b.marks, b.kinds, b.slots, b.stemBelow, b.tubeBelow, run.out->instances, b.lastSlots,
                  status},
                 run.push, run, kGateModules, Over::Modules);
    if ((run.marked & kMarkStem) && tapers) {
        vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
        dispatchPass(cmd, taper,
                     {run.starts, speciesTable, b.commands, b.marks, b.kinds, b.plantOf, b.states, b.slots,
                      b.taperBelow, run.out->instances, plantBounds, status},
                     run.push, run, kGateStems, Over::Modules);
    }
    // The field's pass writes the status words the passes before it read, and reads the bounds the taper wrote.
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    TurtlePush fieldPush = run.push;
    fieldPush.hitMask = kSearchedMarks & ~run.marked; // the searches the room left out
    field.dispatch(cmd, {b.offsets, scan.totalBuffer(), plantBounds, run.out->table, run.out->field, status, present},
                   fieldPush, 1);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
    place.dispatch(cmd, {scan.totalBuffer(), run.out->field, run.out->instances, run.out->table, *run.placed}, run.push,
                   organGroups);
    vk::memoryBarrier(cmd, Hazard::ComputeToCompute);
}

void GpuTurtle::Impl::setPlacements(const turtle::FieldOptions& options, std::uint32_t plants) {
    if (placedAlready(options, plants, organs, placements)) return;
    if (!pending.empty()) throw std::logic_error("GpuTurtle: the placements changed while recordings are in flight");
    uploadPlacements(options, organs, placements);
}

bool GpuTurtle::Impl::placedAlready(const turtle::FieldOptions& options, std::uint32_t plants, DeviceOrgans& out,
                                    const vk::Buffer& buffer) {
    if (!options.placements.empty() && options.placements.size() != plants)
        throw std::invalid_argument("GpuTurtle: one placement per plant");
    out.scattered = options.placements.empty() && options.scattered;
    return buffer && options.placements == out.placements;
}

std::span<const PlantPlacement> GpuTurtle::Impl::placementsToUpload(const turtle::FieldOptions& options) {
    static const PlantPlacement none{}; // a buffer to bind where the plants stand on the grid
    return options.placements.empty() ? std::span(&none, 1) : std::span(options.placements);
}

void GpuTurtle::Impl::uploadPlacements(const turtle::FieldOptions& options, DeviceOrgans& out,
                                       vk::Buffer& buffer) const {
    buffer = vk::deviceBufferWith(ctx, placementsToUpload(options));
    out.placements = options.placements;
}

void GpuTurtle::Impl::recordPlacementsUpload(VkCommandBuffer cmd, const turtle::FieldOptions& options,
                                             TurtleTarget& target) const {
    const std::span<const PlantPlacement> placed = placementsToUpload(options);
    const VkDeviceSize size = placed.size_bytes();
    if (!target.placementsStaging || target.placementsStaging.size() < size) {
        target.placementsStaging = vk::Buffer(ctx, size, vk::MemoryUsage::Upload);
        target.placements = vk::Buffer(ctx, size, vk::MemoryUsage::DeviceLocal);
    }
    std::memcpy(target.placementsStaging.mapped(), placed.data(), size);
    vk::memoryBarrier(cmd, Hazard::AnyToTransfer);
    const VkBufferCopy copy{0, 0, size};
    vkCmdCopyBuffer(cmd, target.placementsStaging.handle(), target.placements.handle(), 1, &copy);
    vk::memoryBarrier(cmd, Hazard::TransferToCompute);
    target.organs.placements = options.placements;
}

void GpuTurtle::Impl::reserve(std::uint64_t n, std::uint64_t plants) {
    reservedModules = std::max(reservedModules, n);
    reservedPlants = std::max(reservedPlants, plants);
    if (plants * 8 > plantCapacity || !plantBounds) {
        plantCapacity = std::max<std::uint64_t>(plants * 8 + plants * 4, 64);
        plantBounds = deviceBuffer(plantCapacity, 4);
    }
    if (!present) present = vk::Buffer(ctx, 4, vk::MemoryUsage::Readback);
    if (n <= scratch.modules) return;
    // Half again as much, within what the device binds for the largest per-module array (the steps).
    std::uint64_t largest = std::max<std::uint64_t>({sizeof(TurtleStep), sizeof(TurtleState), 4ull * kOrganKinds});
    std::uint64_t capacity = std::min<std::uint64_t>(std::max<std::uint64_t>(n + n / 2, 1024),
                                                     ctx.limits().maxStorageBufferRange / largest);
    capacity = std::max(capacity, n);
    scratch = Scratch();
    Scratch& b = scratch;
    for (vk::Buffer* one : {&b.commands, &b.parents, &b.plantOf, &b.marks, &b.kinds, &b.slots, &b.lastSlots,
                            &b.pointers[0], &b.pointers[1], &b.triangleFirst, &b.trianglePrevious, &b.stemBelow,
                            &b.taperBelow, &b.tubeBelow, &b.cylinderAnchors, &b.cylinderStarts, &b.stepTargets,
                            &b.searchTargets,
                            &b.searchChunk, &b.searchJumps[0], &b.searchJumps[1], &b.order})
        *one = deviceBuffer(capacity, 4);
    // Only read where a species draws its cylinders along cpfg's curves.
    for (vk::Buffer* one : {&b.contourSetters, &b.tangentSetters, &b.radiusScaleSetters, &b.radiusTangentSetters})
        *one = deviceBuffer(cylinderCurves ? capacity : 1, 4);
    b.steps[0] = deviceBuffer(capacity, sizeof(TurtleStep));
    b.steps[1] = deviceBuffer(capacity, sizeof(TurtleStep));
    b.states = deviceBuffer(capacity, sizeof(TurtleState));
    b.levels[0] = deviceBuffer(capacity, 8);
    b.levels[1] = deviceBuffer(capacity, 8);
    b.counts = deviceBuffer(capacity + 1, 4);
    for (vk::Buffer& list : b.lists)
        list = vk::Buffer(ctx, (kJumpListHeader + capacity) * 4, vk::MemoryUsage::DeviceLocal,
                          VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT);
    b.flags = deviceBuffer(capacity * kOrganKinds, 4);
    b.offsets = deviceBuffer(capacity * kOrganKinds, 4);
    b.modules = capacity;
}

void GpuTurtle::Impl::sizeOrgans(DeviceOrgans& out, std::uint64_t count) const {
    if (!out.table) out.table = vk::Buffer(ctx, sizeof(OrganTable), vk::MemoryUsage::DeviceLocal);
    if (!out.field) out.field = vk::Buffer(ctx, 4, vk::MemoryUsage::DeviceLocal);
    if (out.instances && count <= out.capacity) return;
    std::uint64_t limit = ctx.limits().maxStorageBufferRange / sizeof(OrganInstance);
    std::uint64_t capacity = std::max<std::uint64_t>(std::min<std::uint64_t>(count + count / 2, limit), count);
    capacity = std::max<std::uint64_t>(capacity, 64);
    out.instances = vk::Buffer(ctx, bytes(capacity, sizeof(OrganInstance)), vk::MemoryUsage::DeviceLocal);
    out.capacity = static_cast<std::uint32_t>(capacity);
}

GpuTurtle::GpuTurtle(const vk::Context& context, const turtle::TurtleCommands& commands,
                     const std::vector<turtle::TurtleSettings>& species)
    : impl_(std::make_unique<Impl>(context, commands, species)) {}

GpuTurtle::~GpuTurtle() = default;

GpuTurtle::ModuleStates GpuTurtle::lastModuleStates() const {
    const Impl& m = *impl_;
    return {&m.scratch.states, &m.scratch.commands, &m.scratch.plantOf,
            m.organs.placements.empty() ? nullptr : &m.placements};
}

const DeviceOrgans& GpuTurtle::interpret(const stream::DeviceModules& modules, const turtle::FieldOptions& field) {
    return impl_->interpret(modules, field);
}

const DeviceOrgans& GpuTurtle::record(VkCommandBuffer cmd, const stream::DeviceModules& modules,
                                      const turtle::FieldOptions& field, TurtleRoom room) {
    return impl_->record(cmd, modules, field, room);
}

TurtleRoom GpuTurtle::lastRoom() const { return impl_->needed; }

std::uint32_t GpuTurtle::lastMarks() const { return impl_->neededMarks; }

void GpuTurtle::reserveTargets(std::uint32_t modules, std::uint32_t plants, TurtleRoom room) {
    impl_->reserveTargets(modules, plants, room);
}

const DeviceOrgans& GpuTurtle::recordInto(VkCommandBuffer cmd, const stream::DeviceModules& modules,
                                          const turtle::FieldOptions& field, TurtleRoom room, TurtleTarget& target) {
    return impl_->recordInto(cmd, modules, field, room, target);
}

void GpuTurtle::recordKeep(VkCommandBuffer cmd, TurtleTarget& target) { impl_->recordKeep(cmd, target); }

namespace {

// What a recording's status words, copied for the host, say it found in the room it had: a string with marks whose
// passes the room left out did not fit it either.
RecordedInterpretation recordedStatus(const vk::Buffer& copied, TurtleRoom room) {
    const auto* words = reinterpret_cast<const std::uint32_t*>(copied.mapped());
    RecordedInterpretation r{words[kTurtleStatusModules], words[kTurtleStatusLevels], words[kTurtleStatusOrgans], false,
                             words[kTurtleStatusMarks]};
    r.fit = r.levels <= room.levels && r.organs <= room.organs && (r.marks & kSearchedMarks & ~room.marks) == 0;
    return r;
}

} // namespace

RecordedInterpretation GpuTurtle::recordedInto(const TurtleTarget& target) {
    if (!target.status) throw std::logic_error("GpuTurtle::recordedInto: nothing recorded into the target");
    return recordedStatus(target.status, target.room);
}

RecordedInterpretation GpuTurtle::recorded() {
    Impl& m = *impl_;
    if (m.pending.empty()) throw std::logic_error("GpuTurtle::recorded: no recording in flight");
    const Impl::Pending oldest = m.pending.front();
    m.pending.pop_front();
    return recordedStatus(m.statusReadback[oldest.slot], oldest.room);
}

std::uint32_t GpuTurtle::lastLevels() const { return impl_->levels; }

std::uint64_t GpuTurtle::lastBytesMoved() const { return impl_->bytesMoved; }

DeviceOrgans uploadOrgans(const vk::Context& context, const turtle::Interpretation& interpretation) {
    OrganTable table{};
    for (std::uint32_t k = 0; k < kOrganKinds; ++k) {
        table.count[k] = interpretation.count[k];
        table.first[k] = interpretation.first[k];
    }
    draw::encodeBounds(draw::Bounds{interpretation.bounds.min, interpretation.bounds.max}, table);
    float spacing = interpretation.spacing;
    DeviceOrgans organs;
    organs.capacity = static_cast<std::uint32_t>(interpretation.organs.size());
    organs.instances = vk::deviceBufferWith(context, std::span<const OrganInstance>(interpretation.organs));
    organs.table = vk::deviceBufferWith(context, std::span<const OrganTable>(&table, 1));
    organs.field = vk::deviceBufferWith(context, std::span<const float>(&spacing, 1));
    organs.scattered = interpretation.scattered;
    return organs;
}

turtle::Interpretation readBack(const vk::Context& context, const DeviceOrgans& organs, std::uint32_t plants) {
    OrganTable table = vk::downloadVector<OrganTable>(context, organs.table, 1)[0];
    float spacing = vk::downloadVector<float>(context, organs.field, 1)[0];
    turtle::Interpretation result;
    std::uint32_t total = 0;
    for (std::uint32_t k = 0; k < kOrganKinds; ++k) {
        result.count[k] = table.count[k];
        result.first[k] = table.first[k];
        total += table.count[k];
    }
    result.organs = vk::downloadVector<OrganInstance>(context, organs.instances, total);
    if (total > 0) {
        draw::Bounds b = draw::decodeBounds(table);
        result.bounds.add(b.min);
        result.bounds.add(b.max);
    }
    result.spacing = spacing;
    for (std::uint32_t p = 0; p < plants; ++p)
        result.plantOrigins.push_back(
            p < organs.placements.size() ? turtle::plantOrigin(organs.placements[p])
            : organs.scattered           ? turtle::plantOrigin(turtle::scatteredPlacement(p, plants, spacing))
                                         : turtle::fieldCell(p, plants) * spacing);
    result.scattered = organs.scattered;
    return result;
}

} // namespace simeco::turtle
