#include "lang/source_text.h"

#include <algorithm>
#include <fstream>
#include <sstream>

#include <fmt/format.h>

namespace simeco::lang {

namespace {

// Length of the UTF-8 sequence starting at text[i], or 0 when it is not valid UTF-8.
size_t utf8SequenceLength(const std::string& text, size_t i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : (c >> 3) == 0x1e ? 4 : 0;
    if (len == 0 || i + len > text.size()) return 0;
    for (size_t k = 1; k < len; ++k)
        if ((static_cast<unsigned char>(text[i + k]) >> 6) != 0x2) return 0;
    return len;
}

} // namespace

void requireText(const std::string& text, const std::string& file) {
    LineMap lines(text);
    for (size_t i = 0; i < text.size();) {
        size_t len = utf8SequenceLength(text, i);
        if (text[i] == '\0' || len == 0)
            throw ir::InputError(lines.locate(file, i), fmt::format("file is not text (byte 0x{:02x})",
                                                                         static_cast<unsigned char>(text[i])));
        i += len;
    }
}

std::string readSourceFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ir::InputError({path, 0, 0}, "cannot open file");
    std::ostringstream buffer;
    buffer << in.rdbuf();
    if (in.bad()) throw ir::InputError({path, 0, 0}, "cannot read file");
    std::string text = buffer.str();
    requireText(text, path);
    // Line ends of every kind: a lone CR (classic Mac OS) ends a line as LF does; CR LF stays, the CR then
    // being white space. The text keeps its length, so columns stay where they were.
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')) text[i] = '\n';
    return text;
}

LineMap::LineMap(const std::string& text) {
    lineStarts_.push_back(0);
    for (size_t i = 0; i < text.size(); ++i)
        if (text[i] == '\n') lineStarts_.push_back(i + 1);
}

ir::SourceLoc LineMap::locate(const std::string& file, size_t offset) const {
    if (lineStarts_.empty()) return {file, 1, static_cast<int>(offset) + 1};
    auto it = std::upper_bound(lineStarts_.begin(), lineStarts_.end(), offset);
    size_t line = static_cast<size_t>(it - lineStarts_.begin());
    return {file, static_cast<int>(line), static_cast<int>(offset - lineStarts_[line - 1]) + 1};
}

} // namespace simeco::lang
