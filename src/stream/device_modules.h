// A module stream on the device, as the derivation kernels leave it and the turtle kernels read it.
#pragma once

#include <cstdint>

namespace simeco::vk {
class Buffer;
}

namespace simeco::stream {

// A module stream on the device, laid out as the derivation kernels leave it: symbols (symbol | parameter
// count << 24), `stride` floats of parameters per module, plants + 1 plant starts, and each module's particle
// state (compute/shared/particle_layout.h) when the derivation carried it.
struct DeviceModules {
    const vk::Buffer* symbols = nullptr;
    const vk::Buffer* params = nullptr;
    const vk::Buffer* plantStarts = nullptr;
    std::uint32_t count = 0; // with countOnDevice, a bound on the modules
    std::uint32_t plants = 0;
    std::uint32_t stride = 1;
    const vk::Buffer* particles = nullptr; // null unless the derivation carried particle state
    // Of a string drawn under the homomorphism: each module's index in the derived string it was drawn from.
    const vk::Buffer* origins = nullptr;
    // The modules are counted only on the device, by the plant table's last entry: the string of a derivation
    // recorded into a command buffer, which its submission writes.
    bool countOnDevice = false;
};

} // namespace simeco::stream
