// Lowers a plant's Grow block to the grammar IR.
//
// - Every segment carries one parameter, its stage. A literal stage in a predecessor or context (`S(7)`)
//   becomes a frame slot plus the condition `slot == 7`; a variable (`L(i)`) is just the slot.
// - `prob(p) a | prob(q) b | c` is one production whose alternatives are tried in order, each taken with
//   its probability; an alternative without prob() has probability 1. When every alternative fails its
//   draw the segment stays as it is.
// - A step production `L(i) -> L(i + 1, 1 < i < 6);` advances the stage while its condition holds: the
//   condition becomes the production's condition, so once it fails the segment falls through to later
//   rules (or stays). When a step successor has further alternatives (`| S(0)`), those are what the thesis
//   tries after a failed test; they become a second production, right after, without the step condition.
// - Rotations are modules named rotr, rotu, rotx, roty, rotz with one argument in radians. They describe
//   how a segment is attached rather than being plant parts, so context matching skips them: in
//   `S(4) < S(10)` the S(10) of `S(4)[rotr(0.78)S(10)]` has S(4) as its left context.
// - `rotu` turns about the parent's growth direction, `rotr` away from it: in a run of rotations the turtle
//   rolls by every rotu before it pitches by the rotr (`rotr(a) rotu(b)` spins the tilted branch about the
//   parent axis, as the thesis draws its phyllotaxis).
// - rotr turns about a stem's reference axis r, the turtle's left. A main stem carries its parent's r turned with
//   it; a branch (a stem or apex after the rotations that open a bracket) takes its parent's direction as r
//   (seed 002, section 3.3.4), here the part of it at right angles to the branch: after the branch's rotations
//   the turtle rolls a quarter turn, `/(-90)`, which brings its left there (the parent's direction, seen from the
//   branch turned by rotr, lies along the turtle's up).
// - The organs are drawn by a homomorphism from their stages (lang/eco_geometry.h).
// - Symbols are interned in a fixed order (brackets, A S L F T R, the rotations and the roll, then the drawing
//   modules), so every SimEco plant of a scene numbers its symbols alike.
#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "lang/eco_geometry.h"
#include "lang/eco_parser.h"

namespace simeco::lang {

namespace {

constexpr const char* kRotationNames[] = {"rotr", "rotu", "rotx", "roty", "rotz"};
constexpr const char* kBranchAxisRoll = "/"; // cpfg's roll, in degrees

ir::Expr localSlot(int slot, const ir::SourceLoc& loc) {
    ir::Expr e;
    e.op = ir::Op::Local;
    e.slot = slot;
    e.loc = loc;
    return e;
}

ir::Expr binary(ir::Op op, ir::Expr a, ir::Expr b, const ir::SourceLoc& loc) {
    ir::Expr e;
    e.op = op;
    e.args.push_back(std::move(a));
    e.args.push_back(std::move(b));
    e.loc = loc;
    return e;
}

std::optional<ir::Expr> conjoin(std::optional<ir::Expr> a, std::optional<ir::Expr> b, const ir::SourceLoc& loc) {
    if (!a) return b;
    if (!b) return a;
    return binary(ir::Op::And, std::move(*a), std::move(*b), loc);
}

class PlantCompiler {
public:
    PlantCompiler(const ir::EcoScene& scene, EcoDrawing drawing, const EcoAssets* assets)
        : drawing_(drawing), assets_(assets) {
        grammar_.sourceFile = scene.file;
        // Stems bend toward gravity or away from it (the growth's `tropism` modules).
        const float g[3] = {scene.gravity.x.typical(), scene.gravity.y.typical(), scene.gravity.z.typical()};
        const float norm = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (norm > 0.0f) grammar_.view.tropismDirection = {g[0] / norm, g[1] / norm, g[2] / norm};
        // The engines keep cpfg's step counters in the first global slots, whatever the language.
        grammar_.globalNames = {"Q", "Z"};
        grammar_.globalInit = {0.0f, 0.0f};
    }

    ir::Grammar compile(const ir::EcoPlant& plant) {
        for (char letter : ir::kEcoSegmentLetters) symbol(std::string(1, letter));
        for (const char* rotation : kRotationNames) symbol(rotation);
        symbol(kBranchAxisRoll);

        grammar_.axiomLoc = plant.grow.axiomLoc;
        grammar_.axiom = successorModules(plant.grow.axiom);
        for (const ir::EcoRule& rule : plant.grow.rules) lowerRule(rule);
        grammar_.productions.present = !plant.grow.rules.empty();
        addEcoOrganGeometry(plant, grammar_, drawing_, assets_);

        grammar_.contextSkip.resize(grammar_.alphabet.size(), false);
        for (const char* rotation : kRotationNames) grammar_.contextSkip[symbol(rotation)] = true;
        grammar_.contextSkip[symbol(kBranchAxisRoll)] = true;

        grammar_.derivationLength = plant.derivationLength.value_or(defaultDerivationLength(plant));
        return std::move(grammar_);
    }

private:
    // SimEco has no derivation length: it derives every DeriveTime seconds for as long as it runs. A grow
    // grammar without cycles (the generator's initial-state grammars) reaches its final form within one step
    // per rule; one with cycles keeps growing, and 10 steps is 30 s at the DeriveTime the seed scripts use.
    static int defaultDerivationLength(const ir::EcoPlant& plant) {
        return std::max(kDefaultEcoDerivationLength, static_cast<int>(plant.grow.rules.size()));
    }

    ir::SymbolId symbol(const std::string& name) { return grammar_.symbol(name); }

