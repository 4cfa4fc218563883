// A position in preprocessed text, with the small scanning steps the cpfg parsers share.
#pragma once

#include <cctype>
#include <cstring>
#include <string>

#include "lang/cpfg_preprocessor.h"

namespace simeco::lang {

struct TextCursor {
    const PreprocessedText* src = nullptr;
    size_t pos = 0;

    const std::string& text() const { return src->text(); }
    bool atEnd() const { return pos >= text().size(); }
    char peek(size_t ahead = 0) const { return pos + ahead < text().size() ? text()[pos + ahead] : '\0'; }
    ir::SourceLoc loc() const { return src->locate(pos); }
    ir::SourceLoc locAt(size_t offset) const { return src->locate(offset); }

    // Skips spaces and tabs (and newlines too when `newlines`).
    void skipBlanks(bool newlines = false) {
        while (!atEnd()) {
            char c = text()[pos];
            if (c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v' || (newlines && c == '\n')) ++pos;
            else break;
        }
    }
    // Skips blanks and line breaks followed by a tab: cpfg continues a line on the next one when that
    // line starts with a tab, and ends it at any other line break.
    void skipLineBlanks() {
        for (;;) {
            skipBlanks();
            if (peek() == '\n' && peek(1) == '\t') ++pos;
            else break;
        }
    }
    bool startsWith(const char* s) const { return text().compare(pos, std::strlen(s), s) == 0; }
    bool eat(const char* s) {
        if (!startsWith(s)) return false;
        pos += std::strlen(s);
        return true;
    }
    [[noreturn]] void fail(const std::string& message) const { throw ir::InputError(loc(), message); }
    [[noreturn]] void failAt(size_t offset, const std::string& message) const {
        throw ir::InputError(locAt(offset), message);
    }
};

inline bool isIdentStartChar(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
inline bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

} // namespace simeco::lang
