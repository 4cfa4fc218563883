// Errors by tier at the command level: bad input exits 2, runtime failures exit 1.
#pragma once

#include <functional>

namespace simeco::app {

inline constexpr int kExitOk = 0;
inline constexpr int kExitRuntime = 1;
inline constexpr int kExitBadInput = 2;

// Runs a command body, printing any error to stderr in the form users expect and returning the exit code.
int runReportingErrors(const std::function<void()>& body);

} // namespace simeco::app
