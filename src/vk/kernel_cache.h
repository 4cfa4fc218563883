// Compiled kernels shared by the pipelines made from the same SPIR-V on one device. A large field runs in batches of
// plants, each with the same derivation, growth and turtle kernels, and a driver compiles every pipeline it is asked
// for anew (lavapipe into machine code through LLVM: about a quarter of a second and some megabytes a batch); with
// the cache a field compiles its kernels once, whatever its batches.
#pragma once

#include <functional>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <unordered_map>

#include "vk/handle.h"

namespace simeco::vk {

// What a kernel compiles to: its descriptor set and pipeline layouts and its pipeline.
struct CompiledKernel {
    UniqueDescriptorSetLayout setLayout;
    UniquePipelineLayout layout;
    UniquePipeline pipeline;
};

class KernelCache {
public:
    // The kernel compiled from `spirv` with `specialization` while a pipeline still holds it, else the one `compile`
    // makes now. Safe to call from several threads.
    std::shared_ptr<const CompiledKernel> get(std::span<const std::uint32_t> spirv,
                                              std::span<const std::uint32_t> specialization,
                                              const std::function<std::shared_ptr<const CompiledKernel>()>& compile);

private:
    std::mutex mutex_;
    // By the SPIR-V's and the specialization's bytes. Held weakly: a kernel goes with the last pipeline using it.
    std::unordered_map<std::string, std::weak_ptr<const CompiledKernel>> kernels_;
};

} // namespace simeco::vk
