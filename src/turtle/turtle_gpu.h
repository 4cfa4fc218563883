// The turtle on the device: organ instances and their table (compute/shared/organ_layout.h) written by compute
// passes over the module stream, the same organs, in the same order, as the CPU reference turtle
// (turtle/turtle_cpu.h). The kernels are in compute/turtle; the method is described in
// compute/shared/turtle_state_layout.h. interpret() reads back only which marks occur (to skip searches nothing
// needs), the levels of non-linear commands, and the number of organs (to size their buffer); record() and
// recordInto() read nothing and work within the room they are given.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include <vulkan/vulkan.h>

#include "stream/device_modules.h"
#include "stream/module_string.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_settings.h"
#include "vk/buffer.h"

namespace simeco::vk {
class Context;
}

namespace simeco::turtle {

// A host string copied to the device in that layout.
class UploadedModules {
public:
    UploadedModules(const vk::Context& context, const stream::ModuleString& string);
    stream::DeviceModules view() const;

private:
    vk::Buffer symbols_, params_, plantStarts_;
    std::uint32_t count_ = 0, plants_ = 0, stride_ = 1;
};

// What the turtle leaves on the device: the instances, and the table that says how many of each kind were
// written, where they start and their bounds.
struct DeviceOrgans {
    vk::Buffer instances;
    vk::Buffer table;
    vk::Buffer field; // one float: the spacing of the plants' grid
    std::uint32_t capacity = 0; // instances the buffer holds
    std::vector<shared::PlantPlacement> placements; // where the plants stand, when not on the grid
    bool scattered = false;                         // without placements: scattered about the grid
};

// The room a recording that reads nothing back interprets a string in: levels of non-linear modules
// resolved one after another, and organ instances written; and the marks that occur in the string (the searches
// that none needs are left out), every one where they are not known. A string with more of them does not fit.
struct TurtleRoom {
    std::uint32_t levels = 0;
    std::uint32_t organs = 0;
    std::uint32_t marks = ~0u;
};

// What a recording found on the device: the string's modules, its levels and organs, whether they fit the room it
// was given, and its marks.
struct RecordedInterpretation {
    std::uint32_t modules = 0;
    std::uint32_t levels = 0;
    std::uint32_t organs = 0;
    bool fit = false;
    // The marks that occur in the string (TurtleRoom::marks): for recording the same string again with no more
    // searches than it needs.
    std::uint32_t marks = 0;
};

// Buffers of the caller's that a recording leaves its organs and its status words in (GpuTurtle::recordInto): each
// batch of a field its own, so that the batches' recordings follow one another in one submission and their organs
// stay until the caller has merged them. The turtle makes and grows them.
struct TurtleTarget {
    DeviceOrgans organs;
    vk::Buffer placements;        // organs.placements on the device, uploaded when they change
    vk::Buffer placementsStaging; // ... on their way there, in the submission of the recording that needs them
    vk::Buffer status;     // the recording's status words, for the host
    TurtleRoom room;       // what the last recording into it had room for
};

// Recordings a turtle keeps in flight at once (ticks submitted and not yet read back), as the renderer keeps
// frames (draw::kFramesInFlight).
inline constexpr std::uint32_t kRecordingsInFlight = 2;

class GpuTurtle {
public:
    // `species[p % species.size()]` interprets plant p; all share the alphabet `commands` was built from.
    GpuTurtle(const vk::Context& context, const turtle::TurtleCommands& commands,
              const std::vector<turtle::TurtleSettings>& species);
    ~GpuTurtle();
    GpuTurtle(const GpuTurtle&) = delete;
    GpuTurtle& operator=(const GpuTurtle&) = delete;

    // Interprets every plant of `modules` and places the plants in the field. Throws ir::LimitError when the
    // stream needs larger buffers than the device binds. The organs stay the turtle's, valid until its next
    // interpretation: their buffers, like the passes' own, are allocated once and grown.
    const DeviceOrgans& interpret(const stream::DeviceModules& modules, const turtle::FieldOptions& field);

    // Records interpreting `modules` into `cmd`, reading nothing back: the count is the plant table's last entry
    // on the device, so the string may be one a derivation recorded before in `cmd` writes (`modules.count` then
    // only bounds it). What interpret() reads between its passes stays on the device: the passes are sized
    // there (compute/turtle/pass_sizes.comp), `room` bounds the levels resolved and the organs written, and
    // recorded() tells, after the submission, whether the string fit (else interpret() it, or record again with more
    // room: its table counts no organs where they or its levels outgrew the room, and the organs of a string with
    // marks the room left out are not its own). Starts with a barrier after everything recorded before; the caller
    // submits.
    const DeviceOrgans& record(VkCommandBuffer cmd, const stream::DeviceModules& modules,
                               const turtle::FieldOptions& field, TurtleRoom room);
    // Makes the turtle's own buffers large enough for strings of up to `modules` modules of up to `plants` plants
    // recorded within `room`, for recordInto(), which grows none of them: one submission may then hold several
    // recordings, which share the turtle's passes' arrays one after another. Refused while recordings are in flight.
    void reserveTargets(std::uint32_t modules, std::uint32_t plants, TurtleRoom room);
    // As record(), leaving the organs and the status words in `target` (its instances grown to `room.organs` and
    // half again) rather than the turtle's, and outside the recordings that recorded() reads: recordedInto() tells,
    // after the submission, whether the string fit. The string and room must be within reserveTargets()'.
    const DeviceOrgans& recordInto(VkCommandBuffer cmd, const stream::DeviceModules& modules,
                                   const turtle::FieldOptions& field, TurtleRoom room, TurtleTarget& target);
    static RecordedInterpretation recordedInto(const TurtleTarget& target);
    // Records a copy of the last interpret()'s organs into `target` (grown to hold them), where they stay past the
    // turtle's next interpretation.
    void recordKeep(VkCommandBuffer cmd, TurtleTarget& target);
    // What the last interpret() needed: room to record the same string again, or another as large (every mark).
    TurtleRoom lastRoom() const;
    // The marks that occur in the string the last interpret() read (TurtleRoom::marks): for recording that string
    // again, as another string may have others.
    std::uint32_t lastMarks() const;
    // What the oldest recording not yet read found, once its submission has completed. Up to
    // kRecordingsInFlight recordings may be in flight (record() refuses more, or one that needs larger buffers
    // than those in flight use, and interpret() refuses while any is); each is read once, oldest first.
    RecordedInterpretation recorded();

    // The last interpretation's per-module arrays, valid until the next: each module's state after it (in its
    // plant's own frame), its command and its plant, and the plants' placements (FieldOptions::placements; unset
    // without them).
    struct ModuleStates {
        const vk::Buffer* states = nullptr;
        const vk::Buffer* commands = nullptr;
        const vk::Buffer* plants = nullptr;
        const vk::Buffer* placements = nullptr;
    };
    ModuleStates lastModuleStates() const;

    // Levels of non-linear commands the last interpretation resolved one after another.
    std::uint32_t lastLevels() const;
    // Bytes the last interpretation's passes read and wrote in their per-module and per-organ arrays, as the
    // host counts them (for the benchmark's comparison with the copy bandwidth).
    std::uint64_t lastBytesMoved() const;

private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

// The CPU turtle's organs on the device in the layout the turtle kernels leave.
DeviceOrgans uploadOrgans(const vk::Context& context, const turtle::Interpretation& interpretation);

// The instances and table read back, in the CPU turtle's form (for tests and tools).
turtle::Interpretation readBack(const vk::Context& context, const DeviceOrgans& organs, std::uint32_t plants);

} // namespace simeco::turtle
