// The sequential strategy's kernel: one invocation per plant, walking the plant's string in order the way
// cpu/derive.cpp does (rewrite(), decompose(), emit()), so that the side effects of productions (globals,
// arrays, persistent locals, stop()) happen in cpfg's order. Plants still run in parallel with each other.
#include <algorithm>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "codegen/curve_codegen.h"
#include "codegen/derive_codegen.h"
#include "codegen/kernel_traits.h"
#include "codegen/production_codegen.h"
#include "codegen/species_classes.h"

namespace simeco::codegen {

namespace {

using codegen::FrameStyle;
using codegen::functionName;
using codegen::literal;
using codegen::RuleKind;

std::string declarations(bool texelInputs) {
    codegen::Bindings b(texelInputs);
    b.addShared(true);
    b.add("", "double", "frames");    // the productions' persistent locals, kFrameSlots per plant
    b.add("", "uint", "stackSym");    // the decomposition stack: pc.stackLevels * kStackWidth modules per plant
    b.add("", "float", "stackPar");
    b.add("", "uint", "stackState");  // per plant and level: modules, the next one; then the depth counters
    b.add("writeonly", "uint", "plantCounts");
    b.add("readonly", "uint", "outStart");
    b.add("writeonly", "uint", "symOut");
    b.add("writeonly", "float", "parOut");
    b.add("", "uint", "resume");      // per plant between dispatches: the next input module, the output position,
                                      // and a suspended decomposition's level + 1 (0: none) and first input module
    b.add("writeonly", "uint", "originOut"); // each written module's origin: the input module it descends from
    return b.text();
}

// Where the productions write and how modules move between the string, the stack and the output.
const char* kMachinery = R"(
uint gPass;          // the random stream pass of the module being rewritten
bool gToStack;       // successors go to the decomposition stack, else to the output
uint gBase;          // where a successor's first module goes
uint gState;         // the plant's first word in stackState
uint gStack;         // the plant's first module in the stack
bool gAbort = false; // the stack is full or the plant outgrew the limit: stop, the host reacts
// Work done in this dispatch: input modules and decomposition steps. A dispatch does pc.chunk of it, then the plant
// goes on in the next dispatch, so that no invocation loops long (see kFlagLoopCut).
uint gWork = 0u;
uint gSuspendedTop;  // the stack level a suspended decomposition goes on from
uint gOrigin;        // the input module whose successor (or decomposition) is being written

const uint kDecomposed = 0u;
const uint kNotDecomposed = 1u; // an original module to which no production applies at depth 0
const uint kDecompositionSuspended = 2u;

uint currentPass() { return gPass; }
// The plant stops after this step, as on the CPU: its remaining modules in this pass are still rewritten.
void requestStop(uint plant) { if (pc.mode == 1u) plantFrozen[plant] = kPlantStopRequested; }
double strictParam(uint i, uint k) { return double(stackPar[i * pc.stride + k]); }
uint levelBase(uint level) { return gStack + level * kStackWidth; }

void emitModule(uint pos, uint sym, uint count, uint origin) {
    if (gToStack) stackSym[gBase + pos] = sym | (count << kSymbolBits);
    else if (pc.mode == 1u) {
        symOut[gBase + pos] = sym | (count << kSymbolBits);
        originOut[gBase + pos] = gOrigin;
    }
}
void emitParam(uint pos, uint k, double value) {
    if (gToStack) stackPar[(gBase + pos) * pc.stride + k] = float(value);
    else if (pc.mode == 1u) parOut[(gBase + pos) * pc.stride + k] = float(value);
}
void emitPartners(uint open, uint close) {} // the next step matches brackets afresh

void advanceOutput(inout uint next, uint n) {
    next += n;
    if (pc.mode == 0u && next > pc.moduleLimit) {
        atomicOr(errors[1], kFlagOverLimit);
        gAbort = true;
    }
}
// The counting pass runs the parameter loops too, without writing: a driver that ends an invocation's loops after
// a number of iterations in all (kFlagLoopCut) then cuts the counting pass whenever it would cut the writing pass,
// and the host retries the step in smaller chunks before anything is written.
void outputFromInput(uint i, inout uint next) {
    if (pc.mode == 1u) {
        symOut[next] = symInAt(i);
        originOut[next] = i;
    }
    for (uint k = 0u; k < (symInAt(i) >> kSymbolBits); ++k)
        if (pc.mode == 1u) parOut[next * pc.stride + k] = parInAt(i * pc.stride + k);
    advanceOutput(next, 1u);
}
void outputFromStack(uint slot, inout uint next) {
    if (pc.mode == 1u) {
        symOut[next] = stackSym[slot];
        originOut[next] = gOrigin;
    }
    for (uint k = 0u; k < (stackSym[slot] >> kSymbolBits); ++k)
        if (pc.mode == 1u) parOut[next * pc.stride + k] = stackPar[slot * pc.stride + k];
    advanceOutput(next, 1u);
}
void stackFromInput(uint i, uint slot) {
    stackSym[slot] = symInAt(i);
    for (uint k = 0u; k < (symInAt(i) >> kSymbolBits); ++k) stackPar[slot * pc.stride + k] = parInAt(i * pc.stride + k);
}
uint levelCountAt(uint level) { return gState + 2u * level; }
uint depthCounterAt(uint depth) { return gState + 2u * pc.stackLevels + depth; }

)";

// Offsets of each production's persistent locals in a plant's frame block.
struct FrameLayout {
    std::vector<std::vector<uint32_t>> step, decomposition; // [species][production]
    uint32_t slots = 0;                                     // the most any species needs
};

FrameLayout layoutFrames(const std::vector<ir::Grammar>& species) {
    FrameLayout layout;
    for (const ir::Grammar& g : species) {
        uint32_t offset = 0;
        auto place = [&](const ir::RuleSet& rules, std::vector<uint32_t>& offsets) {
            for (const ir::Production& p : rules.productions) {
                offsets.push_back(offset);
                offset += static_cast<uint32_t>(p.frameSize);
            }
        };
        layout.step.emplace_back();
        layout.decomposition.emplace_back();
        place(g.productions, layout.step.back());
        place(g.decomposition, layout.decomposition.back());
        layout.slots = std::max(layout.slots, offset);
    }
    return layout;
}

// The choice among the productions for `sym` as cpu/derive.cpp makes it: tests in file order, each running
// once with its side effects, the first applicable one (or a weighted draw among all applicable ones).
// Leaves `chosen` (index + 1, 0 for none) and `length`.
std::string selection(const ir::RuleSet& rules, size_t species, RuleKind kind, const std::vector<uint32_t>& frames) {
    std::map<ir::SymbolId, std::vector<size_t>> bySymbol;
    for (size_t i = 0; i < rules.productions.size(); ++i)
        if (kind == RuleKind::Step || rules.productions[i].strict.size() == 1)
            bySymbol[rules.productions[i].strict[0].sym].push_back(i);
    bool stochastic = codegen::isStochastic(rules);
    auto test = [&](size_t pi) {
        const ir::Production& p = rules.productions[pi];
        return fmt::format("count == {}u && {}Test(i, plant, key, pBegin, pEnd, ctxLeft, ctxRight, draw, frameBase + {}u)",
                           p.strict[0].paramSlots.size(), functionName(species, kind, pi), frames[pi]);
    };
    std::string code = "    switch (sym) {\n";
    for (const auto& [sym, list] : bySymbol) {
        code += fmt::format("    case {}u: {{\n", sym);
        if (!stochastic) {
            // Flat tests rather than an else-if chain: lavapipe loses code nested deeper than 80 levels.
            for (size_t pi : list)
                code += fmt::format("        if (chosen == 0u && {}) {{ chosen = {}u; length = {}u; }}\n", test(pi),
                                    pi + 1, rules.productions[pi].strict.size());
        } else {
            code += "        double total = 0.0LF;\n        bool any = false;\n";
            for (size_t pi : list) {
                std::string weight = literal(static_cast<double>(std::max(rules.productions[pi].weight, 0.0f)));
                code += fmt::format("        bool applicable{0} = {1};\n"
                                    "        if (applicable{0}) {{ total += {2}; any = true; }}\n",
                                    pi, test(pi), weight);
            }
            code += "        if (any) {\n"
                    "            double left = total * double(randomUnit(pc.seed, pc.firstPlant + plant, "
                    "currentPass(), key, 0u));\n"
                    "            bool done = false;\n";
            for (size_t pi : list) {
                const ir::Production& p = rules.productions[pi];
                code += fmt::format("            if (!done && applicable{0}) {{ chosen = {1}u; length = {2}u; left -= {3}; "
                                    "done = left <= 0.0LF; }}\n",
                                    pi, pi + 1, p.strict.size(), literal(static_cast<double>(std::max(p.weight, 0.0f))));
            }
            code += "        }\n";
        }
        code += "        break;\n    }\n";
    }
    return code + "    }\n";
}

// Runs the chosen production's after-statements and writes its successor where gToStack/gBase say.
std::string produce(const ir::RuleSet& rules, size_t species, RuleKind kind, const std::vector<uint32_t>& frames) {
    std::string code = "    uint produced = 0u;\n    switch (chosen) {\n";
    for (size_t pi = 0; pi < rules.productions.size(); ++pi)
        code += fmt::format("    case {}u: {}Produce(plant, key, draw, produced, frameBase + {}u); break;\n", pi + 1,
                            functionName(species, kind, pi), frames[pi]);
    return code + "    }\n";
}

// Depth-first decomposition of the stack from level `top` on (cpu/derive.cpp decompose()): kNotDecomposed when
// `original` (level 0 holds one module of the string) and no production applies to it at depth 0;
// kDecompositionSuspended when the dispatch's work is done (it goes on from gSuspendedTop). Every call takes at
// least one step, so an original module is always examined before a suspension.
std::string decomposeFunction(const ir::Grammar& g, size_t sp, const FrameLayout& frames) {
    std::string s = fmt::format(
        "uint s{}Decompose(uint plant, uint pBegin, uint pEnd, int ctxLeft, uint ctxRight, bool original, uint top, "
        "inout uint next) {{\n"
        "    uint frameBase = plant * kFrameSlots;\n"
        "    bool first = true;\n"
        "    for (;;) {{\n"
        "        if (gAbort) return kDecomposed;\n"
        "        if (!first && gWork >= pc.chunk) {{ gSuspendedTop = top; return kDecompositionSuspended; }}\n"
        "        first = false;\n"
        "        ++gWork;\n"
        "        uint at = levelCountAt(top);\n"
        "        if (stackState[at + 1u] == stackState[at]) {{\n"
        "            if (top == 0u) return kDecomposed;\n"
        "            --top;\n"
        "            continue;\n"
        "        }}\n"
        "        uint i = levelBase(top) + stackState[at + 1u];\n"
        "        stackState[at + 1u] += 1u;\n"
        "        uint depth = top;\n"
        "        uint sym = stackSym[i] & kSymbolMask, count = stackSym[i] >> kSymbolBits;\n"
        "        uint key = stackState[depthCounterAt(depth)];\n"
        "        stackState[depthCounterAt(depth)] = key + 1u;\n"
        "        gPass = pc.pass + 1u + min(depth, kPassesPerStep - 3u);\n"
        "        uint draw = 1u, chosen = 0u, length = 1u;\n",
        sp);
    s += selection(g.decomposition, sp, RuleKind::Decomposition, frames.decomposition[sp]);
    s += fmt::format("        if (chosen == 0u) {{\n"
                     "            if (depth == 0u && original) return kNotDecomposed;\n"
                     "            outputFromStack(i, next);\n"
                     "            continue;\n"
                     "        }}\n"
                     "        if (depth >= {}u) {{ outputFromStack(i, next); continue; }}\n"
                     "        if (top + 1u >= pc.stackLevels) {{ atomicOr(errors[1], kFlagStackFull); gAbort = true; return kDecomposed; }}\n"
                     "        gToStack = true;\n"
                     "        gBase = levelBase(top + 1u);\n",
                     std::max(g.decomposition.maxDepth, 0));
    s += produce(g.decomposition, sp, RuleKind::Decomposition, frames.decomposition[sp]);
    s += "        stackState[levelCountAt(top + 1u)] = produced;\n"
         "        stackState[levelCountAt(top + 1u) + 1u] = 0u;\n"
         "        ++top;\n"
         "    }\n"
         "    return kDecomposed; // not reached: the loop ends by returning (a driver's cut is found by reportLoopsCut)\n"
         "}\n\n";
    return s;
}

// The start of a turn of the step's loop: module i's symbol, and the production that applies to it (`chosen`).
std::string examineModule(const ir::Grammar& g, size_t sp, const FrameLayout& frames) {
    return "        ++gWork;\n"
           "        gOrigin = i;\n"
           "        sym = symOf(i);\n"
           "        count = countOf(i);\n"
           "        uint key = i - pBegin;\n"
           "        int ctxLeft = int(i) - 1;\n"
           "        uint ctxRight = i + 1u;\n"
           "        gPass = pc.pass;\n"
           "        uint draw = 1u, chosen = 0u, length = 1u;\n" +
           selection(g.productions, sp, RuleKind::Step, frames.step[sp]);
}

// The chosen production applied: its successor goes to the first level of the decomposition stack (`toStack`)
// or straight to the output. Leaves `produced`, inside `if (chosen != 0u) {`.
std::string applyChosen(const ir::Grammar& g, size_t sp, const FrameLayout& frames, bool toStack) {
    return std::string("        if (chosen != 0u) {\n") +
           (toStack ? "            gToStack = true;\n            gBase = levelBase(0u);\n"
                    : "            gToStack = false;\n            gBase = next;\n") +
           produce(g.productions, sp, RuleKind::Step, frames.step[sp]);
}

// The end of a turn for a module that nothing rewrites: a cut skips the rest of its branch, else it is copied.
// `decomposes`: the cut restores the count of modules examined, which the decomposition of module i advanced.
std::string copyModule(bool decomposes) {
    return std::string("        if (sym == 2u && count == 0u) {\n"
                       "            // The cut leaves the string with the rest of its branch; it does not count as "
                       "examined.\n") +
           (decomposes ? "            stackState[depthCounterAt(0u)] = examined;\n" : "") +
           "            i = endOfBranch(i + 1u, pBegin, pEnd);\n"
           "            continue;\n"
           "        }\n"
           "        outputFromInput(i, next);\n"
           "        ++i;\n"
           "    }\n"
           "}\n\n";
}

// One plant's step (cpu/derive.cpp rewrite()) for as much work as the dispatch does. `pending` is a suspended
// decomposition's stack level + 1 (0: none); it decomposes the input modules from `pendingFirst` up to i.
std::string deriveFunction(const ir::Grammar& g, size_t sp, const FrameLayout& frames) {
    bool decomposes = !g.decomposition.productions.empty() && g.decomposition.maxDepth > 0;
    std::string s = fmt::format("void s{}Derive(uint plant, uint pBegin, uint pEnd, inout uint i, inout uint next, "
                                "inout uint pending, inout uint pendingFirst) {{\n"
                                "    uint frameBase = plant * kFrameSlots;\n",
                                sp);
    if (!decomposes) {
        s += "    while (i < pEnd && !gAbort && gWork < pc.chunk) {\n"
             "        uint sym, count;\n";
        s += examineModule(g, sp, frames) + applyChosen(g, sp, frames, false);
        s += "            advanceOutput(next, produced);\n"
             "            i += length;\n"
             "            continue;\n"
             "        }\n";
        return s + copyModule(false);
    }
    // One call of the decomposition in the loop: lavapipe inlines every call, and three copies of it nearly
    // doubled the kernel's compile time.
    s += "    if (pc.dispatch == 0u) for (uint d = 0u; d < pc.stackLevels; ++d) stackState[depthCounterAt(d)] = 0u;\n"
         "    while (pending != 0u || (i < pEnd && !gAbort && gWork < pc.chunk)) {\n"
         // What is decomposed: a decomposition suspended in an earlier dispatch, whose stack holds what the input
         // modules from pendingFirst up to i became; else the successor of the production applied to module i, or
         // module i itself.
         "        int decomposeLeft;\n"
         "        uint decomposeRight, top = 0u, advance = 0u, sym = 0u, count = 0u, examined = 0u;\n"
         "        bool original = false;\n"
         "        if (pending != 0u) {\n"
         "            gOrigin = pendingFirst;\n"
         "            top = pending - 1u;\n"
         "            pending = 0u;\n"
         "            decomposeLeft = int(pendingFirst) - 1;\n"
         "            decomposeRight = i;\n"
         "        } else {\n";
    s += examineModule(g, sp, frames) + "        decomposeLeft = int(i) - 1;\n" + applyChosen(g, sp, frames, true);
    s += "            stackState[levelCountAt(0u)] = produced;\n"
         "            decomposeRight = i + length;\n"
         "            advance = length;\n"
         "        } else {\n"
         "            examined = stackState[depthCounterAt(0u)];\n"
         "            stackFromInput(i, levelBase(0u));\n"
         "            stackState[levelCountAt(0u)] = 1u;\n"
         "            decomposeRight = i + 1u;\n"
         "            advance = 1u;\n"
         "            original = true;\n"
         "        }\n"
         "        stackState[levelCountAt(0u) + 1u] = 0u;\n"
         "        }\n";
    s += fmt::format("        uint decomposed = s{}Decompose(plant, pBegin, pEnd, decomposeLeft, decomposeRight, "
                     "original, top, next);\n"
                     "        if (decomposed != kNotDecomposed) {{\n"
                     "            if (advance != 0u) {{\n"
                     "                pendingFirst = i;\n"
                     "                i += advance;\n"
                     "            }}\n"
                     "            if (decomposed == kDecompositionSuspended) {{\n"
                     "                pending = gSuspendedTop + 1u;\n"
                     "                return;\n"
                     "            }}\n"
                     "            continue;\n"
                     "        }}\n",
                     sp);
    return s + copyModule(true);
}

} // namespace

