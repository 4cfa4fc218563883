#include "lang/cpfg_parser.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <set>
#include <utility>

#include <fmt/format.h>

#include "lang/expr_parser.h"
#include "lang/text_cursor.h"

namespace simeco::lang {

namespace {

const char* const kArrows[] = {"-->", "\xE2\x86\x92", "->"}; // longest first; → is U+2192

bool isBlankChar(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

// Names of productions' frames and of the grammar's globals, for expressions.
class Scope : public ExprScope {
public:
    // `subLsystem`: cpfg gives every L-system its own variables; a sub-L-system sees only the globals Q and Z.
    Scope(ir::Grammar& g, ir::Production* production, bool subLsystem = false)
        : g_(g), production_(production), subLsystem_(subLsystem) {}

    std::optional<ir::Expr> variable(const std::string& name) const override {
        if (production_) {
            auto it = std::find(production_->slotNames.begin(), production_->slotNames.end(), name);
            if (it != production_->slotNames.end()) {
                ir::Expr e;
                e.op = ir::Op::Local;
                e.slot = static_cast<int>(it - production_->slotNames.begin());
                return e;
            }
        }
        auto end = subLsystem_ ? g_.globalNames.begin() + kBuiltinGlobals : g_.globalNames.end();
        auto it = std::find(g_.globalNames.begin(), end, name);
        if (it != end) {
            ir::Expr e;
            e.op = ir::Op::Global;
            e.slot = static_cast<int>(it - g_.globalNames.begin());
            return e;
        }
        return std::nullopt;
    }
    std::optional<int> array(const std::string& name) const override {
        if (subLsystem_) return std::nullopt;
        for (size_t i = 0; i < g_.arrays.size(); ++i)
            if (g_.arrays[i].name == name) return static_cast<int>(i);
        return std::nullopt;
    }

    // A frame slot for a new local (in a production) or a new global (in control blocks).
    ir::Expr create(const std::string& name) {
        ir::Expr e;
        if (production_) {
            production_->slotNames.push_back(name);
            production_->frameSize = static_cast<int>(production_->slotNames.size());
            e.op = ir::Op::Local;
            e.slot = production_->frameSize - 1;
        } else {
            g_.globalNames.push_back(name);
            g_.globalInit.push_back(0.0f);
            e.op = ir::Op::Global;
            e.slot = static_cast<int>(g_.globalNames.size() - 1);
        }
        return e;
    }

    static constexpr size_t kBuiltinGlobals = 2; // Q and Z

private:
    ir::Grammar& g_;
    ir::Production* production_;
    bool subLsystem_;
};

// A scope that knows no names: for values that cpfg evaluates while reading the file.
class ConstantScope : public ExprScope {
public:
    std::optional<ir::Expr> variable(const std::string&) const override { return std::nullopt; }
    std::optional<int> array(const std::string&) const override { return std::nullopt; }
};

enum class Section { Header, Productions, Decomposition, Homomorphism };

class CpfgParser {
public:
    CpfgParser(const PreprocessedText& text, ir::Grammar& g) : g_(g) { cur_.src = &text; }

    void parse() {
        collectModuleNames();
        collectLabels();
        g_.globalNames = {"Q", "Z"}; // cpfg's current step and derivation length
        g_.globalInit = {0.0f, 0.0f};
        g_.symbol("[");
        cur_.skipBlanks(true);
        if (!keyword("lsystem", true)) cur_.fail("expected 'Lsystem:' at the start of the L-system");
        // The first L-system is the main one; those after it are its sub-L-systems. What follows the last
        // `endlsystem` is not read.
        for (;;) {
            lsystem();
            cur_.skipBlanks(true);
            if (!keyword("lsystem", true)) break;
            ++space_;
        }
        g_.lsystems = static_cast<int>(space_) + 1;
        contextFilter();
        g_.productions.present = true;
        g_.symbol("]");
    }

private:
    // One L-system, from after its `Lsystem:` to its `endlsystem`.
    void lsystem() {
        restOfLine(); // the label (collectLabels)
        section_ = Section::Header;
        stochastic_ = false;
        sectionsSeen_.clear();
        const size_t firstProduction = g_.productions.productions.size();
        const size_t firstDecomposition = g_.decomposition.productions.size();
        bool sawAxiom = false;
        for (;;) {
            cur_.skipBlanks(true);
            if (cur_.atEnd()) cur_.fail("missing 'endlsystem' at the end of the L-system");
            size_t lineStart = cur_.pos;
            if (keyword("endlsystem", false)) {
                restOfLine();
                break;
            }
            if (keyword("derivation length", true) || keyword("derivationlength", true)) {
                float n = constantExpression("derivation length");
                if (n < 0 || n != std::floor(n) || n > 1e9f)
                    cur_.failAt(lineStart, "derivation length must be a non-negative whole number");
                if (space_ == 0) { // a sub-L-system rewrites once in each of the main L-system's steps
                    g_.derivationLength = static_cast<int>(n);
                    g_.globalInit[1] = n;
                }
            } else if (keyword("axiom", true)) {
                // A sub-L-system's axiom is read, and used only where the L-system runs on its own.
                ir::SourceLoc loc = cur_.loc();
                std::vector<ir::SuccessorModule> axiom = parseModuleList(nullptr, "axiom");
                if (axiom.empty()) cur_.failAt(lineStart, "the axiom is empty");
                if (space_ == 0) {
                    g_.axiomLoc = loc;
                    g_.axiom = std::move(axiom);
                }
                sawAxiom = true;
            } else if (keyword("ignore", true)) {
                contextList(true, lineStart);
            } else if (keyword("consider", true)) {
                contextList(false, lineStart);
            } else if (keyword("seed", true)) {
                float seed = constantExpression("seed");
                if (section_ != Section::Homomorphism) {
                    if (space_ == 0) g_.seed = static_cast<uint32_t>(static_cast<int64_t>(seed));
                    stochastic_ = true;
                }
            } else if (keyword("ring lsystem", false)) {
                mainOnly(lineStart, "'ring L-system'");
                g_.ring = true;
            } else if (keyword("define", true)) {
                mainOnly(lineStart, "'define:'");
                arrayDefinitions();
            } else if (keyword("starteach", true) || keyword("start each", true)) {
                mainOnly(lineStart, "'StartEach:'");
                controlBlock(g_.startEachBlock);
            } else if (keyword("endeach", true) || keyword("end each", true)) {
                mainOnly(lineStart, "'EndEach:'");
                controlBlock(g_.endEachBlock);
            } else if (keyword("start", true)) {
                mainOnly(lineStart, "'Start:'");
                controlBlock(g_.startBlock);
            } else if (keyword("end", true)) {
                mainOnly(lineStart, "'End:'");
                controlBlock(g_.endBlock);
            } else if (keyword("decomposition", false)) {
                enterSection(Section::Decomposition, g_.decomposition, lineStart);
            } else if (keyword("homomorphism", false)) {
                enterSection(Section::Homomorphism, g_.homomorphism, lineStart);
            } else if (keyword("maximum depth", true)) {
                float depth = constantExpression("maximum depth");
                if (section_ != Section::Decomposition && section_ != Section::Homomorphism)
                    cur_.failAt(lineStart, "'maximum depth' belongs after 'decomposition' or 'homomorphism'");
                if (depth < 0 || depth > 1e6f) cur_.failAt(lineStart, "maximum depth out of range");
                // One rule set holds every L-system's decomposition (homomorphism): it goes as deep as the deepest.
                int& most = currentRules().maxDepth;
                most = space_ == 0 ? static_cast<int>(depth) : std::max(most, static_cast<int>(depth));
            } else if (keyword("module", false)) {
                restOfLine(); // declarations were read by collectModuleNames
            } else if (keyword("lsystem", true)) {
                cur_.failAt(lineStart, "missing 'endlsystem' before the next 'Lsystem:'");
            } else {
                if (!sawAxiom) cur_.failAt(lineStart, "expected 'Axiom:' before the first production");
                if (section_ == Section::Header) section_ = Section::Productions;
                production();
            }
        }
        if (!sawAxiom) cur_.fail("the L-system has no 'Axiom:'");
        if (stochastic_) {
            for (auto [rules, first] :
                 {std::pair{&g_.productions, firstProduction}, {&g_.decomposition, firstDecomposition}})
                for (size_t i = first; i < rules->productions.size(); ++i)
                    if (rules->productions[i].weight < 0) rules->productions[i].weight = 1.0f;
        }
    }

    // What simeco reads in the main L-system only: cpfg keeps a sub-L-system's variables per call, which simeco's
    // engines do not.
    void mainOnly(size_t lineStart, const char* what) {
        if (space_ != 0) cur_.failAt(lineStart, fmt::format("{} in a sub-L-system: simeco reads it in the main (first) "
                                                            "L-system only", what));
    }

    // The labels of the file's `Lsystem:` lines, in order (cpfg reads a label as a number; other text is 0).
    void collectLabels() {
        const std::string& t = cur_.text();
        for (size_t lineStart = 0; lineStart < t.size();) {
            size_t lineEnd = std::min(t.find('\n', lineStart), t.size());
            size_t i = t.find_first_not_of(" \t", lineStart);
            if (i < lineEnd && lineEnd - i >= 7) {
                std::string word = t.substr(i, 7);
                std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return std::tolower(c); });
                size_t colon = t.find_first_not_of(" \t", i + 7);
                if (word == "lsystem" && colon < lineEnd && t[colon] == ':')
                    labels_.push_back(static_cast<int>(std::atof(t.substr(colon + 1, lineEnd - colon - 1).c_str())));
            }
            lineStart = lineEnd + 1;
        }
    }

