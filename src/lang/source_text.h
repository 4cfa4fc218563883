// Reading user files as text, refusing what is not text, and mapping offsets to line and column.
#pragma once

#include <string>
#include <vector>

#include "ir/source_loc.h"

namespace simeco::lang {

// The whole file as text. Throws InputError for a missing or unreadable file and for binary content
// (NUL bytes or invalid UTF-8), pointing at the first offending byte.
std::string readSourceFile(const std::string& path);

// Checks that `text` is text (see readSourceFile); `file` names it in the error.
void requireText(const std::string& text, const std::string& file);

// Line and column (1-based, columns counted in bytes) of byte offsets in a text.
class LineMap {
public:
    LineMap() = default;
    explicit LineMap(const std::string& text);
    ir::SourceLoc locate(const std::string& file, size_t offset) const;

private:
    std::vector<size_t> lineStarts_;
};

} // namespace simeco::lang
