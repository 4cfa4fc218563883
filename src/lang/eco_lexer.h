// Tokens of SimEco `.eco` scripts, and the cursor the scene and Grow-block parsers walk them with.
#pragma once

#include <string>
#include <vector>

#include "ir/source_loc.h"
#include "lang/source_text.h"

namespace simeco::lang {

enum class EcoTokenKind { Identifier, Number, String, Punct, End };

struct EcoToken {
    EcoTokenKind kind = EcoTokenKind::End;
    std::string text;   // identifier, punctuation, number as written, or string contents without quotes
    double number = 0;  // for Number
    size_t offset = 0;  // byte offset of the first character (the opening quote of a string)
    size_t length = 0;  // bytes, as written
};

// Splits a script into tokens, ending with one End token. `//` starts a comment to the end of the line.
// Throws InputError for an unterminated string, a malformed number or a character that has no use here.
std::vector<EcoToken> lexEco(const std::string& text, const std::string& file);

// Reads tokens front to back and reports problems at their source positions.
class EcoTokenCursor {
public:
    EcoTokenCursor(const std::string& text, std::string file);

    const EcoToken& peek(size_t ahead = 0) const;
    const EcoToken& next();
    const EcoToken& previous() const;
    size_t position() const { return pos_; }

    bool atPunct(const char* punct, size_t ahead = 0) const;
    bool acceptPunct(const char* punct);
    // Consumes `punct` or throws "expected 'punct' <what>, found ...". A missing `;` is reported just after
    // the token before it, where the user has to type it.
    const EcoToken& expectPunct(const char* punct, const std::string& what);
    // Identifiers compare case-insensitively with keywords: scripts write both `EcoSystem` and `Ecosystem`.
    bool atKeyword(const char* keyword, size_t ahead = 0) const;
    bool acceptKeyword(const char* keyword);
    bool atEnd() const { return peek().kind == EcoTokenKind::End; }

    ir::SourceLoc loc(const EcoToken& token) const { return lines_.locate(file_, token.offset); }
    ir::SourceLoc endOf(const EcoToken& token) const { return lines_.locate(file_, token.offset + token.length); }
    const std::string& file() const { return file_; }

    // How a token reads in a message: 'Plant', number 3.5, string "x", end of file.
    static std::string describe(const EcoToken& token);

    [[noreturn]] void failAt(const EcoToken& token, const std::string& message) const;
    [[noreturn]] void failAfter(const EcoToken& token, const std::string& message) const;

private:
    std::string file_;
    LineMap lines_;
    std::vector<EcoToken> tokens_;
    size_t pos_ = 0;
};

bool equalsIgnoreCase(const std::string& a, const char* b);

} // namespace simeco::lang
