#include "stream/evaluator.h"

#include <cmath>
#include <cstdio>
#include <numbers>

#include <fmt/format.h>

#include "compute/shared/random.h"

namespace simeco::stream {

namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;
// A loop in a statement block that runs this often is taken to be endless.
constexpr long kMaxLoopIterations = 10'000'000;

} // namespace

void PlantState::reset(const ir::Grammar& g) {
    globals.assign(g.globalInit.begin(), g.globalInit.end());
    arrays.clear();
    for (const ir::GlobalArray& a : g.arrays) arrays.emplace_back(a.init.begin(), a.init.end());
    files.clear();
    stopRequested = false;
}

double Evaluator::draw() {
    return shared::randomUnit(key.seed, key.plant, key.pass, key.module, key.draw++);
}

double& Evaluator::arrayElement(int slot, const std::vector<ir::Expr>& indices, const ir::SourceLoc& loc,
                                double* frame) {
    const ir::GlobalArray& a = g_.arrays[static_cast<size_t>(slot)];
    if (indices.size() != a.dims.size())
        throw ir::InputError(loc, fmt::format("array '{}' has {} dimension(s), {} index(es) given", a.name,
                                              a.dims.size(), indices.size()));
    size_t flat = 0;
    for (size_t k = 0; k < indices.size(); ++k) {
        double v = eval(indices[k], frame);
        long index = static_cast<long>(std::floor(v));
        if (!(v >= 0) || index >= a.dims[k])
            throw ir::InputError(loc, fmt::format("index {} out of range for array '{}' (dimension {} has {} elements)",
                                                  v, a.name, k + 1, a.dims[k]));
        flat = flat * static_cast<size_t>(a.dims[k]) + static_cast<size_t>(index);
    }
    return state_.arrays[static_cast<size_t>(slot)][flat];
}

double Evaluator::eval(const ir::Expr& e, double* frame) {
    using ir::Op;
    switch (e.op) {
    case Op::Const: return e.value;
    case Op::Local: return frame[e.slot];
    case Op::Global: return state_.globals[static_cast<size_t>(e.slot)];
    case Op::ArrayElem: return arrayElement(e.slot, e.args, e.loc, frame);
    case Op::Neg: return -eval(e.args[0], frame);
    case Op::Not: return eval(e.args[0], frame) == 0.0 ? 1.0 : 0.0;
    case Op::Add: {
        double a = eval(e.args[0], frame);
        return a + eval(e.args[1], frame);
    }
    case Op::Sub: {
        double a = eval(e.args[0], frame);
        return a - eval(e.args[1], frame);
    }
    case Op::Mul: {
        double a = eval(e.args[0], frame);
        return a * eval(e.args[1], frame);
    }
    case Op::Div: {
        double a = eval(e.args[0], frame), b = eval(e.args[1], frame);
        if (b == 0.0) throw ir::InputError(e.loc, "division by zero");
        return a / b;
    }
    case Op::Mod: {
        // cpfg: both operands truncated to int, C remainder.
        long a = static_cast<long>(eval(e.args[0], frame));
        long b = static_cast<long>(eval(e.args[1], frame));
        if (b == 0) throw ir::InputError(e.loc, "remainder by zero");
        return static_cast<double>(a % b);
    }
    case Op::Pow: {
        double a = eval(e.args[0], frame);
        return std::pow(a, eval(e.args[1], frame));
    }
    case Op::Lt: {
        double a = eval(e.args[0], frame);
        return a < eval(e.args[1], frame) ? 1.0 : 0.0;
    }
    case Op::Le: {
        double a = eval(e.args[0], frame);
        return a <= eval(e.args[1], frame) ? 1.0 : 0.0;
    }
    case Op::Gt: {
        double a = eval(e.args[0], frame);
        return a > eval(e.args[1], frame) ? 1.0 : 0.0;
    }
    case Op::Ge: {
        double a = eval(e.args[0], frame);
        return a >= eval(e.args[1], frame) ? 1.0 : 0.0;
    }
    case Op::Eq: {
        double a = eval(e.args[0], frame);
        return a == eval(e.args[1], frame) ? 1.0 : 0.0;
    }
    case Op::Ne: {
        double a = eval(e.args[0], frame);
        return a != eval(e.args[1], frame) ? 1.0 : 0.0;
    }
    case Op::And: return (eval(e.args[0], frame) != 0.0 && eval(e.args[1], frame) != 0.0) ? 1.0 : 0.0;
    case Op::Or: return (eval(e.args[0], frame) != 0.0 || eval(e.args[1], frame) != 0.0) ? 1.0 : 0.0;
    case Op::Select: return eval(e.args[0], frame) != 0.0 ? eval(e.args[1], frame) : eval(e.args[2], frame);
    case Op::Call: return call(e, frame);
    case Op::String: throw ir::InputError(e.loc, "a string is not a number");
    }
    return 0.0;
}