    bool hasSubLsystems() const { return labels_.size() > 1; }

    // The symbol of a module of L-system `space`. Branches, cuts, `=` and the calls' own `?` and `$` are shared.
    ir::SymbolId symbolIn(const std::string& name, uint32_t space) {
        static const std::set<std::string> kShared = {"[", "]", "%", "=", "?", "$"};
        return g_.symbol(name, kShared.count(name) ? 0 : space);
    }

    // The L-system that `?(label, scale)` calls, from a list of L-system space_ inside the calls `callers`.
    uint32_t calledLsystem(const ir::SuccessorModule& call, const std::vector<uint32_t>& callers) {
        std::optional<double> label = foldConstant(call.args[0]);
        if (!label) throw ir::InputError(call.args[0].loc, "a sub-L-system's label must be a constant");
        const int id = static_cast<int>(*label);
        auto it = std::find(labels_.begin(), labels_.end(), id);
        if (it == labels_.end()) throw ir::InputError(call.loc, fmt::format("no L-system is labelled {}", id));
        const uint32_t space = static_cast<uint32_t>(it - labels_.begin());
        if (space == 0) throw ir::InputError(call.loc, "the main L-system cannot be called as a sub-L-system");
        if (space == space_ || std::find(callers.begin(), callers.end(), space) != callers.end())
            throw ir::InputError(call.loc, fmt::format("L-system {} calls itself", id));
        return space;
    }

