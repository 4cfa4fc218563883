#include "lang/cpfg_preprocessor.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <optional>
#include <set>

#include <fmt/format.h>

#include "lang/source_text.h"

namespace simeco::lang {

ir::SourceLoc PreprocessedText::locate(size_t offset) const {
    if (origins_.empty()) return {files_.empty() ? std::string() : files_[0], 1, 1};
    const Origin& o = origins_[std::min(offset, origins_.size() - 1)];
    ir::SourceLoc loc{files_[o.file], static_cast<int>(o.line), static_cast<int>(o.col)};
    if (offset >= origins_.size()) loc.col += 1; // just past the end of the text
    return loc;
}

void PreprocessedText::append(char c, uint32_t file, uint32_t line, uint32_t col) {
    text_.push_back(c);
    origins_.push_back({file, line, col});
}

uint32_t PreprocessedText::addFile(const std::string& path) {
    files_.push_back(path);
    return static_cast<uint32_t>(files_.size() - 1);
}

namespace {

struct Char {
    char c;
    uint32_t file, line, col;
};
using Chars = std::vector<Char>;

bool isIdentStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool isIdentChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

struct Macro {
    bool functionLike = false;
    std::vector<std::string> params;
    Chars body;
};

constexpr int kMaxIncludeDepth = 16;
// The most characters a file may become after macro expansion, in all and of one expansion: far above any
// model's (tens of kilobytes), low enough that exponential macro growth stops in about a second and 200 MB.
constexpr size_t kMaxExpandedSize = 8u << 20;

class Preprocessor {
public:
    Preprocessor(PreprocessedText& out, const PredefinedMacros& predefined) : out_(out) {
        for (const auto& [name, value] : predefined) {
            Macro m;
            for (char c : value) m.body.push_back({c, 0, 0, 0});
            macros_[name] = std::move(m);
        }
    }

    void run(const std::string& text, const std::string& path, int depth) {
        if (depth > kMaxIncludeDepth) throw ir::InputError({path, 0, 0}, "#include nested too deeply");
        requireText(text, path);
        uint32_t file = out_.addFile(path);
        Chars chars = stripComments(spliceLines(load(text, file, path)), path);
        processLines(chars, path, depth);
    }

private:
    PreprocessedText& out_;
    std::map<std::string, Macro> macros_;

    std::string fileName(uint32_t index) const {
        return index < fileNames_.size() ? fileNames_[index] : std::string();
    }
    std::vector<std::string> fileNames_;

    Chars load(const std::string& text, uint32_t file, const std::string& path) {
        if (fileNames_.size() <= file) fileNames_.resize(file + 1);
        fileNames_[file] = path;
        Chars chars;
        chars.reserve(text.size() + 1);
        uint32_t line = 1, col = 1;
        for (char c : text) {
            if (c == '\r') continue;
            chars.push_back({c, file, line, col});
            if (c == '\n') {
                ++line;
                col = 1;
            } else {
                ++col;
            }
        }
        if (chars.empty() || chars.back().c != '\n') chars.push_back({'\n', file, line, col});
        return chars;
    }
    static Chars spliceLines(const Chars& in) {
        Chars out;
        out.reserve(in.size());
        for (size_t i = 0; i < in.size(); ++i) {
            // cpfg's preprocessor also continues a line that ends in `\\`, which real models rely on.
            size_t j = i;
            while (j < in.size() && in[j].c == '\\') ++j;
            if (j > i && j < in.size() && in[j].c == '\n') {
                i = j;
                continue;
            }
            out.push_back(in[i]);
        }
        return out;
    }

