#include "draw/atomic_file.h"

#include <system_error>

#include <unistd.h>

namespace simeco::draw {

void writeAtomically(const std::filesystem::path& destination,
                     const std::function<void(const std::filesystem::path& temporary)>& write) {
    namespace fs = std::filesystem;
    if (destination.filename().empty()) {
        throw OutputError("cannot write '" + destination.string() + "': not a file name");
    }
    // The process id keeps two writers of the same file from sharing a temporary.
    fs::path temporary = destination;
    temporary += ".tmp" + std::to_string(::getpid());
    auto removeTemporary = [&] {
        std::error_code ignored;
        fs::remove(temporary, ignored);
    };
    try {
        write(temporary);
    } catch (const std::exception& e) {
        removeTemporary();
        throw OutputError("cannot write '" + destination.string() + "': " + e.what());
    }
    std::error_code error;
    fs::rename(temporary, destination, error);
    if (error) {
        removeTemporary();
        throw OutputError("cannot write '" + destination.string() + "': " + error.message());
    }
}

} // namespace simeco::draw
