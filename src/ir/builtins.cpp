#include "ir/expr.h"

namespace simeco::ir {

const std::vector<BuiltinInfo>& builtinTable() {
    static const std::vector<BuiltinInfo> table = {
        {"sin", Builtin::Sin, 1, 1},     {"cos", Builtin::Cos, 1, 1},       {"tan", Builtin::Tan, 1, 1},
        {"asin", Builtin::Asin, 1, 1},   {"acos", Builtin::Acos, 1, 1},     {"atan", Builtin::Atan, 1, 2},
        {"atan2", Builtin::Atan2, 2, 2}, {"exp", Builtin::Exp, 1, 1},       {"log", Builtin::Log, 1, 1},
        {"sqrt", Builtin::Sqrt, 1, 1},   {"fabs", Builtin::Fabs, 1, 1},     {"abs", Builtin::Fabs, 1, 1},
        {"floor", Builtin::Floor, 1, 1}, {"ceil", Builtin::Ceil, 1, 1},     {"trunc", Builtin::Trunc, 1, 1},
        {"sign", Builtin::Sign, 1, 1},   {"pow", Builtin::Pow, 2, 2},       {"min", Builtin::Min, 2, 2},
        {"max", Builtin::Max, 2, 2},     {"ran", Builtin::Ran, 1, 1},       {"nran", Builtin::Nran, 2, 2},
        {"bran", Builtin::Bran, 2, 2},   {"biran", Builtin::Biran, 2, 2},   {"srand", Builtin::Srand, 1, 1},
        {"func", Builtin::Func, 2, 2},   {"curveX", Builtin::CurveX, 2, 2}, {"curveY", Builtin::CurveY, 2, 2},
        {"curveZ", Builtin::CurveZ, 2, 2}, {"curveGAL", Builtin::CurveGal, 1, 1},
        {"fopen", Builtin::Fopen, 2, 2}, {"fclose", Builtin::Fclose, 1, 1}, {"fflush", Builtin::Fflush, 1, 1},
        {"fprintf", Builtin::Fprintf, 2, 64}, {"fscanf", Builtin::Fscanf, 2, 64},   {"printf", Builtin::Printf, 1, 64}, {"stop", Builtin::Stop, 0, 1},
        {"light", Builtin::Light, 0, 0},
    };
    return table;
}

const BuiltinInfo* findBuiltin(const std::string& name) {
    for (const BuiltinInfo& info : builtinTable())
        if (name == info.name) return &info;
    return nullptr;
}

const char* builtinName(Builtin fn) {
    for (const BuiltinInfo& info : builtinTable())
        if (info.fn == fn) return info.name;
    return "?";
}

} // namespace simeco::ir
