#include "random_plant_grammar.h"

#include <random>

#include <fmt/format.h>

namespace simeco::test {

namespace {

class Writer {
public:
    explicit Writer(uint64_t seed) : rng_(seed) {}

    std::string grammar() {
        std::string a = successor(2), b = successor(1);
        int length = pick(3, 6);
        return fmt::format("Lsystem: 1\nderivation length: {}\nAxiom: {}A\nA --> {}\nB --> {}\nendlsystem\n", length,
                           turn(), a, b);
    }

private:
    std::mt19937_64 rng_;

    int pick(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }
    double real(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }

    std::string turn() {
        static const char* kTurns[] = {"+", "-", "&", "^", "/", "\\"};
        std::string s;
        for (int k = pick(0, 2); k > 0; --k) s += fmt::format("{}({:.3g})", kTurns[pick(0, 5)], real(5.0, 95.0));
        return s;
    }

    // A successor: segments, turns and up to `branches` branches, ending in an apex so the plant grows on.
    std::string successor(int branches) {
        std::string s;
        if (pick(0, 3) == 0) s += fmt::format("!({:.3g})", real(0.02, 0.3));
        for (int k = pick(1, 3); k > 0; --k) {
            s += turn() + fmt::format("F({:.3g})", real(0.2, 2.0));
            if (branches > 0 && pick(0, 1) == 0) {
                s += "[" + turn() + fmt::format("F({:.3g})", real(0.2, 1.5)) + (pick(0, 2) ? "A" : "B") + "]";
                --branches;
            }
        }
        return s + turn() + (pick(0, 4) ? "A" : "B");
    }
};

} // namespace

std::string randomPlantGrammar(uint64_t seed) { return Writer(seed).grammar(); }

} // namespace simeco::test
