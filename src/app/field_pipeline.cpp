#include "app/field_pipeline.h"

#include <stdexcept>

#include "app/load_species.h"
#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "ir/species.h"
#include "turtle/turtle_cpu.h"
#include "vk/context.h"

namespace simeco::app {

void addFieldOptions(CLI::App& cmd, FieldSource& source) {
    cmd.add_option("file", source.file, "grammar (.l, .lsys) or scene (.eco)")->required();
    cmd.add_option("-n,--steps", source.steps, "derivation steps (default: the file's derivation length)")
        ->check(CLI::Range(0, 1000000));
    cmd.add_option("--seed", source.seed, "seed of the random streams (default: the file's seed, else 0)")
        ->check(CLI::Range(int64_t(0), int64_t(UINT32_MAX)));
    cmd.add_option("--plants", source.plants, "plants in the field; a scene's species take turns (default: one of each)")
        ->check(CLI::Range(1u, 1000000u));
    cmd.add_option("--spacing", source.spacing, "distance between plants (default: from the widest plant)")
        ->check(CLI::Range(0.0f, 1e6f));
    cmd.add_option("--backend", source.backend, "derivation and turtle: gpu (compute kernels) or cpu (reference)")
        ->check(CLI::IsMember({"cpu", "gpu"}));
    cmd.add_option("--max-modules", source.maxModules, "module budget (default: sized to this machine's memory)");
    cmd.add_option("--device", source.device, "Vulkan device: an index or a name part (see `simeco devices`)");
}

std::unique_ptr<vk::Context> contextFor(const FieldSource& source) {
    if (!source.onDevice()) return nullptr;
    vk::ContextOptions options;
    options.device = source.device;
    return std::make_unique<vk::Context>(options);
}

Field::Field() = default;
Field::~Field() = default;
Field::Field(Field&&) noexcept = default;
Field& Field::operator=(Field&&) noexcept = default;

Field deriveField(const FieldSource& source, const vk::Context* context) {
    Field field;
    field.species = ir::unifySpecies(loadGrammars(source.file));
    cpu::DeriveOptions options;
    options.steps = source.steps;
    options.seed = source.seed;
    options.plants = source.plants ? source.plants : static_cast<uint32_t>(field.species.size());
    options.maxModules = source.maxModules;
    if (source.onDevice()) {
        if (!context) throw std::logic_error("the GPU backend derives on a Vulkan device");
        field.deriver = std::make_unique<gpu::GpuDeriver>(*context, field.species);
        options.homomorphism = true;
        if (field.deriver->appliesHomomorphism()) {
            field.deriver->derive(options, false); // the string stays on the device for the turtle kernels
        } else {
            // A homomorphism the parallel passes cannot run goes through the host.
            options.homomorphism = false;
            cpu::DeriveResult derived = field.deriver->derive(options, true);
            options.homomorphism = true;
            field.string = cpu::applyHomomorphismCpu(field.species, derived.string, options);
            field.deriver.reset();
        }
    } else {
        options.homomorphism = true;
        field.string = cpu::deriveSpeciesCpu(field.species, options).string;
    }
    if (field.deriver) {
        gpu::DeviceModules modules = field.deriver->lastString();
        field.modules = modules.count;
        field.plants = modules.plants;
    } else {
        field.modules = field.string.size();
        field.plants = static_cast<uint32_t>(field.string.plants());
    }
    const ir::Alphabet& alphabet = field.species.front().alphabet;
    field.commands = turtle::turtleCommands(alphabet);
    for (const ir::Grammar& g : field.species) field.turtles.push_back(turtle::turtleSettings(g, alphabet));
    field.options.spacing = source.spacing;
    return field;
}

gpu::DeviceOrgans interpretOnDevice(const FieldSource& source, const Field& field, const vk::Context& context) {
    if (!source.onDevice())
        return gpu::uploadOrgans(context, turtle::interpretCpu(field.string, field.commands, field.turtles, field.options));
    gpu::GpuTurtle turtle(context, field.commands, field.turtles);
    if (field.deriver) return turtle.interpret(field.deriver->lastString(), field.options);
    gpu::UploadedModules modules(context, field.string);
    return turtle.interpret(modules.view(), field.options);
}

turtle::Interpretation interpretOnHost(const FieldSource& source, const Field& field, const vk::Context* context) {
    if (!source.onDevice() || !context)
        return turtle::interpretCpu(field.string, field.commands, field.turtles, field.options);
    gpu::DeviceOrgans organs = interpretOnDevice(source, field, *context);
    return gpu::readBack(*context, organs, field.plants);
}

} // namespace simeco::app