    ir::SuccessorModule successorModule(const ir::EcoModule& m) {
        ir::SuccessorModule module;
        module.sym = m.name == "[" ? ir::kBranchOpen : m.name == "]" ? ir::kBranchClose : symbol(m.name);
        module.args = m.args;
        module.loc = m.loc;
        return module;
    }

    // The modules of a successor or axiom, with rotu moved before rotr within each run of the two.
    std::vector<ir::SuccessorModule> successorModules(const std::vector<ir::EcoModule>& modules) {
        std::vector<ir::EcoModule> ordered = modules;
        auto isTilt = [](const ir::EcoModule& m) { return m.name == "rotr" || m.name == "rotu"; };
        for (auto run = ordered.begin(); run != ordered.end();) {
            if (!isTilt(*run)) {
                ++run;
                continue;
            }
            auto end = std::find_if_not(run, ordered.end(), isTilt);
            std::stable_partition(run, end, [](const ir::EcoModule& m) { return m.name == "rotu"; });
            run = end;
        }
        std::vector<ir::SuccessorModule> out;
        for (size_t k = 0; k < ordered.size(); ++k) {
            out.push_back(successorModule(ordered[k]));
            if (endsBranchTurn(ordered, k)) out.push_back(branchAxisRoll(ordered[k].loc));
        }
        return out;
    }

    static bool isRotation(const ir::EcoModule& m) {
        return std::find(std::begin(kRotationNames), std::end(kRotationNames), m.name) != std::end(kRotationNames);
    }

    // Whether module k ends the rotations that open a bracket before a stem or an apex (a branch's turn).
    static bool endsBranchTurn(const std::vector<ir::EcoModule>& modules, size_t k) {
        if (!isRotation(modules[k]) || k + 1 >= modules.size()) return false;
        const std::string& next = modules[k + 1].name;
        if (next != "S" && next != "A") return false;
        size_t first = k;
        while (first > 0 && isRotation(modules[first - 1])) --first;
        return first > 0 && modules[first - 1].name == "[";
    }

    // The quarter roll that turns a branch's left to its parent's direction.
    ir::SuccessorModule branchAxisRoll(const ir::SourceLoc& loc) {
        ir::SuccessorModule m;
        m.sym = symbol(kBranchAxisRoll);
        m.args.push_back(ir::Expr::constant(-90.0f, loc));
        m.loc = loc;
        return m;
    }

    ir::PatternModule pattern(const ir::EcoPatternSegment& seg) {
        return {symbol(std::string(1, seg.letter)), {seg.slot}, seg.loc};
    }

    // `slot == stage` for every literal stage, in text order.
    std::optional<ir::Expr> stageConditions(const ir::EcoRule& rule) {
        std::optional<ir::Expr> condition;
        auto add = [&](const ir::EcoPatternSegment& seg) {
            if (!seg.stage) return;
            ir::Expr test = binary(ir::Op::Eq, localSlot(seg.slot, seg.loc),
                                   ir::Expr::constant(static_cast<float>(*seg.stage), seg.loc), seg.loc);
            condition = conjoin(std::move(condition), std::move(test), seg.loc);
        };
        for (const ir::EcoPatternSegment& seg : rule.left) add(seg);
        add(rule.predecessor);
        for (const ir::EcoPatternSegment& seg : rule.right) add(seg);
        return condition;
    }

    ir::Alternative alternative(const ir::EcoAlternative& alt) {
        ir::Alternative out;
        out.probability = alt.probability.value_or(1.0f);
        out.modules = successorModules(alt.modules);
        return out;
    }

    ir::Production skeleton(const ir::EcoRule& rule) {
        ir::Production p;
        for (const ir::EcoPatternSegment& seg : rule.left) p.left.push_back(pattern(seg));
        p.strict.push_back(pattern(rule.predecessor));
        for (const ir::EcoPatternSegment& seg : rule.right) p.right.push_back(pattern(seg));
        p.condition = conjoin(stageConditions(rule), rule.condition, rule.loc);
        p.frameSize = static_cast<int>(rule.slotNames.size());
        p.slotNames = rule.slotNames;
        p.loc = rule.loc;
        return p;
    }

    void lowerRule(const ir::EcoRule& rule) {
        ir::Production p = skeleton(rule);
        const ir::EcoAlternative& first = rule.alternatives.front();
        if (first.stepCondition) p.condition = conjoin(std::move(p.condition), *first.stepCondition, first.loc);
        for (const ir::EcoAlternative& alt : rule.alternatives) p.alternatives.push_back(alternative(alt));
        grammar_.productions.productions.push_back(std::move(p));

        if (first.stepCondition && rule.alternatives.size() > 1) {
            ir::Production fallback = skeleton(rule);
            for (size_t i = 1; i < rule.alternatives.size(); ++i)
                fallback.alternatives.push_back(alternative(rule.alternatives[i]));
            grammar_.productions.productions.push_back(std::move(fallback));
        }
    }

    ir::Grammar grammar_;
    EcoDrawing drawing_;
    const EcoAssets* assets_;
};

} // namespace

ir::Grammar compileEcoPlant(const ir::EcoScene& scene, size_t plantIndex, EcoDrawing drawing,
                            const EcoAssets* assets) {
    if (plantIndex >= scene.plants.size())
        throw ir::InputError({scene.file, 0, 0}, fmt::format("the scene has {} plant(s); there is no plant {}",
                                                             scene.plants.size(), plantIndex));
    return PlantCompiler(scene, drawing, assets).compile(scene.plants[plantIndex]);
}

} // namespace simeco::lang