    TextCursor cur_;
    ir::Grammar& g_;
    Section section_ = Section::Header;
    bool stochastic_ = false;
    std::vector<std::string> names_; // names of several characters, longest first
    std::vector<int> labels_;        // the L-systems' labels, in the file's order
    uint32_t space_ = 0;             // the L-system being read: its index in labels_ (0: the main one)
    std::set<Section> sectionsSeen_; // in the L-system being read
    // `ignore:` / `consider:` of an L-system.
    struct ContextFilter {
        bool present = false;
        bool ignore = true;
        std::set<std::string> names;
        size_t at = 0; // where its line starts
    };
    std::map<uint32_t, ContextFilter> filters_; // by L-system
    std::set<uint32_t> contextual_;             // the L-systems with context-sensitive productions

    ir::RuleSet& currentRules() {
        switch (section_) {
        case Section::Decomposition: return g_.decomposition;
        case Section::Homomorphism: return g_.homomorphism;
        default: return g_.productions;
        }
    }

    void enterSection(Section s, ir::RuleSet& rules, size_t lineStart) {
        if (s == Section::Decomposition && section_ == Section::Homomorphism)
            cur_.failAt(lineStart, "'decomposition' must come before 'homomorphism'");
        if (!sectionsSeen_.insert(s).second) cur_.failAt(lineStart, "section declared twice");
        rules.present = true;
        section_ = s;
        cur_.skipBlanks();
        cur_.eat(":");
        restOfLine(); // `warnings` / `no warnings`
    }

    // A case-insensitive keyword at the cursor, followed by `:` when `colon`; words end at a non-letter.
    bool keyword(const char* word, bool colon) {
        size_t save = cur_.pos;
        size_t n = std::strlen(word);
        const std::string& t = cur_.text();
        if (t.size() - cur_.pos < n) return false;
        for (size_t i = 0; i < n; ++i) {
            char a = t[cur_.pos + i], b = word[i];
            if (b == ' ') {
                if (!isBlankChar(a)) return false;
            } else if (std::tolower(static_cast<unsigned char>(a)) != b) {
                return false;
            }
        }
        cur_.pos += n;
        if (isIdentChar(cur_.peek())) {
            cur_.pos = save;
            return false;
        }
        if (colon) {
            cur_.skipBlanks();
            if (!cur_.eat(":")) {
                cur_.pos = save;
                return false;
            }
        }
        return true;
    }

    // What remains of the line must be blank (or words cpfg allows there, such as `warnings`).
    void restOfLine() {
        while (!cur_.atEnd() && cur_.peek() != '\n') ++cur_.pos;
    }
    void expectEndOfLine(const char* what) {
        cur_.skipBlanks();
        if (!cur_.atEnd() && cur_.peek() != '\n')
            cur_.fail(fmt::format("unexpected '{}' after {}", cur_.peek(), what));
    }

