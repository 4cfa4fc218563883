// The field pipeline every client drives: load any input (.l, .lsys, .eco) into its species, derive the field
// (strings under their homomorphisms), and interpret it with the turtle, on the device or on the CPU.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "draw/bounds.h"
#include "field/backend.h"
#include "gpu/derive_gpu.h"
#include "ir/grammar.h"
#include "ir/draw_assets.h"
#include "stream/derive_options.h"
#include "stream/module_string.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_gpu.h"
#include "turtle/turtle_settings.h"
#include "vk/buffer.h"

namespace simeco::vk {
class Context;
}
namespace simeco::turtle {
class OrganMerge;
}

namespace simeco::field {

struct FieldSource {
    std::string file;
    int steps = -1;
    int64_t seed = -1;
    uint32_t plants = 0;
    float spacing = 0;
    Backend backend = Backend::Gpu;
    uint64_t maxModules = 0;
    double maxSeconds = stream::kDefaultMaxSeconds;
    std::string device;
    std::string colormap; // a cpfg colour map (.map) in place of the grammars' own; empty: theirs

    bool onDevice() const { return backend == Backend::Gpu; }
};

// The species of any input file, sharing one alphabet (ir::unifySpecies); a scene's warnings go to stderr. With
// `assets`, a scene's models and textures are read into it for the renderer.
std::vector<ir::Grammar> loadSpecies(const std::string& path, ir::DrawAssets* assets = nullptr);

// A batch of a field's plants copied out of its derived string (field_parts.h).
struct FieldBatchBuffers {
    vk::Buffer symbols, params, plantStarts;
};

// A field derived and ready for the turtle.
struct Field {
    std::vector<ir::Grammar> species; // one alphabet (ir::unifySpecies)
    ir::DrawAssets assets;            // the models and textures a scene's stages draw with (draw::Renderer's)
    // Every plant, under its homomorphism: with the GPU backend left on the device by `deriver` (then `string`
    // stays empty), else on the host.
    stream::ModuleString string;
    std::unique_ptr<gpu::GpuDeriver> deriver;
    uint64_t modules = 0;
    uint32_t plants = 0;
    turtle::TurtleCommands commands;
    std::vector<turtle::TurtleSettings> turtles;
    turtle::FieldOptions options;
    // The turtle kernels, made on the first interpretation on the device and kept with their buffers; the
    // organs the last interpretation left on the device (the turtle's, or the CPU turtle's uploaded).
    std::unique_ptr<turtle::GpuTurtle> turtle;
    turtle::DeviceOrgans uploaded;
    // A field interpreted in batches (field_parts.h): the batch interpreted last, and the organs merged.
    FieldBatchBuffers batch;
    std::unique_ptr<turtle::OrganMerge> merge;

    Field();
    ~Field();
    Field(Field&&) noexcept;
    Field& operator=(Field&&) noexcept;
};

// Loads and derives the source's file; `context` is used by the GPU backend (may be null for the CPU one).
Field deriveField(const FieldSource& source, const vk::Context* context);

// The field's organs on the device: written by the turtle kernels, or with the CPU backend by the reference
// turtle and uploaded. They are the field's, valid until its next interpretation.
const turtle::DeviceOrgans& interpretOnDevice(const FieldSource& source, Field& field, const vk::Context& context);

// The field's organs on the host: the turtle kernels' read back, or the reference turtle's. Refuses organs whose
// values are not all finite numbers (turtle/finite_organs.h), naming the plant and module.
turtle::Interpretation interpretOnHost(const FieldSource& source, Field& field, const vk::Context* context);

// How many organs the device's organ table counts, and their bounds, read back for framing: the instances stay on
// the device. Refuses organs whose values are not all finite numbers, which make the bounds infinite.
struct OrganExtent {
    uint32_t organs = 0;
    draw::Bounds bounds;
};
OrganExtent organExtent(const vk::Context& context, const turtle::DeviceOrgans& organs);

// A Vulkan context for the GPU backend (null for the CPU backend, which needs no device).
std::unique_ptr<vk::Context> contextFor(const FieldSource& source);

} // namespace simeco::field
