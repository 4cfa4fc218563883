// Which engines derive and interpret a field: the device's kernels, or the CPU reference engine and turtle.
#pragma once

#include <optional>
#include <string_view>

namespace simeco::field {

enum class Backend {
    Gpu, // derivation and turtle kernels on the Vulkan device
    Cpu, // the reference engine and the reference turtle
};

// The backend a command line names ("gpu", "cpu"), or nothing.
std::optional<Backend> backendNamed(std::string_view name);
const char* backendName(Backend backend);

} // namespace simeco::field
