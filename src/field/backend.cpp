#include "field/backend.h"

namespace simeco::field {

std::optional<Backend> backendNamed(std::string_view name) {
    if (name == "gpu") return Backend::Gpu;
    if (name == "cpu") return Backend::Cpu;
    return std::nullopt;
}

const char* backendName(Backend backend) {
    return backend == Backend::Gpu ? "gpu" : "cpu";
}

} // namespace simeco::field
