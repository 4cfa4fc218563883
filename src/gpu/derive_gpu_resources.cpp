// The GPU deriver's kernels, generated and compiled once per grammar, and the buffers it sizes as strings grow.
#include "gpu/derive_gpu_impl.h"

#include <algorithm>
#include <chrono>
#include <span>

#include <fmt/format.h>

#include "codegen/glsl_compiler.h"
#include "compute/shared/particle_layout.h"

namespace simeco::gpu {

GpuDeriver::Impl::Impl(const vk::Context& c, std::vector<ir::Grammar> grammars, GpuStrategy requested, GpuLoads loads,
                       GpuContextMatch contexts)
    : ctx(c), species(std::move(grammars)), strategy(requested), stride(1),
      texelInputs(loads == GpuLoads::TexelBuffers ||
                  (loads == GpuLoads::Auto && c.deviceInfo().type == VK_PHYSICAL_DEVICE_TYPE_CPU)),
      contextChunks(contexts == GpuContextMatch::Chunks ||
                    (contexts == GpuContextMatch::Auto && c.deviceInfo().type == VK_PHYSICAL_DEVICE_TYPE_CPU)),
      plantStarts(vk::ComputePipeline::embedded(c, "derive/plant_starts")),
      plantHintsKernel(vk::ComputePipeline::embedded(c, "derive/plant_hints")),
      cutApply(vk::ComputePipeline::embedded(c, "derive/cut_apply")),
      greedyReduce(vk::ComputePipeline::embedded(c, "derive/greedy_reduce")),
      greedyScan(vk::ComputePipeline::embedded(c, "derive/greedy_scan")),
      greedyMark(vk::ComputePipeline::embedded(c, "derive/greedy_mark")),
      streamCopy(vk::ComputePipeline::embedded(c, "derive/stream_copy")), scan(c), brackets(c, scan) {
    if (species.empty()) throw std::invalid_argument("GpuDeriver: no species");
    for (const ir::Grammar& g : species) {
        if (std::optional<std::string> reason = codegen::gpuUnsupportedReason(g))
            throw std::runtime_error("the GPU backend cannot derive this grammar: " + *reason +
                                     " (use --backend cpu)");
        std::optional<std::string> parallelReason = codegen::gpuParallelUnsupportedReason(g);
        if (parallelReason && strategy == GpuStrategy::Parallel)
            throw std::runtime_error("the parallel GPU passes cannot derive this grammar: " + *parallelReason);
        if (parallelReason) strategy = GpuStrategy::Sequential;
        stride = std::max(stride, g.maxParams());
        globalStride = std::max(globalStride, static_cast<uint32_t>(g.globalNames.size()));
        uint32_t elements = 0;
        for (const ir::GlobalArray& a : g.arrays) elements += static_cast<uint32_t>(a.init.size());
        arrayStride = std::max(arrayStride, elements);
    }
    if (strategy == GpuStrategy::Auto) strategy = GpuStrategy::Parallel;
    auto start = std::chrono::steady_clock::now();
    auto build = [&](const std::string& source, const char* name) {
        std::vector<uint32_t> spirv = codegen::cachedComputeKernel(source, name);
        return vk::ComputePipeline(ctx, spirv, name);
    };
    if (strategy == GpuStrategy::Sequential) {
        kernels = codegen::generateSequentialKernel(species, texelInputs);
        sequential.emplace(build(kernels.sequential, "derive/sequential"));
    } else {
        kernels = codegen::generateDeriveKernels(species, texelInputs, contextChunks);
        if (kernels.stride != static_cast<uint32_t>(stride))
            throw std::logic_error(fmt::format("the step's write pass stores {} parameter slots per module, the "
                                               "stream has {}", kernels.stride, stride));
        matchSpirv = codegen::cachedComputeKernel(kernels.match, "derive/match");
        writeSpirv = codegen::cachedComputeKernel(kernels.write, "derive/write");
    }
    if (kernels.hasDecomposition && strategy == GpuStrategy::Parallel) {
        decompositionMatch.emplace(build(kernels.decompositionMatch, "derive/decomposition_match"));
        decompositionWrite.emplace(build(kernels.decompositionWrite, "derive/decomposition_write"));
    }
    if (kernels.fusedScan) {
        const uint32_t choiceBits[] = {kernels.choiceBits};
        plantStartsTiled = vk::ComputePipeline::embedded(ctx, "derive/plant_starts_tiled", choiceBits);
        tileSize = kernels.chunkedMatch ? shared::kContextChunk : ctx.deviceInfo().subgroupSize;
        if (tileSize == 0 || (!kernels.chunkedMatch && shared::kDeriveWorkgroupSize % tileSize != 0))
            throw std::runtime_error(fmt::format("the GPU backend needs subgroups that divide its workgroups of {} "
                                                 "invocations; device {} has subgroups of {}",
                                                 shared::kDeriveWorkgroupSize, ctx.deviceInfo().name, tileSize));
    }
    derivationTables = tablesOf(kernels);
    buildHomomorphism(build);
    compileSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    decompositionDepths = std::min(kernels.maxDecompositionDepth, kFirstRecordedDepths);
    homomorphismDepths = std::min(homomorphismKernels.maxDecompositionDepth, kFirstRecordedDepths);
    // The homomorphism's error words after the derivation's, at a binding's offset.
    homomorphismTables.errorOffset = vk::alignUp(16, ctx.limits().minStorageBufferOffsetAlignment);
    errors = vk::Buffer(ctx, homomorphismTables.errorOffset + 16, vk::MemoryUsage::DeviceLocal);
    if (kernels.readsLight) noParticles = vk::Buffer(ctx, sizeof(shared::ParticleState), vk::MemoryUsage::DeviceLocal);
    readback = vk::Buffer(ctx, 16, vk::MemoryUsage::Readback);
}

template <typename Build> void GpuDeriver::Impl::buildHomomorphism(Build& build) {
    bool any = false;
    std::vector<ir::Grammar> images = species;
    for (ir::Grammar& g : images) {
        any = any || !g.homomorphism.productions.empty();
        g.decomposition = g.homomorphism;
        g.productions = ir::RuleSet{};
        if (!homomorphismHostReason) homomorphismHostReason = codegen::gpuUnsupportedReason(g);
        if (!homomorphismHostReason) homomorphismHostReason = codegen::gpuParallelUnsupportedReason(g);
    }
    if (!any) {
        homomorphismHostReason.reset(); // nothing to apply, on the device or elsewhere
        return;
    }
    if (homomorphismHostReason) return;
    homomorphismKernels = codegen::generateDeriveKernels(images, texelInputs, false, false);
    homomorphismMatch.emplace(build(homomorphismKernels.decompositionMatch, "derive/homomorphism_match"));
    homomorphismWrite.emplace(build(homomorphismKernels.decompositionWrite, "derive/homomorphism_write"));
    homomorphismTables = tablesOf(homomorphismKernels);
}

GpuDeriver::Impl::KernelTables GpuDeriver::Impl::tablesOf(const codegen::GeneratedKernels& k) const {
    KernelTables tables;
    tables.errors = &k.errors;
    std::vector<uint32_t> table = k.speciesTable;
    if (table.empty()) table.push_back(0);
    tables.speciesTable = vk::deviceBufferWith(ctx, std::span<const uint32_t>(table));
    std::vector<double> functions = k.functionTables;
    if (functions.empty()) functions.push_back(0.0);
    tables.funcTables = vk::deviceBufferWith(ctx, std::span<const double>(functions));
    tables.readsLight = k.readsLight;
    return tables;
}

uint64_t GpuDeriver::Impl::bufferLimit() const {
    uint64_t limit = ctx.limits().maxStorageBufferRange;
    if (texelInputs) limit = std::min<uint64_t>(limit, uint64_t(ctx.limits().maxTexelBufferElements) * 4);
    return limit;
}

void GpuDeriver::Impl::checkRange(uint64_t count, uint64_t size, const char* what) const {
    uint64_t limit = bufferLimit();
    if (count * size > limit)
        throw ir::LimitError(fmt::format("the device binds at most {} MiB per buffer; {} modules need {} MiB of {} "
                                         "(derive fewer steps or plants, or use a device with larger buffers)",
                                         limit >> 20, count, (count * size) >> 20, what));
}

void GpuDeriver::Impl::ensureStream(Stream& s, uint64_t count) {
    if (s.capacity >= count && s.sym) return;
    mayReplace("streams");
    uint64_t capacity = std::max<uint64_t>({count + count / 2, 1024, s.capacity});
    uint64_t limit = bufferLimit();
    capacity = std::min<uint64_t>(capacity, limit / (4ull * uint64_t(stride)));
    capacity = std::max(capacity, count);
    checkRange(count, 4ull * uint64_t(stride), "parameters");
    s.sym = vk::Buffer(ctx, bytes(capacity, 4), vk::MemoryUsage::DeviceLocal);
    s.par = vk::Buffer(ctx, bytes(capacity, 4ull * uint64_t(stride)), vk::MemoryUsage::DeviceLocal);
    s.origin = vk::Buffer(ctx, bytes(capacity, 4), vk::MemoryUsage::DeviceLocal);
    s.live = vk::Buffer(ctx, bytes(capacity, 4), vk::MemoryUsage::DeviceLocal);
    if (!s.plantStart) s.plantStart = vk::Buffer(ctx, bytes(plants + 1, 4), vk::MemoryUsage::DeviceLocal);
    s.capacity = capacity;
}

void GpuDeriver::Impl::ensureScratch(uint64_t count) {
    if (scan.capacity() < count + 1) mayReplace("scan");
    scan.reserve(static_cast<uint32_t>(count + 1));
    if (scratchCapacity >= count + 1 && counts) return;
    mayReplace("scratch");
    uint64_t capacity = std::max<uint64_t>(count + count / 2 + 1, 1024);
    capacity = std::min<uint64_t>(capacity, bufferLimit() / 4);
    capacity = std::max<uint64_t>(capacity, count + 1);
    checkRange(count + 1, 4, "per-module scratch");
    for (vk::Buffer* b : {&counts, &choices, &drawStarts, &offsets, &cutDelta, &cutBefore, &examined})
        *b = vk::Buffer(ctx, bytes(capacity, 4), vk::MemoryUsage::DeviceLocal);
    chunkFunctions = vk::Buffer(ctx, bytes(capacity / kGreedyChunk + 1, 4), vk::MemoryUsage::DeviceLocal);
    chunkEntries = vk::Buffer(ctx, bytes(capacity / kGreedyChunk + 1, 4), vk::MemoryUsage::DeviceLocal);
    uint64_t blocks = capacity / kGreedyChunk / kGreedyBlock + 1;
    blockFunctions = vk::Buffer(ctx, bytes(blocks, 4), vk::MemoryUsage::DeviceLocal);
    blockEntries = vk::Buffer(ctx, bytes(blocks, 4), vk::MemoryUsage::DeviceLocal);
    plantHints = vk::Buffer(ctx, bytes(shared::plantHintBlocks(static_cast<uint32_t>(capacity)) + 1, 4),
                            vk::MemoryUsage::DeviceLocal);
    if (kernels.fusedScan)
        for (vk::Buffer* b : {&tileSums, &tileOffsets})
            *b = vk::Buffer(ctx, bytes(tilesFor(capacity) + 1, 4), vk::MemoryUsage::DeviceLocal);
    scratchCapacity = capacity;
}

void GpuDeriver::Impl::ensureParticles(Stream& s) {
    if (!carriesParticles) return;
    static_assert(shared::kParticleStateFloats == 4 * shared::kParticleStateVec4s);
    checkRange(s.count, kParticleBytes, "particle state");
    if (!s.particles || s.particles.size() < bytes(s.count, kParticleBytes))
        s.particles = vk::Buffer(ctx, bytes(std::max<uint64_t>(particleCapacity(s), s.count), kParticleBytes),
                                 vk::MemoryUsage::DeviceLocal);
}

const vk::ComputePipeline& GpuDeriver::Impl::stepMatch() {
    bool single = singlePlant(kernels.matchFindsPlants || anyFrozen);
    auto found = matchVariants.find(single);
    if (found == matchVariants.end()) {
        const uint32_t values[] = {VK_FALSE, single ? VK_TRUE : VK_FALSE};
        found = matchVariants.emplace(single, vk::ComputePipeline(ctx, matchSpirv, "derive/match", values)).first;
    }
    return found->second;
}

const vk::ComputePipeline& GpuDeriver::Impl::stepWrite() {
    bool single = singlePlant(kernels.writeFindsPlants);
    auto found = writeVariants.find(single);
    if (found == writeVariants.end()) {
        const uint32_t values[] = {VK_FALSE, single ? VK_TRUE : VK_FALSE};
        found = writeVariants.emplace(single, vk::ComputePipeline(ctx, writeSpirv, "derive/write", values)).first;
    }
    return found->second;
}

} // namespace simeco::gpu
