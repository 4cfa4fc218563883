#include "codegen/kernel_traits.h"

#include <algorithm>

#include <fmt/format.h>

#include "codegen/context_codegen.h"
#include "codegen/hoisted_constants.h"
#include "codegen/production_analysis.h"
#include "compute/shaders.h"

namespace simeco::codegen {

bool mayLoopLong(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing) {
    // Well inside lavapipe's 65535 iterations, with room for the plant search and parameter copies.
    constexpr uint64_t kMostIterations = 8192;
    // The elementary functions of derive_lib.glsl and contour_curve.glsl loop at most this often per call.
    constexpr uint64_t kMostPerCall = 64;
    uint64_t iterations = 0;
    bool unbounded = false;
    auto countCalls = [&](const ir::Expr& e) {
        using ir::Builtin;
        if (e.op == ir::Op::Pow) iterations += kMostPerCall;
        if (e.op != ir::Op::Call) return;
        switch (e.fn) {
        case Builtin::Biran: unbounded = true; break;
        case Builtin::Exp: case Builtin::Log: case Builtin::Pow: case Builtin::Atan: case Builtin::Atan2:
        case Builtin::Asin: case Builtin::Acos: case Builtin::Nran: case Builtin::CurveX: case Builtin::CurveY:
        case Builtin::CurveZ:
            iterations += kMostPerCall;
            break;
        default: break;
        }
    };
    auto countLoops = [&](const ir::Stmt& st) {
        if (st.kind == ir::StmtKind::While || st.kind == ir::StmtKind::DoWhile) unbounded = true;
    };
    for (const ir::Grammar& g : species)
        for (const ir::Production& p : (kind == RuleKind::Step ? g.productions : g.decomposition).productions) {
            // Context walks pass any number of modules.
            if (writing ? writingWalks(p, p.left) || writingWalks(p, p.right) : !p.left.empty() || !p.right.empty())
                return true;
            walkProductionCode(p, countCalls, countLoops);
        }
    return unbounded || iterations > kMostIterations;
}

PlantInputs plantInputs(const std::vector<ir::Grammar>& species, RuleKind kind, bool writing, bool alternativesGiven) {
    PlantInputs in;
    in.plant = species.size() > 1; // a plant's species is its index modulo their number
    auto scanExpr = [&](const ir::Expr& e) {
        if (e.op == ir::Op::Global || e.op == ir::Op::ArrayElem || isHoisted(e)) in.plant = true;
        if (e.op != ir::Op::Call) return;
        switch (e.fn) {
        case ir::Builtin::Ran: case ir::Builtin::Nran: case ir::Builtin::Biran: in.random = true; break;
        case ir::Builtin::Stop: in.plant = true; break;
        default: break;
        }
    };
    auto scanStatement = [&](const ir::Stmt& st) {
        if (st.kind == ir::StmtKind::Assign && st.target != ir::TargetKind::Local) in.plant = true;
    };
    for (const ir::Grammar& g : species) {
        const ir::RuleSet& rules = kind == RuleKind::Step ? g.productions : g.decomposition;
        if (isStochastic(rules) && !writing) in.random = true;
        for (const ir::Production& p : rules.productions) {
            // A writing pass applies what the match chose: it walks only the contexts whose parameters it reads
            // (writingWalks), and the further modules of a predecessor are known to lie within the plant.
            bool walks = writing ? writingWalks(p, p.left) || writingWalks(p, p.right) : !p.left.empty() || !p.right.empty();
            if (walks || (!writing && p.strict.size() > 1)) in.bounds = true;
            if (p.alternatives.size() > 1 && !(writing && alternativesGiven)) in.random = true;
            walkProductionCode(p, scanExpr, scanStatement);
        }
    }
    if (in.random) in.bounds = true; // a draw's key is the module's index in its plant
    if (in.bounds) in.plant = true;
    return in;
}

std::string functionTableCode(const ir::Grammar& g, size_t species, std::vector<double>& tables) {
    std::string code = fmt::format("double funcValue{}(double idValue, double x, uint errorSite) {{\n"
                                   "    int id = int(idValue);\n", species);
    code += "    uint offset = 0u; int samples = 0;\n";
    for (size_t f = 0; f < g.functions.size(); ++f) {
        code += fmt::format("    if (id == {}) {{ offset = {}u; samples = {}; }}\n", f + 1, tables.size(),
                            g.functions[f].samples);
        tables.insert(tables.end(), g.functions[f].table.begin(), g.functions[f].table.end());
    }
    code += "    if (samples == 0) { reportError(errorSite); return 0.0LF; }\n"
            "    if (x < 0.0LF) x = 0.0LF;\n"
            "    if (x > 1.0LF) x = 1.0LF;\n"
            "    double index = x * double(samples - 1);\n"
            "    int i = int(floor(index));\n"
            "    double w2 = index - double(i), w1 = 1.0LF - w2;\n"
            "    if (i >= samples - 1) return funcTables[offset + uint(samples - 1)];\n"
            "    return w1 * funcTables[offset + uint(i)] + w2 * funcTables[offset + uint(i + 1)];\n"
            "}\n\n";
    return code;
}

std::string perSpecies(size_t count, const std::function<std::string(size_t)>& body) {
    std::string code = "    switch (species) {\n";
    for (size_t sp = 0; sp < count; ++sp) code += fmt::format("    case {}u: {{\n{}        break;\n    }}\n", sp, body(sp));
    return code + "    }\n";
}

bool isStochastic(const ir::RuleSet& rules) {
    return std::any_of(rules.productions.begin(), rules.productions.end(),
                       [](const ir::Production& p) { return p.weight >= 0; });
}

GeneratedKernels speciesTraits(const std::vector<ir::Grammar>& species) {
    GeneratedKernels k;
    for (const ir::Grammar& g : species) {
        if (!g.decomposition.productions.empty() && g.decomposition.maxDepth > 0) {
            k.hasDecomposition = true;
            k.maxDecompositionDepth = std::max(k.maxDecompositionDepth, g.decomposition.maxDepth);
        }
        for (const ir::RuleSet* rules : {&g.productions, &g.decomposition})
            for (const ir::Production& p : rules->productions) {
                if (!p.left.empty() || !p.right.empty()) k.needsBrackets = true;
                for (const ir::Alternative& alt : p.alternatives)
                    for (const ir::SuccessorModule& m : alt.modules)
                        if (m.sym == ir::kCut) k.mayCut = true;
            }
        for (const ir::SuccessorModule& m : g.axiom)
            if (m.sym == ir::kCut) k.mayCut = true;
        for (const ir::Production& p : g.productions.productions)
            k.longestPredecessor = std::max<uint32_t>(k.longestPredecessor, static_cast<uint32_t>(p.strict.size()));
        auto sensesLight = [&](const ir::Expr& e) {
            if (e.op == ir::Op::Call && e.fn == ir::Builtin::Light) k.readsLight = true;
        };
        for (const ir::RuleSet* rules : {&g.productions, &g.decomposition})
            for (const ir::Production& p : rules->productions) walkProductionCode(p, sensesLight, [](const ir::Stmt&) {});
    }
    if (k.mayCut) k.needsBrackets = true;
    return k;
}

std::string deriveLibrary(const SpeciesClasses& classes) {
    return speciesCode(classes) +
           std::string(shaders::glslSource("compute/derive/depth_tree.glsl")) +
           std::string(shaders::glslSource("compute/derive/derive_lib.glsl")) +
           std::string(shaders::glslSource("compute/derive/contour_curve.glsl"));
}

std::vector<uint32_t> speciesTable(const SpeciesClasses& classes) {
    std::vector<uint32_t> table = contextSkipBits(classes.representatives);
    if (!classes.distinct()) table.insert(table.end(), classes.classOf.begin(), classes.classOf.end());
    if (!classes.hoists()) return table;
    uint32_t at = 0;
    for (const std::vector<double>& row : classes.hoisted) {
        table.push_back(at);
        at += static_cast<uint32_t>(row.size());
    }
    return table;
}

std::vector<double> hoistedTable(const SpeciesClasses& classes) {
    std::vector<double> values;
    for (const std::vector<double>& row : classes.hoisted) values.insert(values.end(), row.begin(), row.end());
    return values;
}

std::string speciesCode(const SpeciesClasses& classes) {
    std::vector<uint32_t> skipBits = contextSkipBits(classes.representatives);
    std::string code = contextSkipCode(skipBits);
    if (classes.distinct()) return code + "uint speciesOf(uint plant) { return plant % kSpeciesCount; }\n";
    // A constant array would be copied into every invocation's private memory by some drivers (lavapipe).
    code += fmt::format("uint speciesOf(uint plant) {{ return speciesTable[{}u + plant % kSpeciesCount]; }}\n",
                        skipBits.size());
    if (!classes.hoists()) return code;
    return code + fmt::format("double hoisted(uint plant, uint k) {{\n"
                              "    return funcTables[speciesTable[{}u + plant % kSpeciesCount] + k];\n"
                              "}}\n",
                              skipBits.size() + classes.classOf.size());
}

std::string kernelPrelude(size_t speciesCount) {
    std::string s = "#version 460\n"
                    "#extension GL_EXT_shader_explicit_arithmetic_types_float64 : require\n"
                    "#extension GL_KHR_shader_subgroup_basic : require\n"
                    "#extension GL_KHR_shader_subgroup_arithmetic : require\n"
                    "#extension GL_EXT_spirv_intrinsics : require\n";
    // Expressions are evaluated in doubles as IEEE arithmetic, as the CPU reference (and cpfg) evaluates them:
    // infinities and NaN stay what they are (inf - inf is NaN), where a driver may otherwise fold x - x to 0.
    // SignedZeroInfNanPreserve (4461) for 64-bit floats, with its capability (4466); devices without it are
    // unsuitable (vk::listPhysicalDevices).
    s += "spirv_execution_mode(extensions = [\"SPV_KHR_float_controls\"], capabilities = [4466], 4461, 64);\n";
    s += std::string(shaders::glslSource("compute/shared/derive_layout.h"));
    s += std::string(shaders::glslSource("compute/shared/random.h"));
    s += "layout(local_size_x = kDeriveWorkgroupSize) in;\n"
         "layout(push_constant) uniform Push { DerivePush pc; };\n";
    s += fmt::format("const uint kSpeciesCount = {}u; // plant p is of species p % kSpeciesCount\n", speciesCount);
    return s;
}

} // namespace simeco::codegen
