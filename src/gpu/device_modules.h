// A module stream on the device, as the derivation kernels leave it and the turtle kernels read it.
#pragma once

#include <cstdint>

namespace simeco::vk {
class Buffer;
}

namespace simeco::gpu {

// A module stream on the device, laid out as the derivation kernels leave it: symbols (symbol | parameter
// count << 24), `stride` floats of parameters per module, and plants + 1 plant starts.
struct DeviceModules {
    const vk::Buffer* symbols = nullptr;
    const vk::Buffer* params = nullptr;
    const vk::Buffer* plantStarts = nullptr;
    std::uint32_t count = 0;
    std::uint32_t plants = 0;
    std::uint32_t stride = 1;
};

} // namespace simeco::gpu