    // Comments become one space; newlines inside block comments are kept so lines stay lines.
    Chars stripComments(const Chars& in, const std::string& path) const {
        Chars out;
        out.reserve(in.size());
        for (size_t i = 0; i < in.size(); ++i) {
            char c = in[i].c;
            if (c == '"') {
                size_t j = i;
                out.push_back(in[j++]);
                while (j < in.size() && in[j].c != '"' && in[j].c != '\n') out.push_back(in[j++]);
                if (j >= in.size() || in[j].c != '"')
                    throw ir::InputError({path, int(in[i].line), int(in[i].col)}, "unterminated string literal");
                out.push_back(in[j]);
                i = j;
            } else if (c == '/' && i + 1 < in.size() && in[i + 1].c == '*') {
                size_t j = i + 2;
                out.push_back({' ', in[i].file, in[i].line, in[i].col});
                while (j + 1 < in.size() && !(in[j].c == '*' && in[j + 1].c == '/')) {
                    if (in[j].c == '\n') out.push_back(in[j]);
                    ++j;
                }
                if (j + 1 >= in.size())
                    throw ir::InputError({path, int(in[i].line), int(in[i].col)}, "unterminated comment");
                i = j + 1;
            } else if (c == '/' && i + 1 < in.size() && in[i + 1].c == '/') {
                out.push_back({' ', in[i].file, in[i].line, in[i].col});
                while (i + 1 < in.size() && in[i + 1].c != '\n') ++i;
            } else {
                out.push_back(in[i]);
            }
        }
        return out;
    }

    struct Conditional {
        bool parentActive;
        bool anyTaken; // some branch of this #if chain was taken already
        bool active;
        bool sawElse;
        Char at;
    };

    static std::vector<Chars> splitLines(const Chars& chars) {
        std::vector<Chars> lines(1);
        for (const Char& ch : chars) {
            lines.back().push_back(ch);
            if (ch.c == '\n') lines.emplace_back();
        }
        if (lines.back().empty()) lines.pop_back();
        return lines;
    }

    // `#` + spaces + a directive keyword; returns the keyword and sets `rest` past it.
    static std::optional<std::string> directiveOf(const Chars& line, size_t& rest) {
        size_t i = 0;
        while (i < line.size() && (line[i].c == ' ' || line[i].c == '\t')) ++i;
        if (i >= line.size() || line[i].c != '#') return std::nullopt;
        ++i;
        while (i < line.size() && (line[i].c == ' ' || line[i].c == '\t')) ++i;
        size_t start = i;
        while (i < line.size() && isIdentChar(line[i].c)) ++i;
        std::string word;
        for (size_t k = start; k < i; ++k) word.push_back(line[k].c);
        static const std::set<std::string> kDirectives = {"define", "undef", "if",    "ifdef",  "ifndef",
                                                          "elif",   "else",  "endif", "include", "pragma",
                                                          "error",  "warning", "line"};
        if (!kDirectives.count(word)) return std::nullopt;
        rest = i;
        return word;
    }

