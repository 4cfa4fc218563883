#include "stream/derive_options.h"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>
#include <unistd.h>

#include "ir/species.h"

namespace simeco::stream {

namespace {

uint64_t parameterBytes(int stride) { return sizeof(float) * uint64_t(std::max(stride, 1)); }

} // namespace

uint64_t cpuBytesPerModule(int stride) {
    return 2 * (sizeof(uint32_t) + sizeof(uint8_t) + parameterBytes(stride)) * 3 / 2 + 5;
}

uint64_t deviceBytesPerModule(int stride, bool particles) {
    uint64_t perStream = 3 * sizeof(uint32_t) + parameterBytes(stride) +
                         (particles ? sizeof(float) * shared::kParticleStateFloats : 0);
    uint64_t streams = 3 * perStream;
    uint64_t scratch = 7 * sizeof(uint32_t);
    return (streams + scratch) * 3 / 2;
}

uint64_t hostBytesPerDeviceModule(int stride) { return 2 * (sizeof(uint32_t) + parameterBytes(stride)) + 1; }

uint64_t hostMemoryBytes() {
    long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
    return (pages > 0 && pageSize > 0) ? uint64_t(pages) * uint64_t(pageSize) : (8ull << 30);
}

uint64_t defaultModuleBudget(int stride) { return hostMemoryBytes() / 4 / cpuBytesPerModule(stride); }

ir::LimitError moduleBudgetExceeded(uint64_t budget, int step) {
    return ir::LimitError(fmt::format("the string outgrew the module budget of {} modules in step {} "
                                      "(raise it with --max-modules, or derive fewer steps or plants)",
                                      budget, step));
}

std::vector<std::vector<shared::ParticleState>> splitAxiomParticles(const std::vector<ir::Grammar>& species,
                                                                    uint32_t plants, const DeriveOptions& options) {
    const std::vector<shared::ParticleState>& initial = options.initialParticles;
    std::vector<std::vector<shared::ParticleState>> perPlant(plants);
    size_t total = 0;
    for (uint32_t plant = 0; plant < plants; ++plant) {
        if (options.isAbsent(plant)) continue;
        perPlant[plant].resize(species[ir::speciesOfPlant(plant, species.size())].axiom.size());
        total += perPlant[plant].size();
    }
    if (initial.empty()) return perPlant;
    if (initial.size() != total)
        throw std::invalid_argument(
            fmt::format("{} initial particle states for {} axiom modules", initial.size(), total));
    auto next = initial.begin();
    for (std::vector<shared::ParticleState>& states : perPlant) {
        std::copy_n(next, states.size(), states.begin());
        next += static_cast<std::ptrdiff_t>(states.size());
    }
    return perPlant;
}

} // namespace simeco::stream
