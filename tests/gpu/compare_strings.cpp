#include "compare_strings.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <vector>

#include "compute/shared/derive_layout.h"
#include "compute/shared/particle_layout.h"
#include "vk/buffer.h"

namespace simeco::test {

namespace {

bool sameParameter(float want, float got) {
    if (std::isnan(want) || std::isnan(got)) return std::isnan(want) && std::isnan(got);
    if (want == got) return true; // infinities included
    double difference = std::fabs(double{want} - double{got});
    return difference <= 1e-6 || difference <= 1e-5 * std::max(std::fabs(double{want}), std::fabs(double{got}));
}

std::string moduleText(const stream::ModuleString& s, const ir::Alphabet& alphabet, std::size_t i) {
    return stream::formatModules(s, alphabet, i, i + 1);
}

} // namespace

std::string firstDifference(const stream::DeriveResult& want, const stream::DeriveResult& got,
                            const ir::Alphabet& alphabet) {
    std::ostringstream out;
    if (want.steps != got.steps) out << "steps " << got.steps << ", expected " << want.steps << "; ";
    const stream::ModuleString& a = want.string;
    const stream::ModuleString& b = got.string;
    std::size_t common = std::min(a.size(), b.size());
    for (std::size_t i = 0; i < common; ++i) {
        bool same = a.sym[i] == b.sym[i] && a.paramCount[i] == b.paramCount[i];
        for (std::size_t k = 0; same && k < a.paramCount[i]; ++k)
            same = sameParameter(a.paramsOf(i)[k], b.paramsOf(i)[k]);
        if (same) continue;
        std::size_t from = i >= 8 ? i - 8 : 0;
        auto plant = std::upper_bound(a.plantStart.begin(), a.plantStart.end(), std::uint64_t{i});
        out << "module " << i << " of " << a.size() << " (plant " << (plant - a.plantStart.begin() - 1)
            << "): " << moduleText(b, alphabet, i) << ", expected " << moduleText(a, alphabet, i) << " (after \""
            << stream::formatModules(a, alphabet, from, i) << "\"); ";
        break;
    }
    if (a.size() != b.size()) out << "module count " << b.size() << ", expected " << a.size() << "; ";
    if (a.plantStart != b.plantStart) {
        std::size_t p = 0;
        while (p < a.plantStart.size() && p < b.plantStart.size() && a.plantStart[p] == b.plantStart[p])
            ++p;
        out << "plant segment table differs at entry " << p << " (" << b.plantStart.size() << " entries, expected "
            << a.plantStart.size() << "); ";
    }
    return out.str();
}

stream::DeriveResult readModules(const vk::Context& context, const stream::DeviceModules& modules, int steps) {
    stream::DeriveResult result;
    result.steps = steps;
    stream::ModuleString& s = result.string;
    s.stride = int(modules.stride);
    std::vector<std::uint32_t> table =
        vk::downloadVector<std::uint32_t>(context, *modules.plantStarts, modules.plants + 1);
    s.plantStart.assign(table.begin(), table.end());
    const std::uint32_t count = table.back();
    if (count == 0) return result;
    std::vector<std::uint32_t> words = vk::downloadVector<std::uint32_t>(context, *modules.symbols, count);
    s.params = vk::downloadVector<float>(context, *modules.params, std::size_t(count) * modules.stride);
    for (std::size_t i = 0; i < words.size(); ++i) {
        s.sym.push_back(words[i] & shared::kSymbolMask);
        s.paramCount.push_back(static_cast<std::uint8_t>(words[i] >> shared::kSymbolBits));
        for (std::size_t k = s.paramCount.back(); k < modules.stride; ++k) s.params[i * modules.stride + k] = 0.0f;
    }
    if (modules.particles) s.particles = vk::downloadVector<shared::ParticleState>(context, *modules.particles, count);
    return result;
}

} // namespace simeco::test