    void processLines(const Chars& chars, const std::string& path, int depth) {
        std::vector<Conditional> stack;
        auto active = [&] { return stack.empty() || stack.back().active; };
        Chars pending; // consecutive text lines, expanded together so macro calls may span lines
        auto flush = [&] {
            if (pending.empty()) return;
            Chars expanded;
            std::set<std::string> disabled;
            expand(pending, 0, pending.size(), disabled, nullptr, expanded);
            if (out_.size() + expanded.size() > kMaxExpandedSize)
                failAt(expanded.back(), fmt::format("the text grows past {} MiB after macro expansion",
                                                    kMaxExpandedSize >> 20));
            for (const Char& ch : expanded) out_.append(ch.c, ch.file, ch.line, ch.col);
            pending.clear();
        };
        for (const Chars& line : splitLines(chars)) {
            size_t rest = 0;
            std::optional<std::string> directive = directiveOf(line, rest);
            if (!directive) {
                if (active()) {
                    pending.insert(pending.end(), line.begin(), line.end());
                } else {
                    flush();
                    out_.append('\n', line.back().file, line.back().line, line.back().col);
                }
                continue;
            }
            flush();
            const Char& at = line.front();
            Chars args(line.begin() + static_cast<long>(rest), line.end());
            const std::string& d = *directive;
            if (d == "if" || d == "ifdef" || d == "ifndef") {
                bool parent = active();
                bool value = false;
                if (parent) value = d == "if" ? evalCondition(args, at) : (isDefined(args, at) == (d == "ifdef"));
                stack.push_back({parent, value, parent && value, false, at});
            } else if (d == "elif") {
                if (stack.empty() || stack.back().sawElse) failAt(at, "#elif without #if");
                Conditional& c = stack.back();
                bool value = c.parentActive && !c.anyTaken && evalCondition(args, at);
                c.active = value;
                c.anyTaken = c.anyTaken || value;
            } else if (d == "else") {
                if (stack.empty() || stack.back().sawElse) failAt(at, "#else without #if");
                Conditional& c = stack.back();
                c.sawElse = true;
                c.active = c.parentActive && !c.anyTaken;
                c.anyTaken = true;
            } else if (d == "endif") {
                if (stack.empty()) failAt(at, "#endif without #if");
                stack.pop_back();
            } else if (active()) {
                if (d == "define") define(args, at);
                else if (d == "undef") macros_.erase(identifierOf(args, at, "#undef"));
                else if (d == "include") include(args, at, path, depth);
                else if (d == "error") failAt(at, "#error" + textOf(args));
            }
            out_.append('\n', line.back().file, line.back().line, line.back().col);
        }
        flush();
        if (!stack.empty()) failAt(stack.back().at, "unterminated #if (missing #endif)");
    }

    [[noreturn]] void failAt(const Char& at, const std::string& message) const {
        throw ir::InputError({fileName(at.file), int(at.line), int(at.col)}, message);
    }

    static std::string textOf(const Chars& chars) {
        std::string s;
        for (const Char& ch : chars) s.push_back(ch.c);
        while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.pop_back();
        return s;
    }

    static size_t skipBlanks(const Chars& chars, size_t i) {
        while (i < chars.size() && (chars[i].c == ' ' || chars[i].c == '\t')) ++i;
        return i;
    }

    std::string identifierOf(const Chars& args, const Char& at, const char* what) const {
        size_t i = skipBlanks(args, 0);
        if (i >= args.size() || !isIdentStart(args[i].c)) failAt(at, fmt::format("{} expects a macro name", what));
        std::string name;
        while (i < args.size() && isIdentChar(args[i].c)) name.push_back(args[i++].c);
        return name;
    }

    bool isDefined(const Chars& args, const Char& at) const {
        return macros_.count(identifierOf(args, at, "#ifdef")) > 0;
    }

    void define(const Chars& args, const Char& at) {
        size_t i = skipBlanks(args, 0);
        if (i >= args.size() || !isIdentStart(args[i].c)) failAt(at, "#define expects a macro name");
        std::string name;
        while (i < args.size() && isIdentChar(args[i].c)) name.push_back(args[i++].c);
        Macro m;
        if (i < args.size() && args[i].c == '(') {
            m.functionLike = true;
            ++i;
            for (;;) {
                i = skipBlanks(args, i);
                if (i < args.size() && args[i].c == ')' && m.params.empty()) {
                    ++i;
                    break;
                }
                if (i >= args.size() || !isIdentStart(args[i].c))
                    failAt(i < args.size() ? args[i] : at, fmt::format("bad parameter list in #define {}", name));
                std::string param;
                while (i < args.size() && isIdentChar(args[i].c)) param.push_back(args[i++].c);
                m.params.push_back(param);
                i = skipBlanks(args, i);
                if (i < args.size() && args[i].c == ',') {
                    ++i;
                    continue;
                }
                if (i < args.size() && args[i].c == ')') {
                    ++i;
                    break;
                }
                failAt(i < args.size() ? args[i] : at, fmt::format("bad parameter list in #define {}", name));
            }
        }
        i = skipBlanks(args, i);
        size_t end = args.size();
        while (end > i && std::isspace(static_cast<unsigned char>(args[end - 1].c))) --end;
        m.body.assign(args.begin() + static_cast<long>(i), args.begin() + static_cast<long>(end));
        macros_[name] = std::move(m);
    }