double Evaluator::call(const ir::Expr& e, double* frame) {
    using ir::Builtin;
    auto arg = [&](size_t i) { return eval(e.args[i], frame); };
    switch (e.fn) {
    case Builtin::Sin: return std::sin(arg(0) / kDegrees);
    case Builtin::Cos: return std::cos(arg(0) / kDegrees);
    case Builtin::Tan: return std::tan(arg(0) / kDegrees);
    case Builtin::Asin: return std::asin(arg(0)) * kDegrees;
    case Builtin::Acos: return std::acos(arg(0)) * kDegrees;
    case Builtin::Atan: return std::atan(arg(0)) * kDegrees;
    case Builtin::Atan2: {
        double x = arg(0);
        return std::atan2(arg(1), x) * kDegrees;
    }
    case Builtin::Exp: return std::exp(arg(0));
    case Builtin::Log: return std::log(arg(0));
    case Builtin::Sqrt: return std::sqrt(arg(0));
    case Builtin::Fabs: return std::fabs(arg(0));
    case Builtin::Floor: return std::floor(arg(0));
    case Builtin::Ceil: return std::ceil(arg(0));
    case Builtin::Trunc: return std::floor(arg(0) + 0.5); // cpfg's trunc rounds half up
    case Builtin::Sign: {
        double v = arg(0);
        return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0;
    }
    case Builtin::Pow:
    case Builtin::Min:
    case Builtin::Max: {
        double a = arg(0), b = arg(1);
        return e.fn == Builtin::Pow ? std::pow(a, b) : e.fn == Builtin::Min ? std::min(a, b) : std::max(a, b);
    }
    case Builtin::Ran: {
        double scale = arg(0);
        return draw() * scale;
    }
    case Builtin::Nran: {
        double mean = arg(0), sd = arg(1);
        double u1 = draw(), u2 = draw();
        return mean + sd * std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }
    case Builtin::Bran: {
        // Beta(a, b) as X / (X + Y) with X ~ Gamma(a), Y ~ Gamma(b) (Marsaglia-Tsang, bounded tries).
        double a = arg(0), b = arg(1);
        if (!(a > 0) || !(b > 0)) throw ir::InputError(e.loc, "bran(a, b) needs a > 0 and b > 0");
        auto gamma = [&](double shape) {
            double boost = 1.0;
            if (shape < 1.0) {
                boost = std::pow(1.0 - draw(), 1.0 / shape);
                shape += 1.0;
            }
            double d = shape - 1.0 / 3.0, c = 1.0 / std::sqrt(9.0 * d);
            for (int tries = 0; tries < 64; ++tries) {
                double u1 = draw(), u2 = draw();
                double z = std::sqrt(-2.0 * std::log(1.0 - u1)) * std::cos(2.0 * std::numbers::pi * u2);
                double v = 1.0 + c * z;
                if (v <= 0) continue;
                v = v * v * v;
                double u = draw();
                if (std::log(1.0 - u) < 0.5 * z * z + d - d * v + d * std::log(v)) return d * v * boost;
            }
            return d * boost;
        };
        double x = gamma(a), y = gamma(b);
        return x / (x + y);
    }
    case Builtin::Biran: {
        double n = arg(0), p = arg(1);
        if (n < 0 || n > 1e6) throw ir::InputError(e.loc, "biran(n, p) needs 0 <= n <= 1000000");
        int count = 0;
        for (long i = 0; i < static_cast<long>(n); ++i) count += draw() <= p ? 1 : 0;
        return count;
    }
    case Builtin::Srand: arg(0); return 0.0;
    case Builtin::Func: {
        double id = arg(0), x = arg(1);
        long index = static_cast<long>(id);
        if (index < 1 || index > static_cast<long>(g_.functions.size()))
            throw ir::InputError(e.loc, fmt::format("func({}, x): no such function (the view file defines {})",
                                                    index, g_.functions.size()));
        return ir::evaluateCurve(g_.functions[static_cast<size_t>(index - 1)], x);
    }
    case Builtin::CurveX:
    case Builtin::CurveY:
    case Builtin::CurveZ:
    case Builtin::CurveGal: {
        long index = static_cast<long>(arg(0));
        if (index < 1 || index > static_cast<long>(g_.curves.size()))
            throw ir::InputError(e.loc, fmt::format("{}({}, ...): no such curve (the view file defines {})",
                                                    ir::builtinName(e.fn), index, g_.curves.size()));
        const ir::ContourCurve& c = g_.curves[static_cast<size_t>(index - 1)];
        if (e.fn == Builtin::CurveGal) return ir::curveLength(c);
        return ir::curveCoordinate(c, static_cast<int>(e.fn) - static_cast<int>(Builtin::CurveX), arg(1));
    }
    case Builtin::Printf: {
        std::string text = format(e, 1, frame);
        std::fputs(text.c_str(), stderr);
        return 0.0;
    }
    case Builtin::Fopen:
    case Builtin::Fclose:
    case Builtin::Fflush:
    case Builtin::Fprintf:
    case Builtin::Fscanf: return fileCall(e, frame);
    case Builtin::Stop:
        if (e.args.empty() || arg(0) != 0.0) state_.stopRequested = true;
        return 0.0;
    case Builtin::Light: return light;
    }
    return 0.0;
}

