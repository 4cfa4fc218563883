#include "lang/quick_grammar.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <vector>

#include <fmt/format.h>

#include "lang/source_text.h"

namespace simeco::lang {

namespace {

// A character with its byte offset in the whole text, for error positions.
struct Char {
    char c;
    size_t offset;
};

// The arrow of a rule: `=`, `->` or `→`.
struct Arrow {
    size_t pos = std::string::npos; // in the line
    size_t length = 0;
};

constexpr const char* kUnicodeArrow = "\xe2\x86\x92"; // →
constexpr const char* kDegreeSign = "\xc2\xb0";       // °
// Without an `angle:` line turns are right angles, the first example most lessons draw.
constexpr float kDefaultAngle = 90.0f;

class QuickParser {
public:
    QuickParser(const std::string& text, const std::string& file) : text_(text), file_(file), lines_(text) {}

    ir::Grammar run() {
        grammar_.sourceFile = file_;
        // The engines keep cpfg's step counters in the first global slots, whatever the language.
        grammar_.globalNames = {"Q", "Z"};
        grammar_.globalInit = {0.0f, 0.0f};
        size_t start = 0;
        while (start <= text_.size()) {
            size_t end = text_.find('\n', start);
            if (end == std::string::npos) end = text_.size();
            line(start, end);
            start = end + 1;
        }
        if (!axiomLine_) fail(0, "missing axiom (add a line such as `axiom: X`)");
        if (!iterationsLine_) fail(0, "missing iteration count (add a line such as `iterations: 5`)");
        if (!angleLine_) grammar_.view.angleIncrement = kDefaultAngle;
        grammar_.view.present = true;
        grammar_.productions.present = !grammar_.productions.productions.empty();
        grammar_.contextSkip.resize(grammar_.alphabet.size(), false);
        for (ir::SymbolId s : ignored_) grammar_.contextSkip[s] = true;
        return std::move(grammar_);
    }

private:
    [[noreturn]] void fail(size_t offset, const std::string& message) const {
        throw ir::InputError(lines_.locate(file_, offset), message);
    }

    static bool blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

    void line(size_t begin, size_t end) {
        size_t p = begin;
        while (p < end && blank(text_[p])) ++p;
        if (p == end || text_[p] == '#') return;

        // `word:` starts a setting; one-letter words are modules (`F:0.5` is not a setting).
        size_t word = p;
        while (word < end && std::isalpha(static_cast<unsigned char>(text_[word]))) ++word;
        size_t colon = word;
        while (colon < end && blank(text_[colon])) ++colon;
        if (word - p > 1 && colon < end && text_[colon] == ':') {
            setting(text_.substr(p, word - p), p, colon + 1, end);
            return;
        }
        rule(p, end);
    }

    // ---- settings ----

    void setting(std::string key, size_t keyOffset, size_t valueBegin, size_t end) {
        for (char& c : key) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        size_t v = valueBegin;
        while (v < end && blank(text_[v])) ++v;
        size_t e = end;
        while (e > v && blank(text_[e - 1])) --e;
        std::string value = text_.substr(v, e - v);
        int lineNo = lines_.locate(file_, keyOffset).line;

        auto once = [&](std::optional<int>& seenAt, const char* name) {
            if (seenAt) fail(keyOffset, fmt::format("{} given twice (first at line {})", name, *seenAt));
            seenAt = lineNo;
        };
        if (key == "axiom" || key == "premise") {
            once(axiomLine_, "axiom");
            if (value.empty()) fail(v, "empty axiom");
            grammar_.axiomLoc = lines_.locate(file_, v);
            for (const ParsedModule& m : modules(v, e, "the axiom")) grammar_.axiom.push_back(successorModule(m));
        } else if (key == "angle") {
            once(angleLine_, "angle");
            std::string digits = value;
            if (digits.size() >= 2 && digits.compare(digits.size() - 2, 2, kDegreeSign) == 0)
                digits.erase(digits.size() - 2);
            grammar_.view.angleIncrement = number(digits, v, "angle");
        } else if (key == "iterations" || key == "generations") {
            once(iterationsLine_, "iteration count");
            if (value.empty() || value.find_first_not_of("0123456789") != std::string::npos || value.size() > 7)
                fail(v, fmt::format("the iteration count is a whole number, found '{}'", value));
            grammar_.derivationLength = std::atoi(value.c_str());
        } else if (key == "step") {
            once(stepLine_, "step");
            grammar_.view.stepSize = number(value, v, "step");
        } else if (key == "ignore") {
            once(ignoreLine_, "ignore");
            for (size_t i = v; i < e; ++i) {
                if (blank(text_[i])) continue;
                checkModuleChar(i);
                ignored_.push_back(grammar_.symbol(std::string(1, text_[i])));
            }
        } else {
            fail(keyOffset, fmt::format("unknown setting '{}' (expected axiom, angle, iterations, step or ignore)",
                                        key));
        }
    }

