#include "stream/module_string.h"

#include <cmath>
#include <cstdio>

namespace simeco::stream {

void ModuleString::append(const ModuleString& other, size_t begin, size_t end) {
    if (other.stride == stride) {
        sym.insert(sym.end(), other.sym.begin() + begin, other.sym.begin() + end);
        paramCount.insert(paramCount.end(), other.paramCount.begin() + begin, other.paramCount.begin() + end);
        const size_t width = size_t(stride);
        params.insert(params.end(), other.params.begin() + begin * width, other.params.begin() + end * width);
    } else {
        reserve(size() + (end - begin));
        for (size_t i = begin; i < end; ++i) pushFrom(other, i);
    }
    if (!other.particles.empty())
        particles.insert(particles.end(), other.particles.begin() + begin, other.particles.begin() + end);
}

std::string formatModules(const ModuleString& s, const ir::Alphabet& alphabet, size_t begin, size_t end) {
    std::string out;
    out.reserve((end - begin) * 2);
    char buffer[32];
    for (size_t i = begin; i < end; ++i) {
        out += alphabet.name(s.sym[i]);
        size_t count = s.paramCount[i];
        if (count == 0) continue;
        out.push_back('(');
        const float* p = s.paramsOf(i);
        for (size_t k = 0; k < count; ++k) {
            if (k) out.push_back(',');
            if (std::isnan(p[k])) {
                out += "nan"; // whatever its sign bit, which devices set differently
                continue;
            }
            std::snprintf(buffer, sizeof buffer, "%.9g", static_cast<double>(p[k]));
            out += buffer;
        }
        out.push_back(')');
    }
    return out;
}

} // namespace simeco::stream