    void include(const Chars& args, const Char& at, const std::string& path, int depth) {
        size_t i = skipBlanks(args, 0);
        if (i >= args.size() || (args[i].c != '"' && args[i].c != '<')) failAt(at, "#include expects \"file\"");
        char close = args[i].c == '"' ? '"' : '>';
        std::string name;
        for (++i; i < args.size() && args[i].c != close && args[i].c != '\n'; ++i) name.push_back(args[i].c);
        if (i >= args.size() || args[i].c != close) failAt(at, "#include: missing closing quote");
        std::filesystem::path target = std::filesystem::path(path).parent_path() / name;
        std::string text;
        try {
            text = readSourceFile(target.string());
        } catch (const ir::InputError&) {
            failAt(at, fmt::format("cannot open included file '{}'", name));
        }
        run(text, target.string(), depth + 1);
    }

    // Macro expansion of chars[begin, end), appending to out. `at` forces the origin of every output char
    // (the outermost invocation), so errors inside expansions point at the use.
    void expand(const Chars& in, size_t begin, size_t end, std::set<std::string>& disabled, const Char* at,
                Chars& out) {
        auto emit = [&](const Char& ch) {
            out.push_back(at ? Char{ch.c, at->file, at->line, at->col} : ch);
            if (out.size() > kMaxExpandedSize)
                failAt(out.back(), fmt::format("macro expansion grows past {} MiB", kMaxExpandedSize >> 20));
        };
        for (size_t i = begin; i < end;) {
            char c = in[i].c;
            if (c == '"') {
                do emit(in[i++]);
                while (i < end && in[i].c != '"');
                if (i < end) emit(in[i++]);
            } else if (std::isdigit(static_cast<unsigned char>(c)) ||
                       (c == '.' && i + 1 < end && std::isdigit(static_cast<unsigned char>(in[i + 1].c)))) {
                // A pp-number: identifiers glued to digits (1e5, 2x) are not macro names.
                while (i < end) {
                    char d = in[i].c;
                    if ((d == '+' || d == '-') && (in[i - 1].c == 'e' || in[i - 1].c == 'E')) {
                        emit(in[i++]);
                    } else if (isIdentChar(d) || d == '.') {
                        emit(in[i++]);
                    } else {
                        break;
                    }
                }
            } else if (isIdentStart(c)) {
                size_t start = i;
                std::string name;
                while (i < end && isIdentChar(in[i].c)) name.push_back(in[i++].c);
                auto it = macros_.find(name);
                if (it == macros_.end()) {
                    for (size_t k = start; k < i; ++k) emit(in[k]);
                    continue;
                }
                const Char& use = at ? *at : in[start];
                if (disabled.count(name)) failAt(use, fmt::format("macro '{}' refers to itself", name));
                const Macro& macro = it->second;
                if (!macro.functionLike) {
                    disabled.insert(name);
                    expand(macro.body, 0, macro.body.size(), disabled, &use, out);
                    disabled.erase(name);
                    continue;
                }
                size_t j = i;
                while (j < end && std::isspace(static_cast<unsigned char>(in[j].c))) ++j;
                if (j >= end || in[j].c != '(') { // a function-like macro name without a call is plain text
                    for (size_t k = start; k < i; ++k) emit(in[k]);
                    continue;
                }
                std::vector<Chars> args = collectArgs(in, j, end, i, name, in[start]);
                if (!(macro.params.empty() && args.size() == 1 && textOf(args[0]).empty()) &&
                    args.size() != macro.params.size())
                    failAt(in[start], fmt::format("macro '{}' takes {} argument(s), {} given", name,
                                                  macro.params.size(), args.size()));
                Chars substituted;
                for (size_t k = 0; k < macro.body.size();) {
                    if (isIdentStart(macro.body[k].c)) {
                        std::string word;
                        size_t w = k;
                        while (w < macro.body.size() && isIdentChar(macro.body[w].c)) word.push_back(macro.body[w++].c);
                        auto p = std::find(macro.params.begin(), macro.params.end(), word);
                        if (p != macro.params.end()) {
                            Chars expandedArg;
                            expand(args[size_t(p - macro.params.begin())], 0,
                                   args[size_t(p - macro.params.begin())].size(), disabled, nullptr, expandedArg);
                            substituted.insert(substituted.end(), expandedArg.begin(), expandedArg.end());
                        } else {
                            substituted.insert(substituted.end(), macro.body.begin() + long(k),
                                               macro.body.begin() + long(w));
                        }
                        k = w;
                    } else {
                        substituted.push_back(macro.body[k++]);
                    }
                }
                disabled.insert(name);
                expand(substituted, 0, substituted.size(), disabled, &use, out);
                disabled.erase(name);
            } else {
                emit(in[i++]);
            }
        }
    }