    float constantExpression(const char* what) {
        ConstantScope none;
        size_t start = cur_.pos;
        cur_.skipBlanks();
        ir::Expr e = parseExpression(cur_, none, {.newlines = NewlinePolicy::TabContinuation});
        expectEndOfLine(what);
        std::optional<double> v = foldConstant(e);
        if (!v) cur_.failAt(start, fmt::format("{} must be a constant", what));
        return static_cast<float>(*v);
    }

    // Evaluates an expression made of constants only (parse-time values).
    static std::optional<double> foldConstant(const ir::Expr& e) {
        std::vector<double> a;
        for (const ir::Expr& arg : e.args) {
            std::optional<double> v = foldConstant(arg);
            if (!v) return std::nullopt;
            a.push_back(*v);
        }
        switch (e.op) {
        case ir::Op::Const: return e.value;
        case ir::Op::Neg: return -a[0];
        case ir::Op::Add: return a[0] + a[1];
        case ir::Op::Sub: return a[0] - a[1];
        case ir::Op::Mul: return a[0] * a[1];
        case ir::Op::Div:
            if (a[1] == 0) throw ir::InputError(e.loc, "division by zero");
            return a[0] / a[1];
        case ir::Op::Pow: return std::pow(a[0], a[1]);
        default: return std::nullopt;
        }
    }

    // ignore: / consider: — a list of module names on one line.
    void contextList(bool ignore, size_t lineStart) {
        ContextFilter& filter = filters_[space_];
        if (filter.present) cur_.failAt(lineStart, "only one 'ignore:' or 'consider:' statement is allowed");
        for (;;) {
            cur_.skipBlanks();
            if (cur_.atEnd() || cur_.peek() == '\n') break;
            std::string name = readModuleName();
            g_.symbol(name);
            filter.names.insert(name);
        }
        if (filter.names.empty()) cur_.failAt(lineStart, "empty symbol list");
        filter.present = true;
        filter.ignore = ignore;
        filter.at = lineStart;
    }

    // cpfg matches a context with the list of the L-system whose production it tries; simeco keeps one list for
    // the file: that of the L-systems with context-sensitive productions (they must agree), else the main one's.
    void contextFilter() {
        const ContextFilter* chosen = nullptr;
        for (uint32_t space : contextual_) {
            const ContextFilter& f = filters_[space];
            if (!chosen) {
                chosen = &f;
            } else if (f.present != chosen->present || f.ignore != chosen->ignore || f.names != chosen->names) {
                const ContextFilter& differing = f.present ? f : *chosen;
                cur_.failAt(differing.at, "the L-systems with context-sensitive productions skip different modules "
                                          "in context: simeco needs the same 'ignore:' or 'consider:' in each");
            }
        }
        if (!chosen) chosen = &filters_[0];
        g_.contextSkipDefault = chosen->present && !chosen->ignore;
        g_.contextSkip.assign(g_.alphabet.size(), false);
        if (!chosen->present) return;
        for (ir::SymbolId s = 0; s < g_.alphabet.size(); ++s)
            g_.contextSkip[s] = chosen->names.count(g_.alphabet.name(s)) ? chosen->ignore : !chosen->ignore;
    }

    // define: { array name[d1,d2] = {v, ...}; ... }
    void arrayDefinitions() {
        cur_.skipBlanks(true);
        if (!cur_.eat("{")) cur_.fail("expected '{' after 'define:'");
        ConstantScope none;
        for (;;) {
            cur_.skipBlanks(true);
            if (cur_.eat("}")) break;
            if (!keyword("array", false)) cur_.fail("expected 'array' in 'define:' block");
            for (;;) {
                cur_.skipBlanks(true);
                ir::GlobalArray array;
                array.loc = cur_.loc();
                array.name = identifier("array name");
                for (const ir::GlobalArray& other : g_.arrays)
                    if (other.name == array.name) cur_.fail(fmt::format("array '{}' defined twice", array.name));
                cur_.skipBlanks(true);
                if (!cur_.eat("[")) cur_.fail("expected '[' after the array name");
                for (;;) {
                    cur_.skipBlanks(true);
                    size_t at = cur_.pos;
                    std::optional<double> d = foldConstant(parseExpression(cur_, none));
                    if (!d || *d < 1 || *d != std::floor(*d) || *d > 1e7f)
                        cur_.failAt(at, "array dimension must be a positive whole number");
                    array.dims.push_back(static_cast<int>(*d));
                    cur_.skipBlanks(true);
                    if (cur_.eat(",")) continue;
                    if (!cur_.eat("]")) cur_.fail("expected ']' after the array dimensions");
                    cur_.skipBlanks(true);
                    if (cur_.eat("[")) continue;
                    break;
                }
                size_t size = 1;
                for (int d : array.dims) size *= static_cast<size_t>(d);
                if (size > (1u << 24)) cur_.failAt(cur_.pos, "array too large");
                array.init.assign(size, 0.0f);
                cur_.skipBlanks(true);
                if (cur_.eat("=")) {
                    cur_.skipBlanks(true);
                    if (!cur_.eat("{")) cur_.fail("expected '{' before the array values");
                    size_t count = 0;
                    for (;;) {
                        cur_.skipBlanks(true);
                        size_t at = cur_.pos;
                        std::optional<double> v = foldConstant(parseExpression(cur_, none));
                        if (!v) cur_.failAt(at, "array values must be constants");
                        if (count >= size) cur_.failAt(at, fmt::format("too many values for array '{}'", array.name));
                        array.init[count++] = static_cast<float>(*v);
                        cur_.skipBlanks(true);
                        if (cur_.eat(",")) continue;
                        if (!cur_.eat("}")) cur_.fail("expected '}' after the array values");
                        break;
                    }
                }
                g_.arrays.push_back(std::move(array));
                cur_.skipBlanks(true);
                if (cur_.eat(",")) continue;
                if (!cur_.eat(";")) cur_.fail("expected ';' after an array definition");
                break;
            }
        }
        cur_.skipBlanks();
        cur_.eat(";");
    }

