// Evaluates IR expressions and statements for the CPU reference engine, the way cpfg does: in double
// precision (module parameters are stored as 32-bit floats), trigonometry in degrees, comparisons and
// logic yielding 1 or 0, `&&` `||` `?:` short-circuit.
#pragma once

#include <cstdint>
#include <cstdio>
#include <memory>
#include <vector>

#include "ir/grammar.h"

namespace simeco::stream {

// Where a random draw comes from: the counter-based stream of compute/shared/random.h.
struct RandomKey {
    uint32_t seed = 0;
    uint32_t plant = 0;
    uint32_t pass = 0;
    uint32_t module = 0;
    uint32_t draw = 0; // advanced by every draw
};

// The mutable state of one plant's derivation that expressions read and statements write.
struct PlantState {
    struct CloseFile {
        void operator()(std::FILE* f) const { std::fclose(f); }
    };
    std::vector<double> globals;
    std::vector<std::vector<double>> arrays;
    std::vector<std::unique_ptr<std::FILE, CloseFile>> files; // fopen handles are 1-based indices
    bool stopRequested = false;

    void reset(const ir::Grammar& g);
};

class Evaluator {
public:
    Evaluator(const ir::Grammar& g, PlantState& state) : g_(g), state_(state) {}

    double eval(const ir::Expr& e, double* frame);
    void exec(const std::vector<ir::Stmt>& stmts, double* frame);
    // A uniform number in [0, 1) from the current key, advancing its draw counter.
    double draw();

    RandomKey key;
    // What light() returns: the light of the module being rewritten, as a share of the open's.
    double light = 1.0;

private:
    const ir::Grammar& g_;
    PlantState& state_;

    double call(const ir::Expr& e, double* frame);
    double& arrayElement(int slot, const std::vector<ir::Expr>& indices, const ir::SourceLoc& loc, double* frame);
    // printf-style formatting of args[first...] with the format string args[first - 1].
    std::string format(const ir::Expr& e, size_t first, double* frame);
    double fileCall(const ir::Expr& e, double* frame);
    std::FILE* file(const ir::Expr& handle, double* frame);
};

} // namespace simeco::stream
