#include "ir/grammar.h"

namespace simeco::ir {

Alphabet::Alphabet() {
    intern("[");
    intern("]");
    intern("%");
}

SymbolId Alphabet::intern(const std::string& name, uint32_t space) {
    std::string key = space == 0 ? name : name + '\x1f' + std::to_string(space);
    auto it = ids_.find(key);
    if (it != ids_.end()) return it->second;
    SymbolId id = static_cast<SymbolId>(names_.size());
    auto first = firstByName_.emplace(name, id).first;
    names_.push_back(name);
    spaces_.push_back(space);
    canonical_.push_back(first->second);
    if (space != 0) hasSpaces_ = true;
    ids_.emplace(std::move(key), id);
    return id;
}

std::optional<SymbolId> Alphabet::find(const std::string& name) const {
    auto it = ids_.find(name);
    if (it == ids_.end()) return std::nullopt;
    return it->second;
}

} // namespace simeco::ir
