#include "vk/kernel_profile.h"

#include <algorithm>

#include <fmt/format.h>

namespace simeco::vk {

KernelProfile::KernelProfile(const Context& context, std::uint32_t capacity)
    : stamps_(context, capacity), capacity_(capacity) {}

void KernelProfile::begin(VkCommandBuffer cmd) {
    recording_ = cmd;
    pending_.clear();
    stamps_.cmdReset(cmd);
    stamps_.cmdWrite(cmd, 0, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT);
}

void KernelProfile::afterDispatch(VkCommandBuffer cmd, const std::string& kernel) {
    if (cmd != recording_) return; // recorded outside a profiled submission
    if (pending_.size() + 1 >= capacity_) {
        ++unprofiled_;
        return;
    }
    pending_.push_back(&kernel);
    stamps_.cmdWrite(cmd, static_cast<std::uint32_t>(pending_.size()));
}

void KernelProfile::finish() {
    recording_ = VK_NULL_HANDLE;
    if (pending_.empty()) return;
    std::vector<double> ns = stamps_.readNs(static_cast<std::uint32_t>(pending_.size() + 1));
    for (std::size_t i = 0; i < pending_.size(); ++i) {
        Kernel& k = totals_[*pending_[i]];
        k.name = *pending_[i];
        k.dispatches += 1;
        k.milliseconds += (ns[i + 1] - ns[i]) / 1e6;
    }
    pending_.clear();
}

std::vector<KernelProfile::Kernel> KernelProfile::kernels() const {
    std::vector<Kernel> list;
    for (const auto& entry : totals_) list.push_back(entry.second);
    std::sort(list.begin(), list.end(), [](const Kernel& a, const Kernel& b) { return a.milliseconds > b.milliseconds; });
    return list;
}

std::string KernelProfile::table() const {
    std::vector<Kernel> list = kernels();
    double total = 0;
    for (const Kernel& k : list) total += k.milliseconds;
    std::string out = fmt::format("{:<36} {:>10} {:>12} {:>7}\n", "kernel", "dispatches", "GPU ms", "share");
    for (const Kernel& k : list)
        out += fmt::format("{:<36} {:>10} {:>12.3f} {:>6.1f}%\n", k.name, k.dispatches, k.milliseconds,
                           total > 0 ? 100.0 * k.milliseconds / total : 0.0);
    out += fmt::format("{:<36} {:>10} {:>12.3f}\n", "total", "", total);
    if (unprofiled_ > 0) out += fmt::format("({} dispatches past the profile's capacity are not counted)\n", unprofiled_);
    return out;
}

} // namespace simeco::vk
