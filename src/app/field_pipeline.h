// What `simeco render` and `simeco export` share: the options that say which field to grow, deriving it
// (strings under their homomorphisms), and interpreting it with the turtle, on the device or on the CPU.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cpu/module_string.h"
#include "gpu/derive_gpu.h"
#include "gpu/turtle_gpu.h"
#include "ir/grammar.h"
#include "turtle/interpretation.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_settings.h"

namespace simeco::vk {
class Context;
}

namespace simeco::app {

struct FieldSource {
    std::string file;
    int steps = -1;
    int64_t seed = -1;
    uint32_t plants = 0;
    float spacing = 0;
    std::string backend = "gpu"; // gpu: derivation and turtle kernels; cpu: the reference engine and turtle
    uint64_t maxModules = 0;
    std::string device;

    bool onDevice() const { return backend != "cpu"; }
};

// Adds the file argument and the field options (-n, --seed, --plants, --spacing, --backend, --max-modules,
// --device) to a subcommand.
void addFieldOptions(CLI::App& cmd, FieldSource& source);

// A field derived and ready for the turtle.
struct Field {
    std::vector<ir::Grammar> species; // one alphabet (ir::unifySpecies)
    // Every plant, under its homomorphism: with the GPU backend left on the device by `deriver` (then `string`
    // stays empty), else on the host.
    cpu::ModuleString string;
    std::unique_ptr<gpu::GpuDeriver> deriver;
    uint64_t modules = 0;
    uint32_t plants = 0;
    turtle::TurtleCommands commands;
    std::vector<turtle::TurtleSettings> turtles;
    turtle::FieldOptions options;

    Field();
    ~Field();
    Field(Field&&) noexcept;
    Field& operator=(Field&&) noexcept;
};

// Loads and derives the source's file; `context` is used by the GPU backend (may be null for the CPU one).
Field deriveField(const FieldSource& source, const vk::Context* context);

// The field's organs on the device: written by the turtle kernels, or with the CPU backend by the reference
// turtle and uploaded.
gpu::DeviceOrgans interpretOnDevice(const FieldSource& source, const Field& field, const vk::Context& context);

// The field's organs on the host: the turtle kernels' read back, or the reference turtle's.
turtle::Interpretation interpretOnHost(const FieldSource& source, const Field& field, const vk::Context* context);

// A Vulkan context for the GPU backend (null for the CPU backend, which needs no device).
std::unique_ptr<vk::Context> contextFor(const FieldSource& source);

} // namespace simeco::app
