#include "vk/kernel_cache.h"

#include <cstring>

namespace simeco::vk {

std::shared_ptr<const CompiledKernel>
KernelCache::get(std::span<const std::uint32_t> spirv, std::span<const std::uint32_t> specialization,
                 const std::function<std::shared_ptr<const CompiledKernel>()>& compile) {
    // The SPIR-V's length first, so that no other split of the same bytes reads as the same key.
    const std::size_t words = spirv.size();
    std::string key(sizeof(words) + spirv.size_bytes() + specialization.size_bytes(), '\0');
    std::memcpy(key.data(), &words, sizeof(words));
    std::memcpy(key.data() + sizeof(words), spirv.data(), spirv.size_bytes());
    if (!specialization.empty())
        std::memcpy(key.data() + sizeof(words) + spirv.size_bytes(), specialization.data(),
                    specialization.size_bytes());

    const std::lock_guard<std::mutex> lock(mutex_);
    if (std::shared_ptr<const CompiledKernel> held = kernels_[key].lock()) return held;
    std::erase_if(kernels_, [](const auto& entry) { return entry.second.expired(); });
    std::shared_ptr<const CompiledKernel> compiled = compile();
    kernels_[std::move(key)] = compiled;
    return compiled;
}

} // namespace simeco::vk
