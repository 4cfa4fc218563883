#include "lang/eco_lexer.h"

#include <cctype>
#include <cstdlib>
#include <cstring>
#include <limits>

#include <fmt/format.h>

namespace simeco::lang {

namespace {

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentPart(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
bool isDigit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

// Longest first, so that `->` is not read as `-` `>`.
constexpr const char* kPuncts[] = {"->", "<=", ">=", "==", "!=", "&&", "||", "{", "}", "(", ")", "[", "]",
                                   ";",  ",",  "=",  "|",  "<",  ">",  "+",  "-",  "*", "/", "!", "%", ":"};

class Lexer {
public:
    Lexer(const std::string& text, const std::string& file) : text_(text), file_(file), lines_(text) {}

    std::vector<EcoToken> run() {
        std::vector<EcoToken> tokens;
        for (;;) {
            skipSpaceAndComments();
            if (pos_ >= text_.size()) break;
            tokens.push_back(token());
        }
        EcoToken end;
        end.offset = text_.size();
        tokens.push_back(end);
        return tokens;
    }

private:
    char at(size_t i) const { return i < text_.size() ? text_[i] : '\0'; }

    [[noreturn]] void fail(size_t offset, const std::string& message) const {
        throw ir::InputError(lines_.locate(file_, offset), message);
    }

    void skipSpaceAndComments() {
        while (pos_ < text_.size()) {
            char c = text_[pos_];
            if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v') {
                ++pos_;
            } else if (c == '/' && at(pos_ + 1) == '/') {
                while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
            } else {
                break;
            }
        }
    }

    EcoToken token() {
        EcoToken t;
        t.offset = pos_;
        char c = text_[pos_];
        if (isIdentStart(c)) {
            while (isIdentPart(at(pos_))) ++pos_;
            t.kind = EcoTokenKind::Identifier;
            t.text = text_.substr(t.offset, pos_ - t.offset);
        } else if (isDigit(c) || (c == '.' && isDigit(at(pos_ + 1)))) {
            number(t);
        } else if (c == '"') {
            string(t);
        } else {
            for (const char* p : kPuncts) {
                if (text_.compare(pos_, std::strlen(p), p) == 0) {
                    t.kind = EcoTokenKind::Punct;
                    t.text = p;
                    pos_ += t.text.size();
                    t.length = t.text.size();
                    return t;
                }
            }
            unexpectedCharacter();
        }
        t.length = pos_ - t.offset;
        return t;
    }

    // digits [. digits] [e [+-] digits]; anything glued to it (`1.2.3`, `12abc`, `1.`) makes it bad.
    void number(EcoToken& t) {
        size_t start = pos_;
        bool ok = isDigit(at(pos_));
        while (isDigit(at(pos_))) ++pos_;
        if (at(pos_) == '.') {
            ++pos_;
            if (!isDigit(at(pos_))) ok = false;
            while (isDigit(at(pos_))) ++pos_;
        }
        if ((at(pos_) == 'e' || at(pos_) == 'E') &&
            (isDigit(at(pos_ + 1)) || ((at(pos_ + 1) == '+' || at(pos_ + 1) == '-') && isDigit(at(pos_ + 2))))) {
            pos_ += 2;
            while (isDigit(at(pos_))) ++pos_;
        }
        if (isIdentPart(at(pos_)) || at(pos_) == '.') ok = false;
        if (!ok) {
            while (isIdentPart(at(pos_)) || at(pos_) == '.') ++pos_;
            fail(start, fmt::format("bad number '{}'", text_.substr(start, pos_ - start)));
        }
        t.kind = EcoTokenKind::Number;
        t.text = text_.substr(start, pos_ - start);
        t.number = std::strtod(t.text.c_str(), nullptr);
        // Scene values are floats: a larger number would become infinite and reach the geometry.
        if (!(t.number <= std::numeric_limits<float>::max()))
            fail(start, fmt::format("number '{}' is beyond the largest a scene holds ({:g})", t.text,
                                    std::numeric_limits<float>::max()));
    }

    // Names may hold any character but a quote or a line break (model files have Chinese names).
    void string(EcoToken& t) {
        size_t start = pos_++;
        while (pos_ < text_.size() && text_[pos_] != '"' && text_[pos_] != '\n') ++pos_;
        if (pos_ >= text_.size() || text_[pos_] != '"') fail(start, "unterminated string (a string ends on its line)");
        t.kind = EcoTokenKind::String;
        t.text = text_.substr(start + 1, pos_ - start - 1);
        ++pos_;
    }

    [[noreturn]] void unexpectedCharacter() const {
        unsigned char c = static_cast<unsigned char>(text_[pos_]);
        if (c >= 0x80) {
            size_t end = pos_ + 1;
            while (end < text_.size() && (static_cast<unsigned char>(text_[end]) & 0xc0) == 0x80) ++end;
            fail(pos_, fmt::format("unexpected character '{}' outside a string", text_.substr(pos_, end - pos_)));
        }
        if (std::isprint(c)) fail(pos_, fmt::format("unexpected character '{}'", static_cast<char>(c)));
        fail(pos_, fmt::format("unexpected control character 0x{:02x}", c));
    }

    const std::string& text_;
    const std::string& file_;
    LineMap lines_;
    size_t pos_ = 0;
};

} // namespace

bool equalsIgnoreCase(const std::string& a, const char* b) {
    size_t n = std::strlen(b);
    if (a.size() != n) return false;
    for (size_t i = 0; i < n; ++i)
        if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i])))
            return false;
    return true;
}

