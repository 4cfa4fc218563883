// A text file among a command's outputs: written under a temporary name and renamed when the batch commits
// (draw/atomic_file.h), so a failed command leaves no partial file.
#pragma once

#include <filesystem>
#include <string>

#include "draw/atomic_file.h"

namespace simeco::app {

void writeText(draw::OutputBatch& batch, const std::filesystem::path& path, const std::string& text);

} // namespace simeco::app
