#include "app/field_options.h"

#include <cstdint>
#include <string>

#include <fmt/format.h>

namespace simeco::app {

CLI::Option* addBackendOption(CLI::App& cmd, field::Backend& backend, const std::string& description) {
    auto read = [&backend](const std::string& name) { backend = *field::backendNamed(name); };
    return cmd.add_option_function<std::string>("--backend", read, description)->check(CLI::IsMember({"cpu", "gpu"}));
}

CLI::Option* addColormapOption(CLI::App& cmd, std::string& path) {
    return cmd
        .add_option("--colormap", path,
                    "a cpfg colour map (.map, 256 RGB colours) for a grammar's `;` colour indices in place of its own")
        ->check(CLI::ExistingFile);
}

CLI::Option* addTimeLimitOption(CLI::App& cmd, double& seconds) {
    return cmd
        .add_option("--max-seconds", seconds,
                    fmt::format("stop the derivation with an error after S seconds; 0: no limit (default {})",
                                stream::kDefaultMaxSeconds))
        ->check(CLI::Range(0.0, 1e9));
}

CLI::Option* addDensityOption(CLI::App& cmd, float& density) {
    return cmd
        .add_option("--density", density,
                    "a factor on the plants of every population of the scene (its Count or Density; default 1)")
        ->check(CLI::Range(0.01f, 100.0f));
}

void addFieldOptions(CLI::App& cmd, field::FieldSource& source) {
    cmd.add_option("file", source.file, "grammar (.l, .lsys) or scene (.eco)")->required();
    cmd.add_option("-n,--steps", source.steps, "derivation steps (default: the file's derivation length)")
        ->check(CLI::Range(0, 1000000));
    cmd.add_option("--seed", source.seed, "seed of the random streams (default: the file's seed, else 0)")
        ->check(CLI::Range(int64_t(0), int64_t(UINT32_MAX)));
    cmd.add_option("--plants", source.plants,
                   "plants in the field; a scene's species take turns (default: one of each)")
        ->check(CLI::Range(1u, 1000000u));
    cmd.add_option("--spacing", source.spacing, "distance between plants (default: from the widest plant)")
        ->check(CLI::Range(0.0f, 1e6f));
    addBackendOption(cmd, source.backend, "derivation and turtle: gpu (compute kernels) or cpu (reference)");
    cmd.add_option("--max-modules", source.maxModules, "module budget (default: sized to this machine's memory)");
    addTimeLimitOption(cmd, source.maxSeconds);
    cmd.add_option("--device", source.device, "Vulkan device: an index or a name part (see `simeco devices`)");
}

} // namespace simeco::app
