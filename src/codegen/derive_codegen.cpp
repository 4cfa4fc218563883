#include "codegen/derive_codegen.h"

#include <algorithm>
#include <map>
#include <string>

#include <fmt/format.h>

#include "codegen/context_codegen.h"
#include "codegen/curve_codegen.h"
#include "codegen/kernel_traits.h"
#include "codegen/production_codegen.h"
#include "codegen/species_classes.h"
#include "codegen/successor_slots.h"
#include "compute/shaders.h"
#include "compute/shared/derive_layout.h"
#include "compute/shared/particle_layout.h"

namespace simeco::codegen {

namespace {

using codegen::FrameStyle;
using codegen::functionName;
using codegen::literal;
using codegen::RuleKind;

// The buffers of each kernel. Contexts always read the string being rewritten (symIn, parIn).
// `parameters`: the type of parOut's elements, a module's parameter slots (codegen::parameterVectorWidth).
// `parameterVectors`: the width of parVec, the string's parameters read as one vector per module (1: none).
std::string declarations(bool texelInputs, bool decomposition, bool write, bool readsLight, bool fusedScan = false,
                         bool carriesPartners = false, const std::string& parameters = "float",
                         uint32_t parameterVectors = 1) {
    codegen::Bindings b(texelInputs);
    b.addShared(false);
    if (decomposition) {
        b.add("readonly", "uint", "symX");
        b.add("readonly", "float", "parX");
        b.addInput("uint", "plantStartX");
        b.add("readonly", "uint", "liveX");
        b.add("readonly", "uint", "originX");
        b.add("readonly", "uint", "examined");
    }
    if (!write) {
        if (fusedScan) {
            b.add("writeonly", "uint", "matchWords");
        } else {
            b.add("writeonly", "uint", "counts");
            b.add("writeonly", "uint", "choices");
        }
        b.add("writeonly", "uint", "drawStarts");
        if (!decomposition) b.add("", "uint", "cutDelta");
        if (fusedScan) b.add("writeonly", "uint", "tileSums");
    } else {
        if (fusedScan) {
            b.addInput("uint", "matchWords");
            b.addInput("uint", "tileOffsets");
        } else {
            b.addInput("uint", "offsets");
            b.addInput("uint", "choices");
        }
        b.addInput("uint", "drawStarts");
        b.add("writeonly", "uint", "symOut");
        b.add("writeonly", parameters.c_str(), "parOut");
        b.add("writeonly", "uint", "originOut");
        b.add("writeonly", "uint", "liveOut");
        if (carriesPartners) b.add("writeonly", "uint", "partnersOut");
    }
    b.addInput("uint", "plantHints"); // of the stream plantOf() searches (derive/plant_hints.comp)
    if (parameterVectors > 1) b.addVectorInput(parameterVectors, "parVec");
    if (readsLight) b.add("readonly", "float", "particles");
    return b.text() + moduleLightCode(readsLight);
}

// A weighted draw among the applicable productions of one symbol `list`: every candidate is tested in file order
// (mode 0), then the drawn one runs again from its first draw (mode 1). The rounds are one loop around one call of
// each production, not a call per round: lavapipe's compiler inlines every call, and two inlined copies of a dozen
// productions with context walks took it fifteen seconds instead of two.
std::string stochasticSelection(const ir::RuleSet& rules, size_t species, RuleKind kind,
                                const std::vector<size_t>& list) {
    const size_t n = list.size();
    std::string code = fmt::format("        double total = 0.0LF, weights[{0}];\n"
                                   "        bool any = false, applicable[{0}];\n"
                                   "        uint starts[{0}], pick = 0u;\n"
                                   "        for (uint round = 0u; round <= {0}u; ++round) {{\n"
                                   "            uint k = round, mode = 0u;\n"
                                   "            if (round == {0}u) {{\n"
                                   "                if (!any) break;\n"
                                   // The first to bring r = total * u to zero or below wins, else the last applicable.
                                   "                double left = total * double(randomUnit(pc.seed, "
                                   "pc.firstPlant + plant, currentPass(), key, 0u));\n"
                                   "                bool done = false;\n"
                                   "                for (uint c = 0u; c < {0}u; ++c)\n"
                                   "                    if (!done && applicable[c]) {{ pick = c; left -= weights[c]; "
                                   "done = left <= 0.0LF; }}\n"
                                   "                k = pick;\n"
                                   "                mode = 1u;\n"
                                   "                draw = starts[pick];\n"
                                   "            }} else starts[k] = draw;\n"
                                   "            bool applies = false;\n"
                                   "            uint yields = 0u;\n"
                                   "            switch (k) {{\n",
                                   n);
    for (size_t k = 0; k < n; ++k) {
        const ir::Production& p = rules.productions[list[k]];
        code += fmt::format("            case {}u: applies = count == {}u && {}(i, plant, key, pBegin, pEnd, ctxLeft, "
                            "ctxRight, draw, mode, yields); weights[k] = {}; chosen = {}u; length = {}u; break;\n",
                            k, p.strict[0].paramSlots.size(), functionName(species, kind, list[k]),
                            literal(static_cast<double>(std::max(p.weight, 0.0f))), list[k] + 1, p.strict.size());
    }
    return code + fmt::format("            }}\n"
                              "            if (round < {}u) {{\n"
                              "                applicable[k] = applies;\n"
                              "                if (applies) {{ total += weights[k]; any = true; }}\n"
                              "            }} else {{\n"
                              "                produced = yields;\n"
                              "                start = starts[pick];\n"
                              "            }}\n"
                              "        }}\n"
                              "        if (!any) {{ chosen = 0u; length = 1u; }}\n",
                              n);
}

// The selection among one symbol's productions, as the CPU reference does it: the first applicable in file
// order, or a weighted draw among all applicable ones in stochastic L-systems. Leaves `chosen` (index + 1,
// 0 for none), `start` (draw counter at the chosen production's start) and `produced`.
std::string selection(const ir::RuleSet& rules, size_t species, RuleKind kind, bool stochastic) {
    std::string code;
    std::map<ir::SymbolId, std::vector<size_t>> bySymbol;
    for (size_t i = 0; i < rules.productions.size(); ++i)
        if (kind == RuleKind::Step || rules.productions[i].strict.size() == 1) // as the CPU's decomposition
            bySymbol[rules.productions[i].strict[0].sym].push_back(i);
    code += "    switch (sym) {\n";
    for (const auto& [sym, list] : bySymbol) {
        code += fmt::format("    case {}u: {{\n", sym);
        if (!stochastic) {
            // A flat run of tests rather than a loop left by `break`, whose exits nest: lavapipe loses code nested
            // deeper than 80 levels (its control-flow stack), so a symbol's 77th production would never apply.
            for (size_t pi : list) {
                const ir::Production& p = rules.productions[pi];
                code += fmt::format("        if (chosen == 0u) {{\n"
                                    "            start = draw;\n"
                                    "            if (count == {}u && {}(i, plant, key, pBegin, pEnd, ctxLeft, ctxRight, "
                                    "draw, 1u, produced)) {{ chosen = {}u; length = {}u; }}\n"
                                    "        }}\n",
                                    p.strict[0].paramSlots.size(), functionName(species, kind, pi), pi + 1,
                                    p.strict.size());
            }
        } else {
            code += stochasticSelection(rules, species, kind, list);
        }
        code += "        break;\n    }\n";
    }
    code += "    }\n";
    return code;
}

// `mode`: 2, or 3 where the write pass is given the alternatives (production_codegen.h).
std::string writeDispatch(const ir::RuleSet& rules, size_t species, RuleKind kind, uint32_t mode = 2) {
    std::string code = "    switch (choice) {\n";
    for (size_t pi = 0; pi < rules.productions.size(); ++pi)
        code += fmt::format("    case {}u: {}(i, plant, key, pBegin, pEnd, ctxLeft, ctxRight, draw, {}u, produced); "
                            "break;\n",
                            pi + 1, functionName(species, kind, pi), mode);
    code += "    }\n";
    return code;
}

// The end of a match kernel: what it found for module i.
// `returnsCount`: the function returns the count instead of storing it (the step's matchModule, whose main()
// stores it or, with a fused scan, the counts before it in its tile).
// `recordsDraws`: the write pass draws, from where the chosen production started.
// `packsChoice`: the step's match with a fused scan, whose main() packs the choice into the module's match word
// (its predecessors are one module long, so the choice carries no length).
// `givesAlternative`: the choice carries the drawn alternative above the production (kProductionBits).
std::string recordChoice(bool returnsCount = false, bool recordsDraws = true, bool packsChoice = false,
                         bool givesAlternative = false) {
    std::string choice = givesAlternative ? "chosen | (chosenAlternative << kProductionBits)" : "chosen";
    return std::string("    if (chosen == 0u) produced = 1u;\n") + (returnsCount ? "" : "    counts[i] = produced;\n") +
           (packsChoice ? "    matchedChoice = " + choice + ";\n"
                        : "    choices[i] = " + choice +
                              " | ((length - 1u) << 24u); // the predecessor's length for the greedy walk\n") +
           (recordsDraws ? "    drawStarts[i] = start;\n" : "") + (returnsCount ? "    return produced;\n}\n" : "}\n");
}

// The specialization constant of a step's match and write kernels. The host specialises kSinglePlant when the
// stream holds one plant, which is then the whole stream: no lookup at all.
std::string stepSpecializations() { return "layout(constant_id = 1) const bool kSinglePlant = false;\n\n"; }

// Module i's plant and where the plant's string begins and ends, in a step's passes: looked up only when its
// productions read them (codegen::plantInputs), since each lookup is a search and several loads per module.
// `frozenCheck`: a match pass, which copies the modules of frozen plants while the host says some plant is frozen
// (pc.frozenPlants).
std::string stepPlantLookup(const codegen::PlantInputs& in, bool frozenCheck, bool packsChoice) {
    std::string frozen = std::string("        if (plantFrozen[plant] == kPlantFrozen) { ") +
                         (packsChoice ? "matchedChoice" : "choices[i]") + " = kChoiceCopy; return 1u; }\n";
    std::string s;
    if (in.plant) {
        s += "    uint plant = kSinglePlant ? 0u : plantOf(i);\n";
        if (frozenCheck) s += "    if (pc.frozenPlants != 0u) {\n" + frozen + "    }\n";
    } else {
        s += "    uint plant = 0u;\n";
        if (frozenCheck)
            s += "    if (pc.frozenPlants != 0u) {\n        plant = kSinglePlant ? 0u : plantOf(i);\n" + frozen + "    }\n";
    }
    s += "    uint species = speciesOf(plant);\n";
    s += in.bounds ? "    uint pBegin = kSinglePlant ? 0u : plantStartAt(plant);\n"
                     "    uint pEnd = kSinglePlant ? moduleCount : plantStartAt(plant + 1u);\n"
                   : "    uint pBegin = 0u, pEnd = moduleCount; // unread\n";
    return s;
}


// Every kernel's main() rewrites module i, then, if its loops may run long, asks whether the driver cut them
// (derive_lib.glsl). A decomposition depth's modules are those of the stream it rewrites (X), whose table counts
// them when only the device knows how many there are.
std::string mainCalling(const std::vector<ir::Grammar>& species, const std::string& body, RuleKind kind,
                        bool writing) {
    const std::string moduleIndex =
        "(gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x) * gl_WorkGroupSize.x + gl_LocalInvocationID.x";
    const std::string count = kind == RuleKind::Decomposition
                                  ? "pc.count != kCountOnDevice ? pc.count : plantStartXAt(pc.plants)"
                                  : "streamCount()";
    return "void main() {\n    uint i = " + moduleIndex + ";\n    moduleCount = " + count + ";\n" + body +
           (codegen::mayLoopLong(species, kind, writing) ? "    reportLoopsCut();\n" : "") + "}\n";
}

// A binary search of the plant table between the hints of i's block and the next block.
std::string findPlant(const char* table, const char* name) {
    return fmt::format("uint {}(uint i) {{\n"
                       "    uint block = i / kPlantHintBlock;\n"
                       "    uint low = plantHintsAt(block), high = plantHintsAt(block + 1u);\n"
                       "    while (low < high) {{\n"
                       "        uint mid = (low + high + 1u) / 2u;\n"
                       "        if ({}At(mid) <= i) low = mid; else high = mid - 1u;\n"
                       "    }}\n"
                       "    return low;\n}}\n\n",
                       name, table);
}

// A module's first `count` parameters, loaded once (`load`) for all productions and the copy, which read them
// through ownParam(i, k) (`declare`): lavapipe runs every production's code, and a load in each is a gather each.
// `vector`: all of them in one load from parVec, a vector of paramVector floats per module.
struct OwnParameters {
    std::string declare, load;
};

OwnParameters ownParameters(uint32_t paramVector, int count, bool vector) {
    OwnParameters own;
    std::string accessor = "double ownParam(uint i, uint k) {\n";
    if (vector) own.load = fmt::format("    vec{} ownParams = parVecAt(i);\n", paramVector);
    for (int a = 0; a < count; ++a) {
        own.declare += fmt::format("double ownParam{};\n", a);
        own.load += vector ? fmt::format("    ownParam{} = double(ownParams[{}]);\n", a, a)
                           : fmt::format("    ownParam{0} = paramOf(i, {0}u);\n", a);
        accessor += fmt::format("    if (k == {0}u) return ownParam{0};\n", a);
    }
    own.declare += accessor + "    return 0.0LF;\n}\n\n";
    return own;
}

// What the four kernels of a parallel derivation share: the species' code and the decisions made once for all
// of them (how a choice is packed, whether the scan is fused into the step, what each pass looks up).
struct DerivePlan {
    explicit DerivePlan(const std::vector<ir::Grammar>& all) : species(all) {}