std::FILE* Evaluator::file(const ir::Expr& handle, double* frame) {
    long index = static_cast<long>(eval(handle, frame));
    if (index < 1 || index > static_cast<long>(state_.files.size()) || !state_.files[size_t(index - 1)])
        throw ir::InputError(handle.loc, fmt::format("{} is not an open file", index));
    return state_.files[size_t(index - 1)].get();
}

// Files a model opens with fopen live as long as the plant's derivation; handles are 1-based.
double Evaluator::fileCall(const ir::Expr& e, double* frame) {
    using ir::Builtin;
    switch (e.fn) {
    case Builtin::Fopen: {
        const std::string& mode = e.args[1].text;
        if (mode != "r" && mode != "w" && mode != "a")
            throw ir::InputError(e.args[1].loc, "fopen mode must be \"r\", \"w\" or \"a\"");
        std::FILE* f = std::fopen(e.args[0].text.c_str(), mode.c_str());
        if (!f) throw ir::InputError(e.loc, fmt::format("cannot open '{}'", e.args[0].text));
        state_.files.emplace_back(f);
        return static_cast<double>(state_.files.size());
    }
    case Builtin::Fclose: {
        file(e.args[0], frame);
        state_.files[size_t(eval(e.args[0], frame)) - 1].reset();
        return 0.0;
    }
    case Builtin::Fflush: std::fflush(file(e.args[0], frame)); return 0.0;
    case Builtin::Fprintf: {
        std::FILE* f = file(e.args[0], frame);
        std::string text = format(e, 2, frame);
        std::fputs(text.c_str(), f);
        return 0.0;
    }
    case Builtin::Fscanf: {
        std::FILE* f = file(e.args[0], frame);
        int stored = 0;
        for (size_t i = 2; i < e.args.size(); ++i) {
            double v = 0;
            if (std::fscanf(f, "%lf", &v) != 1) break;
            if (e.args[i].op == ir::Op::Local) frame[e.args[i].slot] = v;
            else state_.globals[size_t(e.args[i].slot)] = v;
            ++stored;
        }
        return stored;
    }
    default: return 0.0;
    }
}

std::string Evaluator::format(const ir::Expr& e, size_t first, double* frame) {
    const std::string& format = e.args[first - 1].text;
    std::string out;
    size_t next = first;
    for (size_t i = 0; i < format.size(); ++i) {
        if (format[i] != '%') {
            out.push_back(format[i]);
            continue;
        }
        if (i + 1 < format.size() && format[i + 1] == '%') {
            out.push_back('%');
            ++i;
            continue;
        }
        std::string spec = "%";
        size_t j = i + 1;
        while (j < format.size() && std::string("-+ #0123456789.").find(format[j]) != std::string::npos)
            spec.push_back(format[j++]);
        while (j < format.size() && (format[j] == 'l' || format[j] == 'h')) ++j;
        char conv = j < format.size() ? format[j] : 'g';
        double value = next < e.args.size() ? eval(e.args[next++], frame) : 0.0;
        char buffer[128];
        if (conv == 'd' || conv == 'i' || conv == 'c' || conv == 'x')
            std::snprintf(buffer, sizeof buffer, (spec + (conv == 'c' ? 'd' : conv)).c_str(), static_cast<int>(value));
        else
            std::snprintf(buffer, sizeof buffer,
                          (spec + (std::string("feEgG").find(conv) != std::string::npos ? conv : 'g')).c_str(), value);
        out += buffer;
        i = j;
    }
    return out;
}

void Evaluator::exec(const std::vector<ir::Stmt>& stmts, double* frame) {
    for (const ir::Stmt& s : stmts) {
        switch (s.kind) {
        case ir::StmtKind::Assign: {
            double v = eval(s.expr, frame);
            if (s.target == ir::TargetKind::Local) frame[s.slot] = v;
            else if (s.target == ir::TargetKind::Global) state_.globals[static_cast<size_t>(s.slot)] = v;
            else arrayElement(s.slot, s.indices, s.loc, frame) = v;
            break;
        }
        case ir::StmtKind::If:
            if (eval(s.expr, frame) != 0.0) exec(s.body, frame);
            else exec(s.elseBody, frame);
            break;
        case ir::StmtKind::While:
        case ir::StmtKind::DoWhile: {
            long iterations = 0;
            if (s.kind == ir::StmtKind::DoWhile) exec(s.body, frame);
            while (eval(s.expr, frame) != 0.0) {
                if (++iterations > kMaxLoopIterations)
                    throw ir::InputError(s.loc, fmt::format("loop still running after {} iterations", kMaxLoopIterations));
                exec(s.body, frame);
            }
            break;
        }
        case ir::StmtKind::Eval: eval(s.expr, frame); break;
        }
    }
}

} // namespace simeco::stream
