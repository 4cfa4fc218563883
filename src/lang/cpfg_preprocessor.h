// The C-preprocessor subset that cpfg runs over `.l` files before reading them.
//
// cpfg passes L-system files through cpp, so real models rely on `#define` (object- and function-like),
// `#if/#ifdef/#ifndef/#elif/#else/#endif`, `#undef`, `#include "file"`, comments and backslash-continued
// lines. This pass does the same and remembers, for every output character, where it came from, so errors
// in expanded text still point at the user's file, line and column.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "ir/source_loc.h"

namespace simeco::lang {

class PreprocessedText {
public:
    const std::string& text() const { return text_; }
    ir::SourceLoc locate(size_t offset) const;
    size_t size() const { return text_.size(); }

    // Appends one character that came from `file` (index into files()) at line:col.
    void append(char c, uint32_t file, uint32_t line, uint32_t col);
    uint32_t addFile(const std::string& path);

private:
    struct Origin {
        uint32_t file, line, col;
    };
    std::string text_;
    std::vector<Origin> origins_;
    std::vector<std::string> files_;
};

// Macros defined before the file is read (cpfg defines one per named function of the view file).
using PredefinedMacros = std::map<std::string, std::string>;

// Preprocesses the file at `path`. Throws InputError on a malformed directive, an unterminated comment or
// conditional, an unknown include, a wrong macro argument count, or a macro that refers to itself.
PreprocessedText preprocessFile(const std::string& path, const PredefinedMacros& predefined);
PreprocessedText preprocessText(const std::string& text, const std::string& file,
                                const PredefinedMacros& predefined);

} // namespace simeco::lang