std::vector<EcoToken> lexEco(const std::string& text, const std::string& file) { return Lexer(text, file).run(); }

EcoTokenCursor::EcoTokenCursor(const std::string& text, std::string file)
    : file_(std::move(file)), lines_(text), tokens_(lexEco(text, file_)) {}

const EcoToken& EcoTokenCursor::peek(size_t ahead) const {
    size_t i = pos_ + ahead;
    return i < tokens_.size() ? tokens_[i] : tokens_.back();
}

const EcoToken& EcoTokenCursor::next() {
    const EcoToken& t = peek();
    if (pos_ + 1 < tokens_.size()) ++pos_;
    return t;
}

const EcoToken& EcoTokenCursor::previous() const { return tokens_[pos_ > 0 ? pos_ - 1 : 0]; }

bool EcoTokenCursor::atPunct(const char* punct, size_t ahead) const {
    const EcoToken& t = peek(ahead);
    return t.kind == EcoTokenKind::Punct && t.text == punct;
}

bool EcoTokenCursor::acceptPunct(const char* punct) {
    if (!atPunct(punct)) return false;
    next();
    return true;
}

const EcoToken& EcoTokenCursor::expectPunct(const char* punct, const std::string& what) {
    if (atPunct(punct)) return next();
    std::string message = fmt::format("expected '{}' {}, found {}", punct, what, describe(peek()));
    if (std::strcmp(punct, ";") == 0 && pos_ > 0) failAfter(previous(), message);
    failAt(peek(), message);
}

bool EcoTokenCursor::atKeyword(const char* keyword, size_t ahead) const {
    const EcoToken& t = peek(ahead);
    return t.kind == EcoTokenKind::Identifier && equalsIgnoreCase(t.text, keyword);
}

bool EcoTokenCursor::acceptKeyword(const char* keyword) {
    if (!atKeyword(keyword)) return false;
    next();
    return true;
}

std::string EcoTokenCursor::describe(const EcoToken& token) {
    switch (token.kind) {
    case EcoTokenKind::Identifier:
    case EcoTokenKind::Punct: return fmt::format("'{}'", token.text);
    case EcoTokenKind::Number: return fmt::format("number {}", token.text);
    case EcoTokenKind::String: return fmt::format("string \"{}\"", token.text);
    case EcoTokenKind::End: return "end of file";
    }
    return "?";
}

void EcoTokenCursor::failAt(const EcoToken& token, const std::string& message) const {
    throw ir::InputError(loc(token), message);
}

void EcoTokenCursor::failAfter(const EcoToken& token, const std::string& message) const {
    throw ir::InputError(endOf(token), message);
}

} // namespace simeco::lang
