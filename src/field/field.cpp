#include "field/field.h"

#include <cstdio>
#include <stdexcept>

#include <fmt/format.h>

#include "cpu/derive.h"
#include "gpu/derive_gpu.h"
#include "ir/species.h"
#include "lang/color_map.h"
#include "lang/load_grammar.h"
#include "turtle/finite_organs.h"
#include "turtle/organ_merge.h"
#include "turtle/turtle_cpu.h"
#include "vk/buffer.h"
#include "vk/context.h"

namespace simeco::field {

std::vector<ir::Grammar> loadSpecies(const std::string& path, ir::DrawAssets* assets) {
    std::vector<ir::EcoWarning> warnings;
    std::vector<ir::Grammar> species = lang::loadSpecies(path, &warnings, assets);
    for (const ir::EcoWarning& w : warnings)
        std::fprintf(stderr, "%s:%d:%d: warning: %s\n", w.loc.file.c_str(), w.loc.line, w.loc.col, w.message.c_str());
    return ir::unifySpecies(std::move(species));
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
    field.species = loadSpecies(source.file, &field.assets);
    if (!source.colormap.empty()) lang::useColorMap(field.species, source.colormap);
    stream::DeriveOptions options;
    options.steps = source.steps;
    options.seed = source.seed;
    options.plants = source.plants ? source.plants : static_cast<uint32_t>(field.species.size());
    options.maxModules = source.maxModules;
    options.maxSeconds = source.maxSeconds;
    if (source.onDevice()) {
        if (!context) throw std::logic_error("the GPU backend derives on a Vulkan device");
        field.deriver = std::make_unique<gpu::GpuDeriver>(*context, field.species);
        options.homomorphism = true;
        if (field.deriver->appliesHomomorphism()) {
            field.deriver->derive(options, false); // the string stays on the device for the turtle kernels
        } else {
            // A homomorphism the parallel passes cannot run goes through the host.
            options.homomorphism = false;
            stream::DeriveResult derived = field.deriver->derive(options, true);
            options.homomorphism = true;
            field.string = cpu::applyHomomorphismCpu(field.species, derived.string, options);
            field.deriver.reset();
        }
    } else {
        options.homomorphism = true;
        field.string = cpu::deriveSpeciesCpu(field.species, options).string;
    }
    if (field.deriver) {
        stream::DeviceModules modules = field.deriver->lastString();
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
    field.options.scattered = field.plants > 1;
    return field;
}

const turtle::DeviceOrgans& interpretOnDevice(const FieldSource& source, Field& field, const vk::Context& context) {
    if (!source.onDevice()) {
        field.uploaded =
            turtle::uploadOrgans(context, turtle::interpretCpu(field.string, field.commands, field.turtles, field.options));
        return field.uploaded;
    }
    if (!field.turtle) field.turtle = std::make_unique<turtle::GpuTurtle>(context, field.commands, field.turtles);
    if (field.deriver) return field.turtle->interpret(field.deriver->lastString(), field.options);
    turtle::UploadedModules modules(context, field.string);
    return field.turtle->interpret(modules.view(), field.options);
}

turtle::Interpretation interpretOnHost(const FieldSource& source, Field& field, const vk::Context* context) {
    turtle::Interpretation interpretation =
        !source.onDevice() || !context
            ? turtle::interpretCpu(field.string, field.commands, field.turtles, field.options)
            : turtle::readBack(*context, interpretOnDevice(source, field, *context), field.plants);
    for (const shared::OrganInstance& o : interpretation.organs)
        if (!turtle::organIsFinite(o))
            throw turtle::nonFiniteOrganError(fmt::format("plant {}, module {}", o.plant, o.module));
    return interpretation;
}

OrganExtent organExtent(const vk::Context& context, const turtle::DeviceOrgans& organs) {
    shared::OrganTable table = vk::downloadVector<shared::OrganTable>(context, organs.table, 1)[0];
    OrganExtent extent;
    for (uint32_t k = 0; k < shared::kOrganKinds; ++k) extent.organs += table.count[k];
    extent.bounds = draw::decodeBounds(table);
    if (extent.organs > 0 && !extent.bounds.finite()) throw turtle::nonFiniteOrganError();
    return extent;
}

} // namespace simeco::field