    // Arguments of a function-like macro call whose `(` is at `open`; sets `next` past the `)`.
    std::vector<Chars> collectArgs(const Chars& in, size_t open, size_t end, size_t& next, const std::string& name,
                                   const Char& use) const {
        std::vector<Chars> args(1);
        int depthParen = 0;
        size_t k = open + 1;
        for (; k < end; ++k) {
            char d = in[k].c;
            if (d == '(') ++depthParen;
            if (d == ')') {
                if (depthParen == 0) break;
                --depthParen;
            }
            if (d == ',' && depthParen == 0) {
                args.emplace_back();
                continue;
            }
            args.back().push_back(in[k]);
        }
        if (k >= end) failAt(use, fmt::format("unterminated call of macro '{}'", name));
        next = k + 1;
        return args;
    }

    // #if / #elif: `defined` handled first, then macros expanded, then a C constant expression.
    bool evalCondition(const Chars& args, const Char& at) {
        Chars replaced;
        for (size_t i = 0; i < args.size();) {
            if (isIdentStart(args[i].c)) {
                std::string word;
                size_t w = i;
                while (w < args.size() && isIdentChar(args[w].c)) word.push_back(args[w++].c);
                if (word == "defined") {
                    size_t k = skipBlanks(args, w);
                    bool paren = k < args.size() && args[k].c == '(';
                    if (paren) k = skipBlanks(args, k + 1);
                    std::string name;
                    while (k < args.size() && isIdentChar(args[k].c)) name.push_back(args[k++].c);
                    if (name.empty()) failAt(at, "'defined' expects a macro name");
                    if (paren) {
                        k = skipBlanks(args, k);
                        if (k >= args.size() || args[k].c != ')') failAt(at, "missing ')' after defined(");
                        ++k;
                    }
                    replaced.push_back({macros_.count(name) ? '1' : '0', at.file, at.line, at.col});
                    i = k;
                    continue;
                }
                replaced.insert(replaced.end(), args.begin() + long(i), args.begin() + long(w));
                i = w;
            } else {
                replaced.push_back(args[i++]);
            }
        }
        Chars expanded;
        std::set<std::string> disabled;
        expand(replaced, 0, replaced.size(), disabled, nullptr, expanded);
        std::string text = textOf(expanded);
        ConditionParser parser{text, 0};
        double value = parser.parseTernary();
        parser.skip();
        if (!parser.ok || parser.pos != text.size())
            failAt(at, fmt::format("cannot evaluate #if expression '{}'", text));
        return value != 0.0;
    }

