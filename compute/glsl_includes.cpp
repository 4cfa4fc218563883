// glslSource(): a run-time kernel's GLSL parts with their includes inlined, since the kernels generated per
// grammar are compiled from one text without an include path.
#include <set>
#include <stdexcept>
#include <string>

#include "compute/shaders.h"

namespace simeco::shaders {

namespace {

void appendInlined(std::string_view name, std::set<std::string, std::less<>>& seen, std::string& out) {
    if (seen.count(name)) return;
    seen.emplace(name);
    std::optional<std::string_view> text = embeddedGlslText(name);
    if (!text) throw std::out_of_range("no embedded GLSL source " + std::string(name));
    constexpr std::string_view kInclude = "#include \"";
    for (size_t at = 0; at < text->size();) {
        size_t end = text->find('\n', at);
        end = end == std::string_view::npos ? text->size() : end + 1;
        std::string_view line = text->substr(at, end - at);
        size_t close = line.find('"', kInclude.size());
        if (line.starts_with(kInclude) && close != std::string_view::npos)
            appendInlined(line.substr(kInclude.size(), close - kInclude.size()), seen, out);
        else
            out.append(line);
        at = end;
    }
}

} // namespace

std::string glslSource(std::string_view name) {
    std::set<std::string, std::less<>> seen;
    std::string out;
    appendInlined(name, seen, out);
    return out;
}

} // namespace simeco::shaders