    float number(const std::string& value, size_t offset, const char* what) {
        char* stop = nullptr;
        float x = std::strtof(value.c_str(), &stop);
        if (value.empty() || *stop != '\0' || !std::isfinite(x))
            fail(offset, fmt::format("bad number '{}' for {}", value, what));
        return x;
    }

    // ---- rules ----

    Arrow findArrow(size_t begin, size_t end) const {
        for (size_t i = begin; i < end; ++i) {
            if (text_[i] == '=') return {i, 1};
            if (text_[i] == '-' && i + 1 < end && text_[i + 1] == '>') return {i, 2};
            if (text_.compare(i, 3, kUnicodeArrow) == 0 && i + 3 <= end) return {i, 3};
        }
        return {};
    }

    void rule(size_t begin, size_t end) {
        Arrow arrow = findArrow(begin, end);
        if (arrow.pos == std::string::npos)
            fail(begin, "expected a rule such as `F = FF` or a setting such as `axiom: F`");

        // Predecessor side: [left <] strict [> right].
        std::vector<Char> lhs;
        for (size_t i = begin; i < arrow.pos; ++i)
            if (!blank(text_[i])) lhs.push_back({text_[i], i});
        if (lhs.empty()) fail(arrow.pos, "rule without a predecessor before the arrow");
        std::vector<Char> left, strict, right;
        std::vector<Char>* part = &strict;
        bool sawLeft = false, sawRight = false;
        for (const Char& ch : lhs) {
            if (ch.c == '<' && !sawLeft && !sawRight && part->size() > 0) {
                left = std::move(strict);
                strict.clear();
                sawLeft = true;
            } else if (ch.c == '>' && !sawRight && !strict.empty()) {
                part = &right;
                sawRight = true;
            } else if (ch.c == ':') {
                fail(ch.offset, "conditions (`pred : cond = succ`) are not supported in quick grammars; use a .l "
                                "file");
            } else if (ch.c == '(') {
                fail(ch.offset, "a predecessor has no parameters in quick grammars; use a .l file");
            } else {
                part->push_back(ch);
            }
        }
        if (strict.empty()) fail(arrow.pos, "rule without a predecessor before the arrow");
        if (strict.size() > 1)
            fail(strict[1].offset, "a predecessor is one module (write contexts as `left < F > right`)");
        if (sawRight && right.empty()) fail(arrow.pos, "missing right context after '>'");
        for (const std::vector<Char>* ctx : {&left, &strict, &right}) {
            for (const Char& ch : *ctx) {
                if (ch.c == '[' || ch.c == ']')
                    fail(ch.offset, "brackets cannot appear in a predecessor or its contexts");
                checkModuleChar(ch.offset);
            }
        }

        ir::Production p;
        p.loc = lines_.locate(file_, begin);
        auto pattern = [&](const Char& ch) {
            return ir::PatternModule{grammar_.symbol(std::string(1, ch.c)), {}, lines_.locate(file_, ch.offset)};
        };
        for (const Char& ch : left) p.left.push_back(pattern(ch));
        p.strict.push_back(pattern(strict[0]));
        for (const Char& ch : right) p.right.push_back(pattern(ch));

        // Successor side: modules [: probability].
        size_t succBegin = arrow.pos + arrow.length;
        size_t succEnd = end;
        size_t colon = text_.find(':', succBegin);
        if (colon != std::string::npos && colon < end) {
            succEnd = colon;
            size_t v = colon + 1;
            while (v < end && blank(text_[v])) ++v;
            size_t e = end;
            while (e > v && blank(text_[e - 1])) --e;
            std::string value = text_.substr(v, e - v);
            float weight = number(value, v, "the probability");
            if (weight < 0.0f || weight > 1.0f)
                fail(v, fmt::format("a probability is between 0 and 1, found {}", value));
            p.weight = weight;
        }
        ir::Alternative alt;
        for (const ParsedModule& m : modules(succBegin, succEnd, "the successor"))
            alt.modules.push_back(successorModule(m));
        p.alternatives.push_back(std::move(alt));
        grammar_.productions.productions.push_back(std::move(p));
    }

