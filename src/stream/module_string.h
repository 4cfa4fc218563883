// The module stream: the derived string of one or more plants, as structure of arrays.
//
// Symbols and parameter counts per module, parameters in a fixed stride per grammar (the layout the GPU
// buffers use too), each module's particle state when the derivation carries it, and a segment table that
// says where each plant's modules start.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "compute/shared/particle_layout.h"
#include "ir/grammar.h"

namespace simeco::stream {

struct ModuleString {
    int stride = 1;                     // parameter slots per module
    std::vector<uint32_t> sym;          // symbol ids
    std::vector<uint8_t> paramCount;    // parameters actually present
    std::vector<float> params;          // stride floats per module
    // One per module while the derivation carries particle state (DeriveOptions::particles), else empty.
    std::vector<shared::ParticleState> particles;
    std::vector<uint64_t> plantStart;   // first module of each plant; size = plants + 1

    size_t size() const { return sym.size(); }
    size_t plants() const { return plantStart.empty() ? 0 : plantStart.size() - 1; }
    const float* paramsOf(size_t i) const { return params.data() + i * static_cast<size_t>(stride); }

    void clear() {
        sym.clear();
        paramCount.clear();
        params.clear();
        particles.clear();
        plantStart.clear();
    }
    void reserve(size_t n) {
        sym.reserve(n);
        paramCount.reserve(n);
        params.reserve(n * static_cast<size_t>(stride));
    }
    void push(uint32_t s, const float* p, size_t count) {
        sym.push_back(s);
        paramCount.push_back(static_cast<uint8_t>(count));
        size_t base = params.size();
        params.resize(base + static_cast<size_t>(stride), 0.0f);
        for (size_t k = 0; k < count; ++k) params[base + k] = p[k];
    }
    void pushFrom(const ModuleString& other, size_t i) { push(other.sym[i], other.paramsOf(i), other.paramCount[i]); }
    // Appends modules [begin, end) of `other`, whose stride may be smaller, with their particle state where `other`
    // carries it. The plant table is the caller's.
    void append(const ModuleString& other, size_t begin, size_t end);
};

// cpfg notation: names, parameters as NAME(p1,p2) printed with %.9g, no separators. One plant's
// modules [begin, end).
std::string formatModules(const ModuleString& s, const ir::Alphabet& alphabet, size_t begin, size_t end);

} // namespace simeco::stream