GeneratedKernels generateSequentialKernel(const std::vector<ir::Grammar>& all, bool texelInputs) {
    SpeciesClasses classes = classifySpecies(all);
    const std::vector<ir::Grammar>& species = classes.representatives; // whose code the kernel holds
    GeneratedKernels k = codegen::speciesTraits(species);
    k.speciesTable = codegen::speciesTable(classes);
    k.functionTables = codegen::hoistedTable(classes);
    FrameLayout frames = layoutFrames(species);
    k.frameSlots = frames.slots;
    for (const ir::Grammar& g : species)
        for (const ir::RuleSet* rules : {&g.productions, &g.decomposition})
            for (const ir::Production& p : rules->productions)
                for (const ir::Alternative& alt : p.alternatives)
                    k.stackWidth = std::max(k.stackWidth, static_cast<uint32_t>(alt.modules.size()));

    std::string s = codegen::kernelPrelude(all.size());
    s += fmt::format("const uint kFrameSlots = {}u;\nconst uint kStackWidth = {}u;\n", std::max(k.frameSlots, 1u),
                     k.stackWidth);
    s += declarations(texelInputs) + moduleLightCode(false); // light() is 1: GpuDeriver refuses a grid's light
    s += codegen::deriveLibrary(classes);
    s += kMachinery;
    std::string productions;
    for (size_t sp = 0; sp < species.size(); ++sp) {
        const ir::Grammar& g = species[sp];
        s += codegen::functionTableCode(g, sp, k.functionTables);
        s += codegen::curveTableCode(g, sp, k.functionTables);
        for (size_t i = 0; i < g.productions.productions.size(); ++i)
            codegen::emitProduction(g, sp, g.productions.productions[i], RuleKind::Step, i, FrameStyle::Persistent,
                                    k.errors, productions);
        for (size_t i = 0; i < g.decomposition.productions.size(); ++i)
            codegen::emitProduction(g, sp, g.decomposition.productions[i], RuleKind::Decomposition, i,
                                    FrameStyle::Persistent, k.errors, productions);
    }
    s += productions;
    for (size_t sp = 0; sp < species.size(); ++sp) {
        const ir::Grammar& g = species[sp];
        if (!g.decomposition.productions.empty() && g.decomposition.maxDepth > 0) s += decomposeFunction(g, sp, frames);
        s += deriveFunction(g, sp, frames);
    }
    s += "void main() {\n"
         "    uint plant = (gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + "
         "gl_LocalInvocationID.x;\n"
         "    if (plant >= pc.plants) return;\n"
         "    uint pBegin = plantStartAt(plant), pEnd = plantStartAt(plant + 1u);\n"
         "    uint first = pc.mode == 1u ? outStart[plant] : 0u;\n"
         "    // A pass is several dispatches, each doing at most pc.chunk work for every plant (gWork).\n"
         "    uint i = pBegin, next = first, pending = 0u, pendingFirst = 0u;\n"
         "    if (pc.dispatch > 0u) {\n"
         "        i = resume[4u * plant];\n"
         "        next = resume[4u * plant + 1u];\n"
         "        pending = resume[4u * plant + 2u];\n"
         "        pendingFirst = resume[4u * plant + 3u];\n"
         "        if (i >= pEnd && pending == 0u) return; // done in an earlier dispatch\n"
         "    }\n"
         "    gState = plant * 3u * pc.stackLevels;\n"
         "    gStack = plant * pc.stackLevels * kStackWidth;\n"
         "    if (plantFrozen[plant] == kPlantFrozen) {\n"
         "        for (; i < pEnd && gWork < pc.chunk; ++i, ++gWork) outputFromInput(i, next);\n"
         "    } else {\n"
         "        uint species = speciesOf(plant);\n";
    s += codegen::perSpecies(species.size(), [](size_t sp) {
        return fmt::format("        s{}Derive(plant, pBegin, pEnd, i, next, pending, pendingFirst);\n", sp);
    });
    s += "    }\n"
         "    resume[4u * plant] = i;\n"
         "    resume[4u * plant + 1u] = next;\n"
         "    resume[4u * plant + 2u] = pending;\n"
         "    resume[4u * plant + 3u] = pendingFirst;\n"
         "    plantCounts[plant] = next - first;\n"
         "    if ((i < pEnd || pending != 0u) && !gAbort) errors[2] = 1u; // the host dispatches again\n"
         "    reportLoopsCut();\n"
         "}\n";
    k.sequential = std::move(s);
    return k;
}

} // namespace simeco::codegen