    std::string identifier(const char* what) {
        if (!isIdentStartChar(cur_.peek())) cur_.fail(fmt::format("expected {}", what));
        size_t start = cur_.pos;
        while (isIdentChar(cur_.peek())) ++cur_.pos;
        return cur_.text().substr(start, cur_.pos - start);
    }

    void controlBlock(std::vector<ir::Stmt>& block) {
        Scope scope(g_, nullptr);
        cur_.skipBlanks(true);
        if (cur_.peek() != '{') cur_.fail("expected '{' to open the block");
        std::vector<ir::Stmt> stmts = statementBlock(scope);
        block.insert(block.end(), stmts.begin(), stmts.end());
        cur_.skipBlanks();
        cur_.eat(";");
        expectEndOfLine("the block");
    }

    // `{ statement ... }`: assignments, if/else, while, do-while and expression statements.
    std::vector<ir::Stmt> statementBlock(Scope& scope) {
        size_t open = cur_.pos;
        if (!cur_.eat("{")) cur_.fail("expected '{'");
        std::vector<ir::Stmt> out;
        for (;;) {
            cur_.skipBlanks(true);
            if (cur_.atEnd()) cur_.failAt(open, "unterminated '{' block");
            if (cur_.eat("}")) return out;
            out.push_back(statement(scope));
        }
    }

    ir::Stmt statement(Scope& scope) {
        ir::Stmt s;
        s.loc = cur_.loc();
        if (cur_.eat(";")) {
            s.kind = ir::StmtKind::Eval;
            s.expr = ir::Expr::constant(0);
            return s;
        }
        auto condition = [&] {
            cur_.skipBlanks(true);
            if (!cur_.eat("(")) cur_.fail("expected '(' before the condition");
            ir::Expr e = parseExpression(cur_, scope);
            cur_.skipBlanks(true);
            if (!cur_.eat(")")) cur_.fail("expected ')' after the condition");
            return e;
        };
        auto body = [&] {
            cur_.skipBlanks(true);
            if (cur_.peek() != '{') cur_.fail("expected '{' (blocks need braces)");
            return statementBlock(scope);
        };
        if (keyword("if", false)) {
            s.kind = ir::StmtKind::If;
            s.expr = condition();
            s.body = body();
            size_t save = cur_.pos;
            cur_.skipBlanks(true);
            if (keyword("else", false)) s.elseBody = body();
            else cur_.pos = save;
            return s;
        }
        if (keyword("while", false)) {
            s.kind = ir::StmtKind::While;
            s.expr = condition();
            s.body = body();
            return s;
        }
        if (keyword("do", false)) {
            s.kind = ir::StmtKind::DoWhile;
            s.body = body();
            cur_.skipBlanks(true);
            if (!keyword("while", false)) cur_.fail("expected 'while' after a 'do' block");
            s.expr = condition();
            cur_.skipBlanks();
            cur_.eat(";");
            return s;
        }
        // An assignment `name = e;` / `name[i] = e;`, or an expression evaluated for its effect.
        size_t start = cur_.pos;
        if (isIdentStartChar(cur_.peek())) {
            std::string name = identifier("a name");
            cur_.skipBlanks(true);
            std::vector<ir::Expr> indices;
            std::optional<int> arraySlot = scope.array(name);
            if (arraySlot && cur_.peek() == '[') {
                while (cur_.eat("[")) {
                    for (;;) {
                        indices.push_back(parseExpression(cur_, scope));
                        cur_.skipBlanks(true);
                        if (cur_.eat(",")) continue;
                        break;
                    }
                    if (!cur_.eat("]")) cur_.fail("expected ']' after the array index");
                    cur_.skipBlanks(true);
                }
            }
            if (cur_.peek() == '=' && cur_.peek(1) != '=') {
                ++cur_.pos;
                if (arraySlot && !indices.empty()) {
                    s.target = ir::TargetKind::ArrayElem;
                    s.slot = *arraySlot;
                    s.indices = std::move(indices);
                } else {
                    if (arraySlot) cur_.failAt(start, fmt::format("array '{}' assigned without an index", name));
                    // The value is parsed before the name is created: `x = x + 1` needs x to exist.
                    std::optional<ir::Expr> target = scope.variable(name);
                    ir::Expr value = parseExpression(cur_, scope);
                    if (!target) target = scope.create(name);
                    s.kind = ir::StmtKind::Assign;
                    s.target = target->op == ir::Op::Local ? ir::TargetKind::Local : ir::TargetKind::Global;
                    s.slot = target->slot;
                    s.expr = std::move(value);
                    endStatement();
                    return s;
                }
                s.kind = ir::StmtKind::Assign;
                s.expr = parseExpression(cur_, scope);
                endStatement();
                return s;
            }
            cur_.pos = start;
        }
        s.kind = ir::StmtKind::Eval;
        s.expr = parseExpression(cur_, scope);
        endStatement();
        return s;
    }

