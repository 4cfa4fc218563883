// The command-line options that say which field to grow, shared by `simeco render` and `simeco export`.
#pragma once

#include <CLI/CLI.hpp>

#include "field/field.h"

namespace simeco::app {

// Adds the file argument and the field options (-n, --seed, --plants, --spacing, --backend, --max-modules,
// --device) to a subcommand.
void addFieldOptions(CLI::App& cmd, field::FieldSource& source);

// Adds `--backend gpu|cpu`, read into `backend`.
CLI::Option* addBackendOption(CLI::App& cmd, field::Backend& backend, const std::string& description);

} // namespace simeco::app
