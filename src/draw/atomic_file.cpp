#include "draw/atomic_file.h"

#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <mutex>
#include <string_view>
#include <system_error>

#include <signal.h>
#include <unistd.h>

namespace simeco::draw {

namespace fs = std::filesystem;

namespace {

// The temporaries that exist now, for the signal handler, which may only call async-signal-safe functions: a
// fixed table of C strings, changed with the signals blocked. A temporary beyond the table's size is still
// removed by its batch, only not on a signal.
constexpr std::size_t kTracked = 32;
constexpr std::size_t kPathBytes = 4096;
std::array<std::array<char, kPathBytes>, kTracked> gTemporaries{};
std::mutex gTemporariesMutex;

void removeTrackedAndReraise(int signal) {
    for (std::array<char, kPathBytes>& path : gTemporaries)
        if (path[0] != '\0') ::unlink(path.data());
    std::signal(signal, SIG_DFL);
    std::raise(signal);
}

// Blocks SIGINT and SIGTERM while the table changes, so the handler never sees half a path.
class SignalsBlocked {
public:
    SignalsBlocked() {
        sigset_t set;
        sigemptyset(&set);
        sigaddset(&set, SIGINT);
        sigaddset(&set, SIGTERM);
        pthread_sigmask(SIG_BLOCK, &set, &previous_);
    }
    ~SignalsBlocked() { pthread_sigmask(SIG_SETMASK, &previous_, nullptr); }

private:
    sigset_t previous_;
};

void installHandlers() {
    static std::once_flag once;
    std::call_once(once, [] {
        for (int signal : {SIGINT, SIGTERM}) {
            struct sigaction action {};
            sigaction(signal, nullptr, &action);
            if (action.sa_handler != SIG_DFL) continue; // the embedding program handles it
            action.sa_handler = removeTrackedAndReraise;
            sigemptyset(&action.sa_mask);
            action.sa_flags = 0;
            sigaction(signal, &action, nullptr);
        }
    });
}

void track(const fs::path& temporary) {
    installHandlers();
    const std::string& text = temporary.native();
    if (text.size() >= kPathBytes) return;
    std::lock_guard lock(gTemporariesMutex);
    SignalsBlocked blocked;
    for (std::array<char, kPathBytes>& slot : gTemporaries)
        if (slot[0] == '\0') {
            std::memcpy(slot.data(), text.c_str(), text.size() + 1);
            return;
        }
}

void untrack(const fs::path& temporary) {
    std::lock_guard lock(gTemporariesMutex);
    SignalsBlocked blocked;
    for (std::array<char, kPathBytes>& slot : gTemporaries)
        if (temporary.native() == slot.data()) slot[0] = '\0';
}

// Removes the temporaries of `destination` whose writers are no longer running: `<name>.tmp<pid>`.
void removeStaleTemporaries(const fs::path& destination) {
    std::string prefix = destination.filename().string() + ".tmp";
    fs::path folder = destination.parent_path().empty() ? fs::path(".") : destination.parent_path();
    std::error_code error;
    for (const fs::directory_entry& entry : fs::directory_iterator(folder, error)) {
        std::string name = entry.path().filename().string();
        if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
        std::string_view digits = std::string_view(name).substr(prefix.size());
        if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string_view::npos) continue;
        pid_t pid = static_cast<pid_t>(std::stol(std::string(digits)));
        if (pid <= 0 || pid == ::getpid()) continue;
        if (::kill(pid, 0) == -1 && errno == ESRCH) fs::remove(entry.path(), error);
    }
}

} // namespace

fs::path temporaryPathFor(const fs::path& destination) {
    // The process id keeps two writers of the same file from sharing a temporary.
    fs::path temporary = destination;
    temporary += ".tmp" + std::to_string(::getpid());
    return temporary;
}

OutputBatch::~OutputBatch() { discard(); }

void OutputBatch::discard() {
    for (const Pending& p : pending_) {
        std::error_code ignored;
        fs::remove(p.temporary, ignored);
        untrack(p.temporary);
    }
    pending_.clear();
}

void OutputBatch::write(const fs::path& destination, const FileWriter& write) {
    if (destination.filename().empty()) {
        discard();
        throw OutputError("cannot write '" + destination.string() + "': not a file name");
    }
    removeStaleTemporaries(destination);
    fs::path temporary = temporaryPathFor(destination);
    track(temporary);
    pending_.push_back({destination, temporary});
    try {
        write(temporary);
    } catch (const std::exception& e) {
        discard();
        throw OutputError("cannot write '" + destination.string() + "': " + e.what());
    }
}

void OutputBatch::commit() {
    for (std::size_t i = 0; i < pending_.size(); ++i) {
        std::error_code error;
        fs::rename(pending_[i].temporary, pending_[i].destination, error);
        if (error) {
            fs::path failed = pending_[i].destination;
            pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(i));
            discard();
            throw OutputError("cannot write '" + failed.string() + "': " + error.message());
        }
        untrack(pending_[i].temporary);
    }
    pending_.clear();
}

void writeAtomically(const fs::path& destination, const FileWriter& write) {
    OutputBatch batch;
    batch.write(destination, write);
    batch.commit();
}

} // namespace simeco::draw
