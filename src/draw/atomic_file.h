// Output files appear whole or not at all: written under a temporary name in the same folder, then renamed
// over the destination, which the file system does in one step.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>

namespace simeco::draw {

// Writing an output file failed; nothing was left at the destination or under the temporary name.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Calls `write` with a temporary path next to `destination`, then renames it to `destination`. When `write`
// throws or the rename fails, the temporary file is removed and an OutputError naming `destination` is thrown.
void writeAtomically(const std::filesystem::path& destination,
                     const std::function<void(const std::filesystem::path& temporary)>& write);

} // namespace simeco::draw