    // A small evaluator for #if expressions; names left after expansion count as 0, as in cpp.
    struct ConditionParser {
        const std::string& s;
        size_t pos;
        bool ok = true;
        void skip() {
            while (pos < s.size() && std::isspace(static_cast<unsigned char>(s[pos]))) ++pos;
        }
        bool eat(const char* op) {
            skip();
            size_t n = std::char_traits<char>::length(op);
            if (s.compare(pos, n, op) == 0) {
                // Do not take `<` of `<=` or `&` of `&&`.
                if (n == 1 && pos + 1 < s.size() && (s[pos + 1] == '=' || s[pos + 1] == s[pos]) &&
                    (op[0] == '<' || op[0] == '>' || op[0] == '&' || op[0] == '|' || op[0] == '=' || op[0] == '!'))
                    return false;
                pos += n;
                return true;
            }
            return false;
        }
        double parseTernary() {
            double c = parseOr();
            if (eat("?")) {
                double a = parseTernary();
                if (!eat(":")) ok = false;
                double b = parseTernary();
                return c != 0 ? a : b;
            }
            return c;
        }
        double parseOr() {
            double v = parseAnd();
            while (eat("||")) v = (parseAnd() != 0 || v != 0) ? 1 : 0;
            return v;
        }
        double parseAnd() {
            double v = parseEq();
            while (eat("&&")) v = (parseEq() != 0 && v != 0) ? 1 : 0;
            return v;
        }
        double parseEq() {
            double v = parseRel();
            for (;;) {
                if (eat("==")) v = v == parseRel();
                else if (eat("!=")) v = v != parseRel();
                else return v;
            }
        }
        double parseRel() {
            double v = parseAdd();
            for (;;) {
                if (eat("<=")) v = v <= parseAdd();
                else if (eat(">=")) v = v >= parseAdd();
                else if (eat("<")) v = v < parseAdd();
                else if (eat(">")) v = v > parseAdd();
                else return v;
            }
        }
        double parseAdd() {
            double v = parseMul();
            for (;;) {
                if (eat("+")) v += parseMul();
                else if (eat("-")) v -= parseMul();
                else return v;
            }
        }
        double parseMul() {
            double v = parseUnary();
            for (;;) {
                if (eat("*")) v *= parseUnary();
                else if (eat("/")) {
                    double d = parseUnary();
                    if (d == 0) ok = false;
                    else v /= d;
                } else if (eat("%")) {
                    double d = parseUnary();
                    if (d == 0) ok = false;
                    else v = std::fmod(v, d);
                } else return v;
            }
        }
        double parseUnary() {
            if (eat("!")) return parseUnary() == 0 ? 1 : 0;
            if (eat("-")) return -parseUnary();
            if (eat("+")) return parseUnary();
            return parsePrimary();
        }
        double parsePrimary() {
            skip();
            if (eat("(")) {
                double v = parseTernary();
                if (!eat(")")) ok = false;
                return v;
            }
            if (pos < s.size() && (std::isdigit(static_cast<unsigned char>(s[pos])) || s[pos] == '.')) {
                size_t used = 0;
                double v = 0;
                try {
                    v = std::stod(s.substr(pos), &used);
                } catch (...) {
                    ok = false;
                    return 0;
                }
                pos += used;
                while (pos < s.size() && (s[pos] == 'u' || s[pos] == 'U' || s[pos] == 'l' || s[pos] == 'L')) ++pos;
                return v;
            }
            if (pos < s.size() && isIdentStart(s[pos])) {
                while (pos < s.size() && isIdentChar(s[pos])) ++pos;
                return 0;
            }
            ok = false;
            return 0;
        }
    };
};

} // namespace

PreprocessedText preprocessText(const std::string& text, const std::string& file,
                                const PredefinedMacros& predefined) {
    PreprocessedText out;
    Preprocessor pp(out, predefined);
    pp.run(text, file, 0);
    return out;
}

PreprocessedText preprocessFile(const std::string& path, const PredefinedMacros& predefined) {
    return preprocessText(readSourceFile(path), path, predefined);
}

} // namespace simeco::lang
