// Output files appear whole or not at all, and several files of one command together or not at all: each is
// written under a temporary name in its destination's folder, and only when every file is written are they
// renamed over their destinations, which the file system does in one step each.
//
// No temporary outlives the process that wrote it: a batch dropped before its commit removes its temporaries,
// so does SIGINT or SIGTERM while they exist (the process then ends as the signal asks), and writing a file
// removes the temporaries of that file that processes no longer running left behind (a SIGKILL, a power cut).
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace simeco::draw {

// Writing an output file failed; nothing was left at the destination or under the temporary name.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

using FileWriter = std::function<void(const std::filesystem::path& temporary)>;

// The output files of one command.
class OutputBatch {
public:
    OutputBatch() = default;
    ~OutputBatch(); // removes the temporaries of a batch not committed
    OutputBatch(const OutputBatch&) = delete;
    OutputBatch& operator=(const OutputBatch&) = delete;

    // Calls `write` with a temporary path next to `destination`. When `write` throws, every temporary of the
    // batch is removed and an OutputError naming `destination` is thrown.
    void write(const std::filesystem::path& destination, const FileWriter& write);
    // Renames every temporary to its destination, in the order they were written. When a rename fails, the
    // temporaries not yet renamed are removed and an OutputError naming that destination is thrown.
    void commit();

private:
    void discard();

    struct Pending {
        std::filesystem::path destination, temporary;
    };
    std::vector<Pending> pending_;
};

// A batch of one file.
void writeAtomically(const std::filesystem::path& destination, const FileWriter& write);

// The temporary name `destination` is written under by this process.
std::filesystem::path temporaryPathFor(const std::filesystem::path& destination);

} // namespace simeco::draw
