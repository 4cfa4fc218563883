// Expressions and statements of the grammar IR.
//
// Every front end (cpfg `.l`, SimEco `.eco`, quick grammars) lowers its expressions to this tree. The CPU
// reference engine evaluates it directly; the GPU back end turns it into straight-line GLSL. Names are
// resolved at parse time: a production's formal parameters and local variables are slots in a per-production
// frame, global variables and arrays are slots in the grammar.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ir/source_loc.h"

namespace simeco::ir {

enum class Builtin : uint8_t {
    Sin, Cos, Tan, Asin, Acos, Atan, Atan2, Exp, Log, Sqrt, Fabs, Floor, Ceil, Trunc, Sign, Pow, Min, Max,
    Ran,    // ran(x): uniform in [0, x), from the counter-based stream
    Nran,   // nran(mean, sd): normal
    Bran,   // bran(a, b): beta distribution
    Biran,  // biran(n, p): binomial count
    Srand,  // srand(seed): accepted for compatibility; streams are keyed by position, so it has no effect
    Func,   // func(id, x): user-defined function table
    CurveX, CurveY, CurveZ, // curveX(id, t): a point of a contour curve
    CurveGal, // curveGAL(id): the length of a contour curve
    Fopen, Fclose, Fflush, Fprintf, Fscanf, // file input and output from control blocks
    Printf, // printf("...", ...): evaluated for its arguments, prints nothing in derivation
    Stop,   // stop(n): ends the derivation after the current step
    Light,  // light(): the light the rewritten module's particle had, as a share of the open's (1 without a grid)
};

struct BuiltinInfo {
    const char* name;
    Builtin fn;
    int minArgs;
    int maxArgs;
};
// The table of builtins that expressions may call, for parsers and code generators.
const std::vector<BuiltinInfo>& builtinTable();
const BuiltinInfo* findBuiltin(const std::string& name);
const char* builtinName(Builtin fn);

enum class Op : uint8_t {
    Const,     // value
    Local,     // slot in the production's frame (formal parameters first, then locals)
    Global,    // slot in the grammar's global variables
    ArrayElem, // array `slot`, args = indices
    Neg, Not,
    Add, Sub, Mul, Div, Mod, Pow,
    Lt, Le, Gt, Ge, Eq, Ne,
    And, Or,
    Select,    // args[0] ? args[1] : args[2]
    Call,      // builtin `fn` with args
    String,    // a string literal (only as a printf argument)
};

struct Expr {
    Op op = Op::Const;
    Builtin fn = Builtin::Sin;
    double value = 0.0; // Const: cpfg reads literals in double precision
    int slot = 0;
    std::vector<Expr> args;
    std::string text; // String: the literal's characters
    SourceLoc loc;

    static Expr constant(double v, SourceLoc l = {}) {
        Expr e;
        e.op = Op::Const;
        e.value = v;
        e.loc = std::move(l);
        return e;
    }
    bool isConst() const { return op == Op::Const; }
};

enum class StmtKind : uint8_t { Assign, If, While, DoWhile, Eval };

// Where an assignment writes.
enum class TargetKind : uint8_t { Local, Global, ArrayElem };

struct Stmt {
    StmtKind kind = StmtKind::Eval;
    TargetKind target = TargetKind::Local;
    int slot = 0;              // local, global or array slot of the target
    std::vector<Expr> indices; // array indices of the target
    Expr expr;                 // assigned value, or the condition of if/while/do
    std::vector<Stmt> body;
    std::vector<Stmt> elseBody;
    SourceLoc loc;
};

} // namespace simeco::ir