    void checkModuleChar(size_t offset) const {
        unsigned char c = static_cast<unsigned char>(text_[offset]);
        if (c >= 0x80) {
            if (text_.compare(offset, 3, kUnicodeArrow) == 0) fail(offset, "a rule has one arrow");
            fail(offset, "unexpected non-ASCII character (modules are single ASCII characters)");
        }
        if (!std::isprint(c)) fail(offset, fmt::format("unexpected control character 0x{:02x}", c));
        if (c == '=' || c == ',' || c == ')' || c == ':' || c == '(')
            fail(offset, fmt::format("unexpected '{}'", static_cast<char>(c)));
    }

    struct ParsedModule {
        ir::SymbolId sym;
        std::vector<float> params;
        ir::SourceLoc loc;
    };

    static ir::SuccessorModule successorModule(const ParsedModule& m) {
        ir::SuccessorModule module;
        module.sym = m.sym;
        for (float x : m.params) module.args.push_back(ir::Expr::constant(x, m.loc));
        module.loc = m.loc;
        return module;
    }

    // One module per character, `(n, ...)` after a module gives it parameters; brackets must balance.
    std::vector<ParsedModule> modules(size_t begin, size_t end, const char* where) {
        std::vector<ParsedModule> out;
        std::vector<size_t> open;
        for (size_t i = begin; i < end; ++i) {
            char c = text_[i];
            if (blank(c)) continue;
            if (c == '(') {
                if (out.empty() || out.back().sym == ir::kBranchOpen || out.back().sym == ir::kBranchClose)
                    fail(i, "'(' must follow a module, as in F(0.5)");
                if (!out.back().params.empty()) fail(i, "a module has one parameter list");
                i = parameters(i, end, out.back().params);
                continue;
            }
            if (c == '=' || (c == '-' && i + 1 < end && text_[i + 1] == '>'))
                fail(i, "a rule has one arrow");
            checkModuleChar(i);
            ir::SymbolId sym = grammar_.symbol(std::string(1, c));
            if (sym == ir::kBranchOpen) open.push_back(i);
            if (sym == ir::kBranchClose) {
                if (open.empty()) fail(i, "']' without a matching '['");
                open.pop_back();
            }
            out.push_back({sym, {}, lines_.locate(file_, i)});
        }
        if (!open.empty()) fail(open.back(), fmt::format("'[' is never closed in {}", where));
        return out;
    }

    // Numbers separated by commas up to `)`; returns the offset of the `)`.
    size_t parameters(size_t open, size_t end, std::vector<float>& params) {
        size_t close = text_.find(')', open);
        if (close == std::string::npos || close >= end) fail(open, "'(' is never closed");
        size_t start = open + 1;
        for (;;) {
            size_t comma = text_.find(',', start);
            size_t stop = (comma == std::string::npos || comma > close) ? close : comma;
            size_t v = start;
            while (v < stop && blank(text_[v])) ++v;
            size_t e = stop;
            while (e > v && blank(text_[e - 1])) --e;
            params.push_back(number(text_.substr(v, e - v), v, "a module parameter"));
            if (stop == close) break;
            start = stop + 1;
        }
        return close;
    }

    const std::string& text_;
    const std::string& file_;
    LineMap lines_;
    ir::Grammar grammar_;
    std::optional<int> axiomLine_, angleLine_, iterationsLine_, stepLine_, ignoreLine_;
    std::vector<ir::SymbolId> ignored_;
};

} // namespace

ir::Grammar parseQuickGrammar(const std::string& text, const std::string& file) {
    requireText(text, file);
    return QuickParser(text, file).run();
}

ir::Grammar parseQuickGrammarFile(const std::string& path) {
    std::string text = readSourceFile(path);
    return parseQuickGrammar(text, path);
}

} // namespace simeco::lang
