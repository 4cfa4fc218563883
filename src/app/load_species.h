// The grammars a command works on: one for `.l` and `.lsys`, one per plant (species) of an `.eco` scene.
#pragma once

#include <string>
#include <vector>

#include "ir/grammar.h"

namespace simeco::app {

// Scene warnings go to stderr.
std::vector<ir::Grammar> loadGrammars(const std::string& path);

} // namespace simeco::app
