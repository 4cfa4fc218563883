#include "ir/grammar.h"

namespace simeco::ir {

Alphabet::Alphabet() {
    intern("[");
    intern("]");
    intern("%");
}

SymbolId Alphabet::intern(const std::string& name) {
    auto it = ids_.find(name);
    if (it != ids_.end()) return it->second;
    SymbolId id = static_cast<SymbolId>(names_.size());
    names_.push_back(name);
    ids_.emplace(name, id);
    return id;
}

std::optional<SymbolId> Alphabet::find(const std::string& name) const {
    auto it = ids_.find(name);
    if (it == ids_.end()) return std::nullopt;
    return it->second;
}

} // namespace simeco::ir
