// Errors by tier at the command level: bad input exits 2, runtime failures exit 1.
#pragma once

#include <functional>
#include <stdexcept>

namespace simeco::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRuntime = 1;
inline constexpr int kExitBadInput = 2;

// A command-line value the option parser could not judge (an image size, a camera, a file's extension): bad
// input like any other, exit code 2.
class CommandLineError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// Runs a command body, printing any error to stderr in the form users expect and returning the exit code.
int runReportingErrors(const std::function<void()>& body);

} // namespace simeco::app