    void endStatement() {
        cur_.skipBlanks(true);
        if (!cur_.eat(";")) cur_.fail("expected ';' after the statement");
    }

    // ---- modules -------------------------------------------------------------------------------

    // Finds names of several characters: declared by `module` lines, or used as predecessors with
    // parameters in a file that clearly uses long names (cpfg reads `XI(a)` as X then I(a)).
    void collectModuleNames() {
        std::set<std::string> declared, candidates;
        bool clearlyLong = false;
        const std::string& t = cur_.text();
        size_t lineStart = 0;
        while (lineStart < t.size()) {
            size_t lineEnd = t.find('\n', lineStart);
            if (lineEnd == std::string::npos) lineEnd = t.size();
            std::string line = t.substr(lineStart, lineEnd - lineStart);
            size_t first = line.find_first_not_of(" \t");
            if (first != std::string::npos && line.compare(first, 7, "module ") == 0) {
                for (size_t i = first + 7; i < line.size();) {
                    if (isIdentStartChar(line[i])) {
                        size_t s = i;
                        while (i < line.size() && (isIdentChar(line[i]) || (line[i] == '-' && i + 1 < line.size() && isIdentStartChar(line[i + 1])))) ++i;
                        declared.insert(line.substr(s, i - s));
                        if (i < line.size() && line[i] == '(') i = line.find(')', i) == std::string::npos ? line.size() : line.find(')', i) + 1;
                    } else {
                        ++i;
                    }
                }
            } else {
                size_t arrow = std::string::npos;
                for (const char* a : kArrows) arrow = std::min(arrow, line.find(a));
                if (arrow != std::string::npos) {
                    std::string pred = line.substr(0, std::min(arrow, line.find(':')));
                    pred = pred.substr(0, pred.find('{'));
                    for (size_t i = 0; i < pred.size();) {
                        if (!isIdentStartChar(pred[i])) {
                            ++i;
                            continue;
                        }
                        size_t s = i;
                        while (i < pred.size() && (isIdentChar(pred[i]) || (pred[i] == '-' && i + 1 < pred.size() && isIdentStartChar(pred[i + 1])))) ++i;
                        std::string run = pred.substr(s, i - s);
                        if (i < pred.size() && pred[i] == '(' && run.size() >= 2) {
                            candidates.insert(run);
                            bool lower = std::any_of(run.begin() + 1, run.end(), [](char c) { return std::islower(static_cast<unsigned char>(c)); });
                            if (run.size() >= 3 || run.find_first_of("_-") != std::string::npos || lower) clearlyLong = true;
                        }
                        if (i < pred.size() && pred[i] == '(') i = pred.find(')', i) == std::string::npos ? pred.size() : pred.find(')', i) + 1;
                    }
                }
            }
            lineStart = lineEnd + 1;
        }
        names_.assign(declared.begin(), declared.end());
        if (clearlyLong || !declared.empty()) names_.insert(names_.end(), candidates.begin(), candidates.end());
        std::sort(names_.begin(), names_.end(), [](const std::string& a, const std::string& b) {
            return a.size() != b.size() ? a.size() > b.size() : a < b;
        });
        names_.erase(std::unique(names_.begin(), names_.end()), names_.end());
    }

    bool atArrow() const {
        for (const char* a : kArrows)
            if (cur_.startsWith(a)) return true;
        return false;
    }
    bool eatArrow() {
        for (const char* a : kArrows)
            if (cur_.eat(a)) return true;
        return false;
    }

