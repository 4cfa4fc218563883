#include "ir/source_loc.h"

#include <fmt/format.h>

namespace simeco::ir {

std::string InputError::formatted() const {
    std::string file = loc_.file.empty() ? "<input>" : loc_.file;
    if (loc_.line <= 0) return fmt::format("{}: error: {}", file, what());
    return fmt::format("{}:{}:{}: error: {}", file, loc_.line, std::max(loc_.col, 1), what());
}

} // namespace simeco::ir
