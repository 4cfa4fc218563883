// Source positions and the user-facing error every front end and engine reports.
#pragma once

#include <stdexcept>
#include <string>

namespace simeco::ir {

struct SourceLoc {
    std::string file;
    int line = 0;
    int col = 0;
};

// A problem in the user's input (a grammar, a scene, a derive-time evaluation such as a division by zero).
// Printed as `file:line:col: error: message`; the command exits with code 2.
class InputError : public std::runtime_error {
public:
    InputError(SourceLoc loc, const std::string& message)
        : std::runtime_error(message), loc_(std::move(loc)) {}
    const SourceLoc& loc() const { return loc_; }
    // `file:line:col: error: message` (line and column left out when unknown).
    std::string formatted() const;

private:
    SourceLoc loc_;
};

// A resource limit was reached (module budget, memory); exit code 1 with a clear message.
class LimitError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace simeco::ir