    // One module name at the cursor: a declared long name (longest match) or one character
    // (a whole UTF-8 sequence, so that non-ASCII symbols stay intact).
    std::string readModuleName() {
        for (const std::string& n : names_)
            if (cur_.startsWith(n.c_str())) {
                cur_.pos += n.size();
                return n;
            }
        unsigned char c = static_cast<unsigned char>(cur_.peek());
        size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xe ? 3 : 4;
        std::string name = cur_.text().substr(cur_.pos, len);
        cur_.pos += len;
        return name;
    }

    static bool endsModuleList(char c) { return c == '\0' || c == '\n'; }

    // A successor or axiom: modules with parameter expressions, up to the end of the line (continued onto
    // lines that start with a tab).
    std::vector<ir::SuccessorModule> parseModuleList(ir::Production* production, const char* what) {
        Scope scope(g_, production, space_ != 0);
        std::vector<ir::SuccessorModule> modules;
        std::vector<ir::SourceLoc> openBrackets;
        // The sub-L-systems this list calls, innermost last: what follows `?(label, s)` up to its `$` is rewritten
        // by the L-system of that label.
        std::vector<uint32_t> calls;
        bool returned = false; // a `$` has ended the call this list's own L-system runs in
        for (;;) {
            cur_.skipBlanks();
            char c = cur_.peek();
            if (endsModuleList(c)) {
                if (c == '\n' && cur_.peek(1) == '\t') {
                    ++cur_.pos;
                    continue;
                }
                break;
            }
            if (c == ':' && production) break; // probability follows
            if (c == '*' || c == '<' || c == '>' || c == ':' || (c == '(' )) {
                if (c == '(') cur_.fail(fmt::format("'(' without a module name in the {}", what));
                cur_.fail(fmt::format("unexpected '{}' in the {}", c, what));
            }
            if (atArrow() && c != '-') cur_.fail(fmt::format("unexpected arrow in the {}", what));
            if (cur_.startsWith("-->")) cur_.fail(fmt::format("unexpected arrow in the {}", what));
            ir::SuccessorModule m;
            m.loc = cur_.loc();
            const std::string name = readModuleName();
            if (returned && space_ != 0)
                throw ir::InputError(m.loc, "a module after a '$' that returns from this sub-L-system: simeco cannot "
                                            "tell which L-system rewrites it");
            m.sym = symbolIn(name, calls.empty() ? space_ : calls.back());
            if (m.sym == ir::kBranchOpen) openBrackets.push_back(m.loc);
            if (m.sym == ir::kBranchClose) {
                if (openBrackets.empty()) throw ir::InputError(m.loc, fmt::format("unbalanced ']' in the {}", what));
                openBrackets.pop_back();
            }
            if (cur_.peek() == '(') {
                size_t open = cur_.pos++;
                for (;;) {
                    cur_.skipLineBlanks();
                    if (cur_.peek() == ')' && m.args.empty()) cur_.fail("empty parameter list");
                    m.args.push_back(parseExpression(cur_, scope, {.newlines = NewlinePolicy::TabContinuation}));
                    cur_.skipLineBlanks();
                    if (cur_.eat(",")) continue;
                    if (cur_.eat(")")) break;
                    if (cur_.atEnd()) cur_.failAt(open, "unterminated parameter list");
                    cur_.fail(fmt::format("expected ',' or ')' in the parameters of '{}'", g_.alphabet.name(m.sym)));
                }
                if (m.args.size() > kMaxParams) throw ir::InputError(m.loc, "too many parameters");
            }
            if (name == "?" && !m.args.empty()) {
                calls.push_back(calledLsystem(m, calls));
            } else if (hasSubLsystems() && name == "$") {
                if (!calls.empty())
                    calls.pop_back();
                else
                    returned = true;
            }
            modules.push_back(std::move(m));
        }
        if (!openBrackets.empty())
            throw ir::InputError(openBrackets.back(), fmt::format("unbalanced '[' in the {} (never closed)", what));
        return modules;
    }

    static constexpr size_t kMaxParams = 32;

