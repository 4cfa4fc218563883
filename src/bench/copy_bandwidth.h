// The device's copy bandwidth, measured by compute kernels in the same run as the derivations it is compared
// with: one reading its source as a storage buffer (compute/bench/copy.comp), one as a uniform texel buffer
// (compute/bench/copy_texel.comp); the faster is the device's figure.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace simeco::vk {
class Context;
}

namespace simeco::bench {

inline constexpr std::uint64_t kCopyBufferBytes = 256ull << 20;

struct CopyBandwidth {
    std::uint64_t bufferBytes = 0; // bytes copied per run (each of source and destination is this large)
    std::uint64_t limitBytes = 0;  // the device's largest storage-buffer binding
    std::vector<double> runMillis; // each timed run
    double medianMillis = 0;
    double bytesPerSecond = 0; // (read + written) / median time
    bool timestamps = false;   // GPU timestamps (else host wall time around each submission)
    std::string kernel;        // the faster kernel: "storage buffer" or "texel buffer" reads
    double otherBytesPerSecond = 0; // the slower kernel's figure
};

// Copies min(kCopyBufferBytes, the device's largest storage-buffer binding) bytes `warmUp` + `repeat` times with
// each kernel.
CopyBandwidth measureCopyBandwidth(const vk::Context& context, int warmUp, int repeat);

// The figure and how it was taken, as the render and growth reports give it.
nlohmann::json copyBandwidthSummary(const CopyBandwidth& c);

} // namespace simeco::bench
