// The command-line options that say which field to grow, shared by `simeco render` and `simeco export`.
#pragma once

#include <CLI/CLI.hpp>

#include "field/field.h"

namespace simeco::app {

// Adds the file argument and the field options (-n, --seed, --plants, --spacing, --backend, --max-modules,
// --max-seconds, --device) to a subcommand.
void addFieldOptions(CLI::App& cmd, field::FieldSource& source);

// Adds `--backend gpu|cpu`, read into `backend`.
// --colormap FILE: a cpfg colour map (.map) for a grammar's `;` colour indices in place of its own.
CLI::Option* addColormapOption(CLI::App& cmd, std::string& path);

CLI::Option* addBackendOption(CLI::App& cmd, field::Backend& backend, const std::string& description);

// Adds `--max-seconds S`, the derivation's time limit (stream::DeriveOptions::maxSeconds), read into `seconds`.
CLI::Option* addTimeLimitOption(CLI::App& cmd, double& seconds);

// Adds `--density F`, the factor on a scene's populations' plants (field::SimulationOptions::density).
CLI::Option* addDensityOption(CLI::App& cmd, float& density);

} // namespace simeco::app