    // A predecessor or context: modules with formal parameter names.
    std::vector<ir::PatternModule> parsePattern(ir::Production& p, const char* what) {
        std::vector<ir::PatternModule> modules;
        cur_.skipLineBlanks();
        if (cur_.peek() == '*') {
            ++cur_.pos;
            return modules;
        }
        for (;;) {
            cur_.skipLineBlanks();
            char c = cur_.peek();
            if (cur_.atEnd() || c == '\n' || c == '<' || c == '>' || c == ':' || c == '*' || atArrow()) break;
            if (c == '(') cur_.fail(fmt::format("'(' without a module name in the {}", what));
            if (c == '{') cur_.fail("expected ':' before the statement block");
            ir::PatternModule m;
            m.loc = cur_.loc();
            m.sym = symbolIn(readModuleName(), space_);
            if (cur_.peek() == '(') {
                ++cur_.pos;
                for (;;) {
                    cur_.skipBlanks(true);
                    size_t at = cur_.pos;
                    if (!isIdentStartChar(cur_.peek()))
                        cur_.fail(fmt::format("expected a parameter name in the {}", what));
                    std::string name = identifier("a parameter name");
                    if (std::find(p.slotNames.begin(), p.slotNames.end(), name) != p.slotNames.end())
                        cur_.failAt(at, fmt::format("parameter '{}' defined twice in one production", name));
                    p.slotNames.push_back(name);
                    m.paramSlots.push_back(static_cast<int>(p.slotNames.size() - 1));
                    cur_.skipBlanks(true);
                    if (cur_.eat(",")) continue;
                    if (cur_.eat(")")) break;
                    cur_.fail(fmt::format("expected ',' or ')' after parameter '{}'", name));
                }
            }
            modules.push_back(std::move(m));
        }
        return modules;
    }

    void production() {
        ir::Production p;
        p.loc = cur_.loc();
        std::vector<ir::PatternModule> first = parsePattern(p, "predecessor");
        cur_.skipLineBlanks();
        if (cur_.eat("<")) {
            p.left = std::move(first);
            p.strict = parsePattern(p, "predecessor");
        } else {
            p.strict = std::move(first);
        }
        cur_.skipLineBlanks();
        if (cur_.peek() == '>' ) {
            ++cur_.pos;
            p.right = parsePattern(p, "right context");
        }
        if (p.strict.empty()) throw ir::InputError(p.loc, "the strict predecessor is empty");
        if (hasSubLsystems()) {
            // A call's `?` is rewritten by the caller and its `$` by the callee, which simeco's symbols do not tell.
            const std::string& rewritten = g_.alphabet.name(p.strict.front().sym);
            if (rewritten == "?" || rewritten == "$")
                throw ir::InputError(p.loc, fmt::format("a production of '{}' in a file of several L-systems: simeco "
                                                        "does not rewrite a sub-L-system's '?' or '$'", rewritten));
            if (!p.left.empty() || !p.right.empty()) contextual_.insert(space_);
        }
        p.frameSize = static_cast<int>(p.slotNames.size());
        cur_.skipLineBlanks();
        Scope scope(g_, &p, space_ != 0);
        if (cur_.eat(":")) {
            cur_.skipLineBlanks();
            if (cur_.peek() == '{') p.before = statementBlock(scope);
            cur_.skipLineBlanks();
            if (cur_.peek() == '*') {
                ++cur_.pos;
            } else if (!atArrow() && cur_.peek() != '{') {
                if (cur_.atEnd()) cur_.fail("expected a condition and '-->'");
                p.condition = parseExpression(cur_, scope, {.newlines = NewlinePolicy::TabContinuation});
            }
            cur_.skipLineBlanks();
            if (cur_.peek() == '{') p.after = statementBlock(scope);
            cur_.skipLineBlanks();
        }
        if (!eatArrow()) {
            if (cur_.atEnd() || cur_.peek() == '\n') cur_.fail("expected '-->' in the production before the end of the line");
            cur_.fail(fmt::format("expected '-->' in the production, found '{}'", cur_.peek()));
        }
        cur_.skipLineBlanks();
        ir::Alternative alt;
        if (cur_.peek() == '*') {
            ++cur_.pos;
        } else {
            if (cur_.atEnd() || cur_.peek() == ':' || cur_.peek() == '\n')
                cur_.fail("the successor is empty (write '*' to erase)");
            alt.modules = parseModuleList(&p, "successor");
        }
        cur_.skipBlanks();
        if (cur_.eat(":")) {
            cur_.skipBlanks();
            size_t at = cur_.pos;
            std::optional<double> w = foldConstant(parseExpression(cur_, scope, {.newlines = NewlinePolicy::TabContinuation}));
            if (!w || *w < 0) cur_.failAt(at, "the probability factor must be a non-negative constant");
            p.weight = static_cast<float>(*w);
            stochastic_ = true;
        }
        expectEndOfLine("the successor");
        p.frameSize = static_cast<int>(p.slotNames.size());
        p.alternatives.push_back(std::move(alt));
        currentRules().productions.push_back(std::move(p));
    }
};

} // namespace

ir::Grammar parseCpfg(const PreprocessedText& text, std::vector<ir::FunctionCurve> functions) {
    ir::Grammar g;
    g.sourceFile = text.locate(0).file;
    g.functions = std::move(functions);
    CpfgParser parser(text, g);
    parser.parse();
    return g;
}

} // namespace simeco::lang
