#include "random_grammar.h"

#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace simeco::test {
namespace {

constexpr char kSymbolPool[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

struct Symbol {
    char name;
    int params; // fixed per symbol, so that patterns written for it can match
};

// Appends the parts in order (GCC 12 warns falsely about `"literal" + std::string` chains).
template <typename... Parts> std::string cat(const Parts&... parts) {
    std::string out;
    (out += ... += parts);
    return out;
}

// An expression's text, and whether its value stays within a fixed range whatever the variables hold.
// Two unbounded values are never multiplied, so parameters grow at most by a constant factor per step.
struct Value {
    std::string text;
    bool bounded;
};

// The names an expression may read: the formal parameters of the production's patterns and the locals
// assigned so far.
struct Frame {
    std::vector<std::string> vars;
    int nextParam = 0;
    int nextLocal = 0;
};

class Generator {
public:
    explicit Generator(std::uint64_t seed) : rng_(seed) {}

    std::string grammar(std::uint64_t seed) {
        int steps = uniform(2, 6);
        // Successors shrink as derivations lengthen: about maxSuccessor^steps modules from one axiom module.
        static constexpr int kMaxSuccessor[] = {0, 0, 8, 6, 5, 4, 4};
        maxSuccessor_ = kMaxSuccessor[steps];
        stochastic_ = chance(0.3);

        int count = uniform(3, 7);
        std::string pool = kSymbolPool;
        for (int i = 0; i < count; ++i) {
            std::size_t at = static_cast<std::size_t>(uniform(0, static_cast<int>(pool.size()) - 1));
            static constexpr int kParamWeights[] = {0, 0, 0, 1, 1, 1, 2, 2, 3};
            symbols_.push_back({pool[at], kParamWeights[uniform(0, 8)]});
            pool.erase(at, 1);
        }

        std::string out = cat("/* random grammar, seed ", std::to_string(seed), " */\nLsystem: 1\n");
        if (stochastic_) out += cat("seed: ", std::to_string(uniform(0, 100000)), "\n");
        out += cat("derivation length: ", std::to_string(steps), "\n");
        if (chance(0.25)) {
            bool ignore = chance(0.8);
            // `ignore:` hides the listed symbols from contexts, `consider:` all but the listed ones.
            std::vector<Symbol> listed;
            int n = uniform(1, 2);
            for (int i = 0; i < n; ++i) {
                const Symbol& s = symbol();
                if (listed.empty() || listed[0].name != s.name) listed.push_back(s);
            }
            out += ignore ? "ignore:" : "consider:";
            for (const Symbol& s : listed) {
                out += ' ';
                out += s.name;
            }
            out += '\n';
            for (const Symbol& s : symbols_) {
                bool isListed = false;
                for (const Symbol& l : listed)
                    isListed = isListed || l.name == s.name;
                if (isListed == ignore) hidden_.push_back(s.name);
            }
        }

        Frame none;
        out += cat("Axiom: ", moduleList(none, uniform(1, 4), 0, /*inAxiom=*/true), "\n");

        for (const Symbol& s : symbols_) {
            if (!chance(0.85)) continue;
            int n = uniform(1, 3);
            for (int i = 0; i < n; ++i)
                out += production(s, /*lastOfSymbol=*/i == n - 1) + "\n";
        }

        if (chance(0.25)) {
            out += cat("decomposition\nmaximum depth: ", std::to_string(uniform(1, 3)), "\n");
            int n = uniform(1, 2);
            for (int i = 0; i < n; ++i)
                out += production(symbol(), /*lastOfSymbol=*/true, /*decomposition=*/true) + "\n";
        }
        out += "endlsystem\n";
        return out;
    }

private:
    std::mt19937_64 rng_;
    std::vector<Symbol> symbols_;
    std::vector<char> hidden_; // invisible to contexts (ignore: / consider:)
    bool stochastic_ = false;
    int maxSuccessor_ = 3;

    // Plain modulo and bit arithmetic rather than the std distributions, whose results differ between
    // standard libraries.
    int uniform(int lo, int hi) { return lo + static_cast<int>(rng_() % static_cast<std::uint64_t>(hi - lo + 1)); }
    bool chance(double p) { return static_cast<double>(rng_() >> 11) * 0x1.0p-53 < p; }
    template <typename T, std::size_t N> const T& pick(const T (&items)[N]) { return items[uniform(0, N - 1)]; }
    const Symbol& symbol() {
        return symbols_[static_cast<std::size_t>(uniform(0, static_cast<int>(symbols_.size()) - 1))];
    }

    const Symbol& visibleSymbol() {
        for (int tries = 0; tries < 20; ++tries) {
            const Symbol& s = symbol();
            bool hidden = false;
            for (char h : hidden_)
                hidden = hidden || h == s.name;
            if (!hidden) return s;
        }
        return symbol();
    }

    // ---- expressions ---------------------------------------------------------------------------

    Value constant() {
        static const char* const kConstants[] = {"0",  "1",   "2",   "3",    "4",   "5",
                                                 "10", "0.5", "1.5", "2.25", "0.1", "0.75"};
        return {pick(kConstants), true};
    }

    Value atom(const Frame& f) {
        if (!f.vars.empty() && chance(0.7))
            return {f.vars[static_cast<std::size_t>(uniform(0, static_cast<int>(f.vars.size()) - 1))], false};
        return constant();
    }

    // `random`: ran() may be drawn (successor parameters only).
    Value expression(const Frame& f, int depth, bool random) {
        if (depth <= 0 || chance(0.3)) return atom(f);
        auto sub = [&] { return expression(f, depth - 1, random); };
        switch (uniform(0, 15)) {
        case 0:
        case 1: {
            Value a = sub(), b = sub();
            return {cat("(", a.text, " + ", b.text, ")"), a.bounded && b.bounded};
        }
        case 2:
        case 3: {
            Value a = sub(), b = sub();
            return {cat("(", a.text, " - ", b.text, ")"), a.bounded && b.bounded};
        }
        case 4:
        case 5: {
            Value a = sub(), b = sub();
            if (!a.bounded && !b.bounded) b = constant();
            return {cat("(", a.text, " * ", b.text, ")"), a.bounded && b.bounded};
        }
        case 6: { // never by zero: the divisor is at least 0.5
            Value a = sub(), d = sub();
            static const char* const kOffsets[] = {"1", "0.5", "2"};
            return {cat("(", a.text, " / (", d.text, " * ", d.text, " + ", pick(kOffsets), "))"), a.bounded};
        }
        case 7: {
            static const char* const kPeriodic[] = {"sin", "cos"};
            const char* name = pick(kPeriodic);
            return {cat(name, "(", sub().text, ")"), true};
        }
        case 8: {
            Value a = sub();
            return {cat("floor(", a.text, ")"), a.bounded};
        }
        case 9: { // of a non-negative value
            Value a = sub();
            return {cat("sqrt(", a.text, " * ", a.text, " + ", constant().text, ")"), a.bounded};
        }
        case 10: { // small integer powers of a bounded base
            Value a = sub();
            if (!a.bounded) a = {cat("sin(", a.text, ")"), true};
            return {cat("(", a.text, " ^ ", std::to_string(uniform(2, 3)), ")"), true};
        }
        case 11: {
            std::string c = condition(f, depth - 1);
            Value a = sub(), b = sub();
            return {cat("(", c, " ? ", a.text, " : ", b.text, ")"), a.bounded && b.bounded};
        }
        case 12: {
            Value a = sub();
            return {cat("(-", a.text, ")"), a.bounded};
        }
        case 13: {
            static const char* const kMinMax[] = {"min", "max"};
            Value a = sub(), b = sub();
            return {cat(pick(kMinMax), "(", a.text, ", ", b.text, ")"), a.bounded && b.bounded};
        }
        case 14: {
            Value a = sub();
            return {cat("fabs(", a.text, ")"), a.bounded};
        }
        default: {
            if (!random) return atom(f);
            if (chance(0.5)) return {cat("ran(", constant().text, ")"), true};
            Value a = sub();
            return {cat("ran(fabs(", a.text, ") + 1)"), a.bounded};
        }
        }
    }

    // Comparisons whose two sides come out the same in float and double: `==` only between floors.
    std::string condition(const Frame& f, int depth) {
        if (depth > 0 && chance(0.3)) {
            int kind = uniform(0, 2);
            std::string a = condition(f, depth - 1);
            if (kind == 2) return cat("!(", a, ")");
            std::string b = condition(f, depth - 1);
            return cat("(", a, kind == 0 ? " && " : " || ", b, ")");
        }
        if (chance(0.15)) {
            static const char* const kEquality[] = {" == ", " != "};
            std::string a = expression(f, depth, false).text;
            const char* op = pick(kEquality);
            return cat("floor(", a, ")", op, std::to_string(uniform(0, 3)));
        }
        static const char* const kComparisons[] = {" < ", " > ", " <= ", " >= "};
        std::string a = expression(f, depth, false).text;
        const char* op = pick(kComparisons);
        return cat(a, op, expression(f, depth > 1 ? 1 : 0, false).text);
    }

    // `{ t0 = ...; ... }`: locals assigned before they are read; sometimes an if/else that assigns a local
    // in both branches, or a formal parameter overwritten.
    std::string block(Frame& f) {
        std::string out = "{ ";
        int n = uniform(1, 2);
        for (int i = 0; i < n; ++i) {
            if (chance(0.15)) {
                std::string name = cat("t", std::to_string(f.nextLocal++));
                std::string c = condition(f, 1);
                std::string a = expression(f, 1, false).text, b = expression(f, 1, false).text;
                out += cat("if (", c, ") { ", name, " = ", a, "; } else { ", name, " = ", b, "; } ");
                f.vars.push_back(name);
                continue;
            }
            Value v = expression(f, 2, false);
            std::string name;
            if (!f.vars.empty() && chance(0.1)) {
                name = f.vars[static_cast<std::size_t>(uniform(0, static_cast<int>(f.vars.size()) - 1))];
                if (!v.bounded) v = {cat("(", v.text, " * 0.5)"), false};
            } else {
                name = cat("t", std::to_string(f.nextLocal++));
                f.vars.push_back(name);
            }
            out += cat(name, " = ", v.text, "; ");
        }
        return out + "}";
    }

    // ---- modules -------------------------------------------------------------------------------

    std::string successorModule(const Frame& f, bool inAxiom) {
        const Symbol& s = symbol();
        std::string out(1, s.name);
        if (s.params == 0) return out;
        out += '(';
        for (int k = 0; k < s.params; ++k) {
            if (k) out += ',';
            out += expression(f, uniform(0, 2), !inAxiom).text;
        }
        return out + ')';
    }

    // Modules with balanced, sometimes nested, branches; a cut `%` now and then inside a branch (rarely at
    // the top, where it cuts the rest of the string).
    std::string moduleList(const Frame& f, int count, int depth, bool inAxiom) {
        std::vector<std::string> items;
        for (int i = 0; i < count; ++i) {
            if (depth < 2 && chance(0.2))
                items.push_back(cat("[", moduleList(f, uniform(1, 2), depth + 1, inAxiom), "]"));
            else
                items.push_back(successorModule(f, inAxiom));
        }
        if (!inAxiom && chance(depth > 0 ? 0.12 : 0.02))
            items.insert(items.begin() + uniform(0, static_cast<int>(items.size())), "%");
        std::string out;
        for (const std::string& item : items)
            out += item;
        return out;
    }

    std::string patternModule(const Symbol& s, Frame& f) {
        std::string out(1, s.name);
        if (s.params == 0) return out;
        out += '(';
        for (int k = 0; k < s.params; ++k) {
            std::string name = cat("x", std::to_string(f.nextParam++));
            if (k) out += ',';
            out += name;
            f.vars.push_back(name);
        }
        return out + ')';
    }

    // Modules separated by blanks, so that no run of letters is mistaken for a long module name.
    std::string leftContext(Frame& f) {
        std::string out;
        int n = uniform(1, 2);
        for (int i = 0; i < n; ++i)
            out += patternModule(visibleSymbol(), f) + " ";
        return out + "< ";
    }

    // `C`, `C D`, `[C]`, `[C] D`, `[C D]`, `C [D]`, ...
    std::string rightContext(Frame& f) {
        std::string out = " >";
        int n = uniform(1, 2);
        for (int i = 0; i < n; ++i) {
            if (chance(0.3)) {
                out += " [";
                int m = uniform(1, 2);
                for (int j = 0; j < m; ++j)
                    out += cat(" ", patternModule(visibleSymbol(), f));
                out += " ]";
            } else {
                out += cat(" ", patternModule(visibleSymbol(), f));
            }
        }
        return out;
    }

    // `lc < pred > rc : { pre } cond { post } --> succ : weight`. The last production of a symbol is more
    // often unconditional, so that first-match order matters.
    std::string production(const Symbol& s, bool lastOfSymbol, bool decomposition = false) {
        Frame f;
        double contextChance = decomposition ? 0.15 : lastOfSymbol ? 0.2 : 0.45;
        std::string left = chance(contextChance) ? leftContext(f) : "";
        std::string strict = patternModule(s, f);
        std::string right = chance(contextChance) ? rightContext(f) : "";
        std::string out = left + strict + right;

        std::string guard;
        if (chance(0.2)) guard += cat(" ", block(f));
        if (chance(lastOfSymbol ? 0.3 : 0.55))
            guard += cat(" ", condition(f, uniform(0, 2)));
        else if (!guard.empty() && chance(0.3))
            guard += " *";
        if (chance(0.1)) guard += cat(" ", block(f));
        if (!guard.empty()) out += cat(" :", guard);

        out += " --> ";
        if (chance(0.08))
            out += "*";
        else
            out += moduleList(f, uniform(1, decomposition ? 3 : maxSuccessor_), 0, false);

        if (stochastic_ && chance(decomposition ? 0.3 : 0.7)) {
            static const char* const kWeights[] = {"1", "2", "3", "5", "0.25", "0.5", "0"};
            out += std::string(" : ") + pick(kWeights);
        }
        return out;
    }
};

} // namespace

std::string randomGrammarText(std::uint64_t seed) {
    return Generator(seed).grammar(seed);
}

} // namespace simeco::test