    const std::vector<ir::Grammar>& species;
    bool texelInputs = false;
    std::string prelude, library, functions, stepFunctions, decompositionFunctions;
    // The parameter slots a module can have: the host's stride, except that the stride is at least 1. A copied
    // module of a grammar without parameters copies none.
    int copiedParams = 0;
    uint32_t paramVector = 1;       // the step's write pass stores a module's parameters as one such vector
    std::string parameterType;      // its GLSL type
    int predecessorParams = 0;      // the most parameters of a step's predecessor
    codegen::SuccessorSlots stepSlots, decompositionSlots;
    uint32_t productionBits = 1;    // of a choice, below the alternative when givesAlternatives
    bool givesAlternatives = false; // the match passes the alternative it drew to the write pass
    codegen::PlantInputs matchInputs, writeInputs;
    std::string choiceBits, tileOf; // their GLSL
};

std::string stepSelection(const std::vector<ir::Grammar>& species, size_t sp) {
    return selection(species[sp].productions, sp, RuleKind::Step, codegen::isStochastic(species[sp].productions));
}

std::string decompositionSelection(const std::vector<ir::Grammar>& species, size_t sp) {
    // At a species' maximum depth a module stays as it is, whether a production applies or not.
    const ir::RuleSet& rules = species[sp].decomposition;
    return fmt::format("    if (pc.depth < {}u) {{\n{}    }}\n", std::max(rules.maxDepth, 0),
                       selection(rules, sp, RuleKind::Decomposition, codegen::isStochastic(rules)));
}

// The plan of the species' kernels; fills k's decisions (stride, choiceBits, fusedScan, ...) and error sites.
// `species`: the classes' representatives, whose code the kernels hold.
DerivePlan planDeriveKernels(const std::vector<ir::Grammar>& species, const SpeciesClasses& classes,
                             bool texelInputs, bool contextChunks, GeneratedKernels& k) {
    DerivePlan plan(species);
    plan.texelInputs = texelInputs;
    plan.prelude = codegen::kernelPrelude(classes.classOf.size()) + "uint currentPass() { return pc.pass; }\n";
    plan.library = codegen::deriveLibrary(classes);
    for (size_t sp = 0; sp < species.size(); ++sp) {
        const ir::Grammar& g = species[sp];
        plan.functions += codegen::functionTableCode(g, sp, k.functionTables);
        plan.functions += codegen::curveTableCode(g, sp, k.functionTables);
        for (size_t i = 0; i < g.productions.productions.size(); ++i)
            codegen::emitProduction(g, sp, g.productions.productions[i], RuleKind::Step, i, FrameStyle::Fresh, k.errors,
                                    plan.stepFunctions);
        for (size_t i = 0; i < g.decomposition.productions.size(); ++i)
            codegen::emitProduction(g, sp, g.decomposition.productions[i], RuleKind::Decomposition, i,
                                    FrameStyle::Fresh, k.errors, plan.decompositionFunctions);
    }
    for (const ir::Grammar& g : species) plan.copiedParams = std::max(plan.copiedParams, g.maxParams());
    k.stride = static_cast<uint32_t>(std::max(plan.copiedParams, 1));
    plan.paramVector = codegen::parameterVectorWidth(k.stride);
    plan.parameterType = plan.paramVector > 1 ? fmt::format("vec{}", plan.paramVector) : "float";
    plan.stepSlots = codegen::successorSlots(species, RuleKind::Step, uint32_t(plan.copiedParams));
    plan.decompositionSlots = codegen::successorSlots(species, RuleKind::Decomposition, 0);
    // The step's scan fused into its two passes: match sums the successor counts of each subgroup's modules (a
    // tile of gl_SubgroupSize consecutive modules: invocations fill subgroups in order) and stores for each module
    // the counts before it in its tile; the host scans the sums, and a module's position is its tile's offset plus
    // the counts before it. Subgroup operations need no barrier, and no pass over the string is added. A match
    // by chunks (chunkedMatch) sums each chunk's counts in order: its tiles are the chunks.
    // Cuts and predecessors of several modules change counts after the match, so they keep the separate scan.
    // The counts before a module and its choice share one word (choiceBits): one store in match, one load in
    // write. The counts before a module stay below the largest subgroup (128) times the longest successor.
    // A choice is the production (index + 1) and, above it, the alternative drawn when the write is given it.
    size_t productions = 0, mostAlternatives = 1;
    for (const ir::Grammar& g : species) {
        productions = std::max(productions, g.productions.productions.size());
        for (const ir::Production& p : g.productions.productions)
            mostAlternatives = std::max(mostAlternatives, p.alternatives.size());
    }
    uint32_t productionBits = 1, alternativeBits = 0;
    while (productionBits < 32 && (size_t{1} << productionBits) <= productions) ++productionBits;
    while (alternativeBits < 32 && (size_t{1} << alternativeBits) < mostAlternatives) ++alternativeBits;
    uint64_t mostBefore = 128ull * plan.stepSlots.params.size();
    auto fusesScan = [&](uint32_t choiceBits) {
        return !k.mayCut && k.longestPredecessor <= 1 && choiceBits < 32 && mostBefore < (1ull << (32 - choiceBits));
    };
    // The alternative a production's match drew goes to the write pass with the choice, above the production's
    // bits, when the productions' code draws nothing else: the write pass then draws nothing, so it needs no
    // draw starts and, unless its productions read more of the plant, no plant. Otherwise it draws the
    // alternative again from the match's draw start, numbering the stream's draws as the CPU reference does.
    plan.writeInputs = codegen::plantInputs(species, RuleKind::Step, true, true);
    plan.givesAlternatives = alternativeBits > 0 && !plan.writeInputs.random &&
                             productionBits + alternativeBits <= shared::kSymbolBits &&
                             fusesScan(productionBits + alternativeBits) == fusesScan(productionBits);
    if (!plan.givesAlternatives) {
        alternativeBits = 0;
        plan.writeInputs = codegen::plantInputs(species, RuleKind::Step, true, false);
    }
    k.choiceBits = productionBits + alternativeBits;
    k.fusedScan = fusesScan(k.choiceBits);
    // Brackets a successor opens and closes are partners there (emitPartners); a copied `[` finds where its
    // partner went (outputPosition). Cuts and decomposition change brackets after the write.
    k.carriesPartners = k.needsBrackets && k.fusedScan && !k.hasDecomposition &&
                        codegen::successorsKeepBracketsBalanced(species);
    // Matching by chunks finds the first context modules a step's productions read; its chunks are the tiles.
    k.chunkedMatch = contextChunks && k.fusedScan && codegen::everyModuleOfASymbolWalks(species);
    plan.tileOf = k.chunkedMatch ? "uint tileOf(uint i) { return i / kContextChunk; }\n"
                                 : "uint tileOf(uint i) { return i / gl_SubgroupSize; }\n";
    plan.matchInputs = codegen::plantInputs(species, RuleKind::Step, false);
    plan.matchInputs.bounds = plan.matchInputs.bounds || k.mayCut; // a cut ends where its branch does, within the plant
    plan.matchInputs.plant = plan.matchInputs.plant || plan.matchInputs.bounds;
    k.matchFindsPlants = plan.matchInputs.plant;
    k.writeFindsPlants = plan.writeInputs.plant;
    plan.productionBits = productionBits;
    plan.choiceBits = fmt::format("const uint kChoiceBits = {}u;\n", k.choiceBits);
    if (plan.givesAlternatives) plan.choiceBits += fmt::format("const uint kProductionBits = {}u;\n", productionBits);
    for (const ir::Grammar& g : species)
        for (const ir::Production& p : g.productions.productions)
            plan.predecessorParams = std::max(plan.predecessorParams, static_cast<int>(p.strict[0].paramSlots.size()));
    k.matchReadsParameterVectors = plan.paramVector > 1 && plan.predecessorParams > 0;
    k.writeReadsParameterVectors = plan.paramVector > 1; // copiedParams, the stride, parameters are loaded
    return plan;
}

// The step's match pass: each module's production (and alternative) and successor count.
std::string stepMatchKernel(const DerivePlan& plan, const GeneratedKernels& k) {
    std::string s = plan.prelude +
                    declarations(plan.texelInputs, false, false, k.readsLight, k.fusedScan, false, "float",
                                 k.matchReadsParameterVectors ? plan.paramVector : 1) +
                    plan.library + plan.functions;
    s += codegen::slotDeclarations(plan.stepSlots);
    OwnParameters own = ownParameters(plan.paramVector, plan.predecessorParams, k.matchReadsParameterVectors);
    s += own.declare + findPlant("plantStart", "plantOf");
    if (!k.chunkedMatch) s += codegen::contextPrefetchCode(plan.species, RuleKind::Step, false);
    s += plan.stepFunctions + stepSpecializations();
    if (k.fusedScan || plan.givesAlternatives) s += plan.choiceBits;
    if (k.fusedScan) s += plan.tileOf;
    if (k.fusedScan) s += "uint matchedChoice = kChoiceCopy; // packed with the counts by main()\n";
    if (k.chunkedMatch) {
        // Module i with its word, plant and bounds as context_chunks.glsl found them, and the first context
        // modules it left in firstRight...
        s += "uint matchChunkModule(uint i, uint word, uint plant, uint pBegin, uint pEnd) {\n"
             "    if (pc.frozenPlants != 0u) {\n"
             "        if (plantFrozen[plant] == kPlantFrozen) { matchedChoice = kChoiceCopy; return 1u; }\n"
             "    }\n"
             "    uint species = speciesOf(plant);\n"
             "    uint sym = word & kSymbolMask, count = word >> kSymbolBits;\n"
             "    lightModule = i;\n";
    } else {
        s += "uint matchModule(uint i) {\n    lightModule = i;\n" + stepPlantLookup(plan.matchInputs, true, k.fusedScan);
        s += "    uint sym = symOf(i), count = countOf(i);\n";
    }
    s += own.load +
         "    uint key = i - pBegin;\n"
         "    int ctxLeft = int(i) - 1;\n"
         "    uint ctxRight = i + 1u;\n";
    if (!k.chunkedMatch) s += "    prefetchContexts(i, species, sym, ctxLeft, ctxRight, pBegin, pEnd);\n";
    s += "    uint draw = 1u, chosen = 0u, start = 0u, produced = 1u, length = 1u;\n";
    s += codegen::perSpecies(plan.species.size(), [&](size_t sp) { return stepSelection(plan.species, sp); });
    if (k.mayCut) {
        s += "    if (chosen == 0u && sym == 2u && count == 0u) {\n"
             "        // A cut: this module and the rest of its branch leave the string.\n"
             "        atomicAdd(cutDelta[i], 1u);\n"
             "        atomicAdd(cutDelta[endOfBranch(i + 1u, pBegin, pEnd)], 0xFFFFFFFFu);\n"
             "    }\n";
    }
    s += recordChoice(true, plan.writeInputs.random, k.fusedScan, plan.givesAlternatives);
    if (k.chunkedMatch) {
        s += codegen::contextChunkConstants(plan.species) +
             std::string(shaders::glslSource("compute/derive/context_chunks.glsl"));
        s += mainCalling(plan.species, "    matchChunk(i);\n", RuleKind::Step, false);
    } else {
        // The subgroup's last invocation holds the tile's sum in its inclusive prefix: one subgroup operation,
        // which lavapipe runs as a loop over the invocations, where an exclusive prefix and a sum are two.
        const char* fusedBody =
            "    uint produced = i < moduleCount ? matchModule(i) : 0u;\n"
            "    uint through = subgroupInclusiveAdd(produced);\n"
            "    if (i < moduleCount) matchWords[i] = ((through - produced) << kChoiceBits) | matchedChoice;\n"
            "    if (gl_SubgroupInvocationID == gl_SubgroupSize - 1u && i - gl_SubgroupInvocationID < moduleCount)\n"
            "        tileSums[tileOf(i)] = through;\n";
        const char* countsBody = "    if (i < moduleCount) counts[i] = matchModule(i);\n";
        s += mainCalling(plan.species, k.fusedScan ? fusedBody : countsBody, RuleKind::Step, false);
    }
    return s;
}

// The step's write pass: each module's successor at its position.
std::string stepWriteKernel(const DerivePlan& plan, const GeneratedKernels& k) {
    std::string s = plan.prelude +
                    declarations(plan.texelInputs, false, true, k.readsLight, k.fusedScan, k.carriesPartners,
                                 plan.parameterType, k.writeReadsParameterVectors ? plan.paramVector : 1) +
                    plan.library + plan.functions;
    s += codegen::slotDeclarations(plan.stepSlots) +
         codegen::slotStoreCode(plan.stepSlots, k.hasDecomposition, k.carriesPartners, plan.paramVector);
    OwnParameters own = ownParameters(plan.paramVector, plan.copiedParams, k.writeReadsParameterVectors);
    std::string copyOwn;
    for (int a = 0; a < plan.copiedParams; ++a) copyOwn += fmt::format("    slotParam0_{0} = float(ownParam{0});\n", a);
    s += own.declare + findPlant("plantStart", "plantOf");
    if (k.fusedScan || plan.givesAlternatives) s += plan.choiceBits;
    if (k.fusedScan) s += plan.tileOf;
    if (k.carriesPartners) // module j's first position in the written string
        s += "uint outputPosition(uint j) { return tileOffsetsAt(tileOf(j)) + (matchWordsAt(j) >> kChoiceBits); }\n\n";
    s += codegen::contextPrefetchCode(plan.species, RuleKind::Step, true) + plan.stepFunctions;
    // Every module's successor goes through the slots, a copied module's too, so that each output position
    // is stored once in the kernel's code: drivers that run every branch for the whole subgroup (lavapipe)
    // pay for the stores of all productions otherwise.
    s += stepSpecializations() + "void writeModule(uint i, uint pos, uint choice) {\n";
    s += "    if (choice == kChoiceDropped) return;\n"
         "    choice &= kSymbolMask;\n";
    if (plan.givesAlternatives)
        s += "    givenAlternative = choice >> kProductionBits;\n"
             "    choice &= (1u << kProductionBits) - 1u;\n";
    s += "    uint origin = i;\n"
         "    lightModule = i;\n"
         "    uint word = symInAt(i);\n" +
         own.load +
         "    uint produced = 1u;\n"
         "    slotWord0 = word;\n" +
         copyOwn + codegen::resetSlotPartners(plan.stepSlots);
    if (k.carriesPartners) // brackets are never rewritten: both partners are copies
        s += "    if (choice == kChoiceCopy && (word & kSymbolMask) == kOpen) {\n"
             "        uint partner = outputPosition(bracketPartnersAt(i));\n"
             "        partnersOut[pos] = partner;\n"
             "        partnersOut[partner] = pos;\n"
             "    }\n";
    s += "    if (choice != kChoiceCopy) {\n";
    s += stepPlantLookup(plan.writeInputs, false, false);
    s += "    uint key = i - pBegin;\n"
         "    int ctxLeft = int(i) - 1;\n"
         "    uint ctxRight = i + 1u;\n"
         "    prefetchContexts(i, species, word & kSymbolMask, ctxLeft, ctxRight, pBegin, pEnd);\n";
    s += plan.writeInputs.random ? "    uint draw = drawStartsAt(i);\n" : "    uint draw = 1u; // as match left it\n";
    s += codegen::perSpecies(plan.species.size(), [&](size_t sp) {
        return writeDispatch(plan.species[sp].productions, sp, RuleKind::Step, plan.givesAlternatives ? 3 : 2);
    });
    s += "    }\n"
         "    storeSlots(pos, produced, origin);\n"
         "}\n";
    s += mainCalling(plan.species, k.fusedScan ? "    if (i < moduleCount) {\n"
                                   "        uint matched = matchWordsAt(i);\n"
                                   "        writeModule(i, tileOffsetsAt(tileOf(i)) + (matched >> kChoiceBits),\n"
                                   "                    matched & ((1u << kChoiceBits) - 1u));\n"
                                   "    }\n"
                                 : "    if (i < moduleCount) writeModule(i, offsetsAt(i), choicesAt(i));\n",
                     RuleKind::Step, true);
    return s;
}

// A plant that stopped (stop(), or its species' derivation length reached) keeps its string.
const std::string kFrozenCopy =
    "    if (plantFrozen[plant] == kPlantFrozen) { counts[i] = 1u; choices[i] = kChoiceCopy; "
    "drawStarts[i] = 0u; return; }\n";

// What a decomposition pass knows of module i: its plant, species, origin and contexts.
const std::string kDecompositionSetup =
    "    uint species = speciesOf(plant);\n"
    "    uint pBegin = plantStartAt(plant), pEnd = plantStartAt(plant + 1u);\n"
    "    uint origin = originX[i];\n"
    "    lightModule = origin;\n"
    "    uint key = examined[i] - examined[plantStartXAt(plant)];\n"
    "    int ctxLeft = int(origin) - 1;\n"
    "    uint ctxRight = origin + 1u;\n"
    "    uint sym = symX[i] & kSymbolMask, count = symX[i] >> kSymbolBits;\n"
    "    prefetchContexts(i, species, sym, ctxLeft, ctxRight, pBegin, pEnd);\n";

// A decomposition depth's match pass: the production each module of the depth takes, and its count.
std::string decompositionMatchKernel(const DerivePlan& plan, const GeneratedKernels& k) {
    std::string s =
        plan.prelude + declarations(plan.texelInputs, true, false, k.readsLight) + plan.library + plan.functions;
    s += "double strictParam(uint i, uint k) { return double(parX[i * pc.stride + k]); }\n" +
         codegen::slotDeclarations(plan.decompositionSlots);
    s += findPlant("plantStartX", "plantOfX");
    s += codegen::contextPrefetchCode(plan.species, RuleKind::Decomposition, false) + plan.decompositionFunctions;
    s += "void matchModule(uint i) {\n";
    s += "    if (liveX[i] == 0u) { counts[i] = 1u; choices[i] = kChoiceCopy; drawStarts[i] = 0u; return; }\n";
    s += "    uint plant = plantOfX(i);\n" + kFrozenCopy + kDecompositionSetup;
    s += "    uint draw = 1u, chosen = 0u, start = 0u, produced = 1u, length = 1u;\n";
    s += codegen::perSpecies(plan.species.size(), [&](size_t sp) { return decompositionSelection(plan.species, sp); });
    s += recordChoice();
    s += mainCalling(plan.species, "    if (i < moduleCount) matchModule(i);\n", RuleKind::Decomposition, false);
    return s;
}

// A decomposition depth's write pass.
std::string decompositionWriteKernel(const DerivePlan& plan, const GeneratedKernels& k) {
    std::string s =
        plan.prelude + declarations(plan.texelInputs, true, true, k.readsLight) + plan.library + plan.functions;
    s += "double strictParam(uint i, uint k) { return double(parX[i * pc.stride + k]); }\n" +
         codegen::slotDeclarations(plan.decompositionSlots) +
         codegen::slotStoreCode(plan.decompositionSlots, true, false);
    s += findPlant("plantStartX", "plantOfX");
    s += codegen::contextPrefetchCode(plan.species, RuleKind::Decomposition, true) + plan.decompositionFunctions;
    s += "void writeModule(uint i) {\n";
    s += "    uint choice = choicesAt(i);\n"
         "    uint pos = offsetsAt(i);\n"
         "    if (choice == kChoiceCopy) {\n"
         "        uint count = symX[i] >> kSymbolBits;\n"
         "        symOut[pos] = symX[i];\n"
         "        originOut[pos] = originX[i];\n"
         "        liveOut[pos] = 0u; // not decomposed at this depth: final\n"
         "        for (uint k = 0u; k < count; ++k) parOut[pos * pc.stride + k] = parX[i * pc.stride + k];\n"
         "        return;\n"
         "    }\n"
         "    uint plant = plantOfX(i);\n";
    s += kDecompositionSetup;
    s += "    uint draw = drawStartsAt(i);\n"
         "    uint produced = 0u;\n";
    s += codegen::perSpecies(plan.species.size(), [&](size_t sp) {
        return writeDispatch(plan.species[sp].decomposition, sp, RuleKind::Decomposition);
    });
    s += "    storeSlots(pos, produced, origin);\n"
         "}\n";
    s += mainCalling(plan.species, "    if (i < moduleCount) writeModule(i);\n", RuleKind::Decomposition, true);
    return s;
}
} // namespace

std::string moduleLightCode(bool particles) {
    if (!particles) return "uint lightModule = 0u;\ndouble moduleLight() { return 1.0LF; }\n\n";
    return fmt::format("uint lightModule = 0u; // the module being rewritten (or decomposed: its origin)\n"
                       "double moduleLight() {{\n"
                       "    uint at = lightModule * {}u;\n"
                       "    if (pc.lightScale <= 0.0 || floatBitsToUint(particles[at + {}u]) == 0u) return 1.0LF;\n"
                       "    return double(particles[at + {}u]) * double(pc.lightScale);\n"
                       "}}\n\n",
                       shared::kParticleStateFloats, shared::kParticleId, shared::kParticleLight);
}

GeneratedKernels generateDeriveKernels(const std::vector<ir::Grammar>& species, bool texelInputs, bool contextChunks,
                                       bool sensesLight) {
    SpeciesClasses classes = classifySpecies(species);
    const std::vector<ir::Grammar>& code = classes.representatives;
    GeneratedKernels k = codegen::speciesTraits(code);
    if (!sensesLight) k.readsLight = false;
    k.speciesTable = codegen::speciesTable(classes);
    k.functionTables = codegen::hoistedTable(classes);
    DerivePlan plan = planDeriveKernels(code, classes, texelInputs, contextChunks, k);
    k.match = stepMatchKernel(plan, k);
    k.write = stepWriteKernel(plan, k);
    if (k.hasDecomposition) {
        k.decompositionMatch = decompositionMatchKernel(plan, k);
        k.decompositionWrite = decompositionWriteKernel(plan, k);
    }
    return k;
}

} // namespace simeco::codegen
