#include "cpu/derive.h"

#include <algorithm>
#include <bit>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "compute/shared/particle_layout.h"
#include "compute/shared/random.h"
#include "stream/evaluator.h"
#include "stream/plant_control.h"
#include "stream/random_passes.h"

namespace simeco::cpu {

using stream::DeriveOptions;
using stream::DeriveResult;
using stream::Evaluator;
using stream::ModuleString;
using stream::PlantControl;
using stream::PlantState;
using stream::RandomKey;
using stream::decompositionPass;
using stream::homomorphismPass;
using stream::kPassesPerStep;

namespace {

constexpr int64_t kNone = -1;

// A module outside the current string (one being decomposed).
struct ModuleRef {
    uint32_t sym;
    const float* params;
    size_t count;
};

class PlantDeriver {
public:
    // `room`: the modules this plant may still use of the field's `budget`, which earlier plants share.
    PlantDeriver(PlantControl& control, uint32_t plant, uint64_t room, uint64_t budget)
        : control_(control), plant_(plant), g_(control.speciesOf(plant)), state_(control.state(plant)),
          evaluator_(g_, state_), room_(room), budget_(budget) {
        evaluator_.key.seed = control.seed();
        evaluator_.key.plant = control.randomStream(plant);
        stride_ = std::max(g_.maxParams(), 1);
        cur_.stride = next_.stride = stride_;
        index(g_.productions, productionsBySymbol_);
        makeFrames(g_.productions, productionFrames_);
        decomposition_ = RecursiveRules(g_.decomposition);
        homomorphism_ = RecursiveRules(g_.homomorphism);
        stochastic_ = std::any_of(g_.productions.productions.begin(), g_.productions.productions.end(),
                                  [](const ir::Production& p) { return p.weight >= 0; });
        if (auto eq = g_.alphabet.find("=")) equalsSym_ = int64_t(*eq);
        percentSym_ = ir::kCut;
    }

    // `particles`: the state of the axiom's modules, when the derivation carries particle state.
    void run(const std::optional<std::vector<shared::ParticleState>>& particles) {
        control_.start(plant_, &cur_);
        if (particles) cur_.particles = *particles;
        carries_ = particles.has_value();
        checkBudget(cur_.size());
        for (int step = 1; control_.beginStep(plant_, step); ++step) {
            step_ = static_cast<uint32_t>(step);
            rewrite();
            control_.endStep(plant_, step);
        }
        control_.finish(plant_);
    }

    // Takes modules [begin, end) of `s` as the derived string, with the globals as the Start block leaves them,
    // or as they are when `restart` is false (a derivation that goes on).
    void adopt(const ModuleString& s, size_t begin, size_t end, bool restart = true) {
        if (restart) control_.start(plant_, nullptr);
        cur_.clear();
        cur_.reserve(end - begin);
        for (size_t i = begin; i < end; ++i) cur_.push(s.sym[i], s.paramsOf(i), s.paramCount[i]);
        carries_ = !s.particles.empty();
        if (carries_) cur_.particles.assign(s.particles.begin() + begin, s.particles.begin() + end);
    }

    // Replaces the derived string by its image under the homomorphism, the string the turtle interprets:
    // every module rewritten recursively up to the homomorphism's maximum depth, contexts read in the derived
    // string. A `%` it produces stays in the string (the turtle ignores it) rather than cutting.
    void applyHomomorphism() {
        if (g_.homomorphism.productions.empty()) return;
        evaluator_.light = 1.0; // the drawing does not sense
        matchBrackets();
        next_.clear();
        depthCounter_.assign(1, 0);
        for (size_t i = 0; i < cur_.size(); ++i) {
            ModuleRef self{cur_.sym[i], cur_.paramsOf(i), cur_.paramCount[i]};
            if (!rewriteRecursively(homomorphism_, homomorphismPass, self, int64_t(i) - 1, i + 1))
                next_.push(self.sym, self.params, self.count);
            inherit(i);
            checkBudget(next_.size());
        }
        std::swap(cur_, next_);
    }

    // One step more, its random draws keyed by `step`.
    void derive(uint32_t step) {
        step_ = step;
        rewrite();
    }

    ModuleString& result() { return cur_; }

private:
    PlantControl& control_;
    uint32_t plant_;
    const ir::Grammar& g_;
    PlantState& state_;
    Evaluator evaluator_;
    uint64_t room_, budget_;
    int stride_ = 1;
    ModuleString cur_, next_;
    std::vector<ModuleString> recursionLevels_; // rewriteRecursively's stack, kept between calls
    std::vector<size_t> recursionNext_;
    std::vector<int64_t> match_; // the matching bracket of each bracket in cur_
    std::vector<std::vector<uint32_t>> productionsBySymbol_;
    bool stochastic_ = false;
    int64_t equalsSym_ = kNone;
    uint32_t percentSym_ = ir::kCut;
    uint32_t step_ = 0;
    std::vector<uint32_t> depthCounter_;
    bool carries_ = false; // the strings carry particle state

    // What light() says while module i of cur_ is rewritten (or decomposed): its particle's light as a share of
    // the open's, where a light grid runs and the particle has been born; else 1.
    void sense(size_t i) {
        const float scale = control_.lightScale();
        const shared::ParticleState* p = carries_ ? &cur_.particles[i] : nullptr;
        const bool born = p && std::bit_cast<uint32_t>(p->value[shared::kParticleId]) != 0;
        evaluator_.light = born && scale > 0.0f ? double(p->value[shared::kParticleLight]) * double(scale) : 1.0;
    }

    // The modules next_ gained since the last call came from module `source` of cur_: they take its particle
    // state.
    void inherit(size_t source) {
        if (carries_) next_.particles.resize(next_.size(), cur_.particles[source]);
    }

    static void index(const ir::RuleSet& rules, std::vector<std::vector<uint32_t>>& bySymbol) {
        for (size_t i = 0; i < rules.productions.size(); ++i) {
            uint32_t s = rules.productions[i].strict.front().sym;
            if (bySymbol.size() <= s) bySymbol.resize(s + 1);
            bySymbol[s].push_back(static_cast<uint32_t>(i));
        }
    }

    void checkBudget(size_t size) const {
        if (size > room_) throw stream::moduleBudgetExceeded(budget_, step_);
    }

    void matchBrackets() {
        size_t n = cur_.size();
        match_.assign(n, kNone);
        std::vector<size_t> open;
        for (size_t i = 0; i < n; ++i) {
            if (cur_.sym[i] == ir::kBranchOpen) {
                open.push_back(i);
            } else if (cur_.sym[i] == ir::kBranchClose && !open.empty()) {
                match_[i] = int64_t(open.back());
                match_[open.back()] = int64_t(i);
                open.pop_back();
            }
        }
    }

    // The `]` that closes the branch containing position s (or the end of the string).
    size_t endOfBranch(size_t s) const {
        size_t n = cur_.size();
        while (s < n) {
            if (cur_.sym[s] == ir::kBranchClose) return s;
            if (cur_.sym[s] == ir::kBranchOpen) s = match_[s] == kNone ? n : size_t(match_[s]) + 1;
            else ++s;
        }
        return n;
    }

    bool sameModule(const ir::PatternModule& pm, size_t pos) const {
        // By name: a context (or a predecessor's further module) of one L-system matches another's modules.
        const ir::Alphabet& a = g_.alphabet;
        return a.canonical(cur_.sym[pos]) == a.canonical(pm.sym) && cur_.paramCount[pos] == pm.paramSlots.size();
    }
    void bind(const ir::PatternModule& pm, const float* params, double* frame) const {
        for (size_t k = 0; k < pm.paramSlots.size(); ++k) frame[pm.paramSlots[k]] = params[k];
    }

    // Right context from position s: skipped symbols pass, closed branches pass unless the pattern
    // enters one with `[`, `=` jumps to the end of the current branch; the string's `]` ends it.
    bool matchRight(const std::vector<ir::PatternModule>& pattern, size_t s, double* frame) const {
        size_t n = cur_.size();
        size_t wrapped = 0;
        for (const ir::PatternModule& pm : pattern) {
            if (int64_t(pm.sym) == equalsSym_) {
                s = endOfBranch(s);
                continue;
            }
            for (;;) {
                if (s >= n) {
                    if (!g_.ring || wrapped++ > 0) return false;
                    s = 0;
                    continue;
                }
                uint32_t sym = cur_.sym[s];
                if (g_.skippedInContext(sym)) {
                    ++s;
                } else if (pm.sym != ir::kBranchOpen && sym == ir::kBranchOpen) {
                    if (match_[s] == kNone) return false;
                    s = size_t(match_[s]) + 1;
                } else {
                    break;
                }
            }
            if (!sameModule(pm, s)) return false;
            bind(pm, cur_.paramsOf(s), frame);
            ++s;
        }
        return true;
    }

    // Left context ending at position s: branches to the left are skipped, a `[` is passed on the way
    // out of a branch, skipped symbols pass.
    bool matchLeft(const std::vector<ir::PatternModule>& pattern, int64_t s, double* frame) const {
        int64_t n = int64_t(cur_.size());
        size_t wrapped = 0;
        for (auto it = pattern.rbegin(); it != pattern.rend(); ++it) {
            for (;;) {
                if (s < 0) {
                    if (!g_.ring || wrapped++ > 0) return false;
                    s = n - 1;
                    continue;
                }
                uint32_t sym = cur_.sym[size_t(s)];
                if (sym == ir::kBranchClose) {
                    if (match_[size_t(s)] == kNone) return false;
                    s = match_[size_t(s)] - 1;
                } else if (sym == ir::kBranchOpen || g_.skippedInContext(sym)) {
                    --s;
                } else {
                    break;
                }
            }
            if (!sameModule(*it, size_t(s))) return false;
            bind(*it, cur_.paramsOf(size_t(s)), frame);
            --s;
        }
        return true;
    }

    // cpfg keeps one variable table per production for the whole derivation: a local keeps the value of the
    // production's last application until it is assigned again.
    std::vector<std::vector<double>> productionFrames_;

    static void makeFrames(const ir::RuleSet& rules, std::vector<std::vector<double>>& frames) {
        for (const ir::Production& p : rules.productions) frames.emplace_back(size_t(p.frameSize), 0.0);
    }

    // Decomposition or homomorphism: rules applied to single modules, recursively up to a maximum depth.
    struct RecursiveRules {
        RecursiveRules() = default;
        explicit RecursiveRules(const ir::RuleSet& r) : rules(&r) {
            index(r, bySymbol);
            makeFrames(r, frames);
        }
        const ir::RuleSet* rules = nullptr;
        std::vector<std::vector<uint32_t>> bySymbol;
        std::vector<std::vector<double>> frames;
    };
    RecursiveRules decomposition_, homomorphism_;

    // Tests production p with its strict predecessor bound by `bindStrict`; contexts around [left, right].
    template <typename BindStrict>
    bool applicable(const ir::Production& p, int64_t left, size_t right, std::vector<double>& frame,
                    BindStrict bindStrict) {
        if (!p.right.empty() && !matchRight(p.right, right, frame.data())) return false;
        if (!p.left.empty() && !matchLeft(p.left, left, frame.data())) return false;
        bindStrict(frame.data());
        evaluator_.exec(p.before, frame.data());
        return !p.condition || evaluator_.eval(*p.condition, frame.data()) != 0.0;
    }

    // Among applicable candidates with weights, one drawn with probability proportional to its weight.
    uint32_t choose(const ir::RuleSet& rules, const std::vector<uint32_t>& candidates) const {
        double total = 0;
        for (uint32_t c : candidates) total += rules.productions[c].weight;
        const RandomKey& k = evaluator_.key;
        double r = total * shared::randomUnit(k.seed, k.plant, k.pass, k.module, 0);
        for (uint32_t c : candidates)
            if ((r -= rules.productions[c].weight) <= 0) return c;
        return candidates.back();
    }

    // Runs the after-statements and writes the successor (one alternative drawn in order) to `out`.
    void produce(const ir::Production& p, std::vector<double>& frame, ModuleString& out) {
        evaluator_.exec(p.after, frame.data());
        const ir::Alternative* alt = &p.alternatives.back();
        for (size_t k = 0; k + 1 < p.alternatives.size(); ++k)
            if (evaluator_.draw() < p.alternatives[k].probability) {
                alt = &p.alternatives[k];
                break;
            }
        float values[64];
        for (const ir::SuccessorModule& m : alt->modules) {
            size_t count = std::min<size_t>(m.args.size(), 64);
            // A string argument (a label's text, `@L("%.f", x)`) is not kept: modules carry numbers, and the
            // turtle draws no labels. Its slot holds 0, as on the GPU.
            for (size_t a = 0; a < count; ++a)
                values[a] = m.args[a].op == ir::Op::String
                                ? 0.0f
                                : static_cast<float>(evaluator_.eval(m.args[a], frame.data()));
            out.push(m.sym, values, count);
        }
    }

    void setKey(uint32_t pass, uint32_t module) {
        evaluator_.key.pass = pass;
        evaluator_.key.module = module;
        evaluator_.key.draw = 1; // draw 0 belongs to the choice among stochastic productions
    }

    // The production `set` applies to module m at `depth` (counting m among the modules examined there), or kNone.
    template <typename PassOfDepth>
    int64_t chooseRecursive(RecursiveRules& set, PassOfDepth passOfDepth, const ModuleRef& m, int depth, int64_t left,
                            size_t right) {
        const ir::RuleSet& rules = *set.rules;
        if (depthCounter_.size() <= size_t(depth)) depthCounter_.resize(size_t(depth) + 1, 0);
        setKey(passOfDepth(step_, depth), depthCounter_[size_t(depth)]++);
        std::vector<uint32_t> candidates;
        if (m.sym < set.bySymbol.size()) {
            for (uint32_t pi : set.bySymbol[m.sym]) {
                const ir::Production& p = rules.productions[pi];
                if (p.strict.size() != 1 || p.strict[0].paramSlots.size() != m.count) continue;
                std::vector<double>& frame = set.frames[pi];
                bool ok = applicable(p, left, right, frame, [&](double* f) { bind(p.strict[0], m.params, f); });
                if (!ok) continue;
                if (p.weight < 0) return pi;
                candidates.push_back(pi);
            }
        }
        return candidates.empty() ? kNone : choose(rules, candidates);
    }

    // Rewrites module m with `set` (depth-first, up to the maximum depth) into next_, with contexts taken
    // around the predecessor in the current string. Returns false when no rule applies at depth 0 (the
    // caller then copies or cuts). The depth-first walk keeps its own stack, as decompositions may go thousands
    // of levels deep: levels[d] holds what the production applied at depth d produced, next[d] how many of
    // those were rewritten.
    template <typename PassOfDepth>
    bool rewriteRecursively(RecursiveRules& set, PassOfDepth passOfDepth, const ModuleRef& m, int64_t left,
                            size_t right) {
        const ir::RuleSet& rules = *set.rules;
        if (rules.productions.empty() || rules.maxDepth <= 0) return false;
        int64_t found = chooseRecursive(set, passOfDepth, m, 0, left, right);
        if (found == kNone) return false;
        std::vector<ModuleString>& levels = recursionLevels_;
        std::vector<size_t>& next = recursionNext_;
        auto open = [&](size_t level, int64_t production) {
            if (levels.size() <= level) levels.resize(level + 1);
            if (next.size() <= level) next.resize(level + 1);
            levels[level].clear();
            levels[level].stride = stride_;
            produce(rules.productions[size_t(production)], set.frames[size_t(production)], levels[level]);
            next[level] = 0;
        };
        open(0, found);
        for (int64_t top = 0; top >= 0;) {
            ModuleString& level = levels[size_t(top)];
            if (next[size_t(top)] == level.size()) {
                --top;
                continue;
            }
            size_t k = next[size_t(top)]++;
            ModuleRef child{level.sym[k], level.paramsOf(k), level.paramCount[k]};
            int depth = int(top) + 1;
            found = chooseRecursive(set, passOfDepth, child, depth, left, right);
            if (found == kNone || depth >= rules.maxDepth) {
                next_.push(child.sym, child.params, child.count);
                checkBudget(next_.size());
                continue;
            }
            open(size_t(++top), found);
        }
        return true;
    }

    bool decompose(const ModuleRef& m, int64_t left, size_t right) {
        return rewriteRecursively(decomposition_, decompositionPass, m, left, right);
    }

    // Emits module m after trying decomposition on it.
    void emit(const ModuleRef& m, int64_t left, size_t right) {
        if (!decompose(m, left, right)) next_.push(m.sym, m.params, m.count);
        checkBudget(next_.size());
    }

    void rewrite() {
        matchBrackets();
        next_.clear();
        depthCounter_.assign(1, 0);
        const ir::RuleSet& rules = g_.productions;
        const bool useDecomposition = !g_.decomposition.productions.empty();
        std::vector<uint32_t> candidates;
        ModuleString produced;
        produced.stride = stride_;
        size_t n = cur_.size();
        for (size_t i = 0; i < n;) {
            uint32_t sym = cur_.sym[i];
            setKey(step_ * kPassesPerStep, uint32_t(i));
            sense(i);
            int64_t found = kNone;
            candidates.clear();
            if (sym < productionsBySymbol_.size()) {
                for (uint32_t pi : productionsBySymbol_[sym]) {
                    const ir::Production& p = rules.productions[pi];
                    if (i + p.strict.size() > n) continue;
                    bool strictMatches = true;
                    for (size_t k = 0; k < p.strict.size() && strictMatches; ++k)
                        strictMatches = sameModule(p.strict[k], i + k);
                    if (!strictMatches) continue;
                    std::vector<double>& frame = productionFrames_[pi];
                    bool ok = applicable(p, int64_t(i) - 1, i + p.strict.size(), frame, [&](double* f) {
                        for (size_t k = 0; k < p.strict.size(); ++k) bind(p.strict[k], cur_.paramsOf(i + k), f);
                    });
                    if (!ok) continue;
                    if (!stochastic_) {
                        found = pi;
                        break;
                    }
                    candidates.push_back(pi);
                }
            }
            if (stochastic_ && !candidates.empty()) found = choose(rules, candidates);
            if (found != kNone) {
                const ir::Production& p = rules.productions[size_t(found)];
                std::vector<double>& frame = productionFrames_[size_t(found)];
                size_t len = p.strict.size();
                if (!useDecomposition) {
                    produce(p, frame, next_);
                    checkBudget(next_.size());
                } else {
                    produced.clear();
                    produce(p, frame, produced);
                    for (size_t k = 0; k < produced.size(); ++k)
                        emit({produced.sym[k], produced.paramsOf(k), produced.paramCount[k]}, int64_t(i) - 1, i + len);
                }
                inherit(i);
                i += len;
                continue;
            }
            ModuleRef self{sym, cur_.paramsOf(i), cur_.paramCount[i]};
            uint32_t examined = depthCounter_[0];
            if (useDecomposition && decompose(self, int64_t(i) - 1, i + 1)) {
                checkBudget(next_.size());
                inherit(i);
                ++i;
                continue;
            }
            if (sym == percentSym_ && cur_.paramCount[i] == 0) {
                // The cut `%` leaves the string: it does not count among the modules decomposition examined,
                // which keeps that count equal to a module's position in the step's output.
                if (useDecomposition) depthCounter_[0] = examined;
                i = endOfBranch(i + 1); // the cut drops the rest of the branch; its `]` stays
                continue;
            }
            next_.push(sym, self.params, self.count);
            checkBudget(next_.size());
            inherit(i);
            ++i;
        }
        std::swap(cur_, next_);
    }
};

// Appends one plant's string, whose stride may be smaller than the stream's.
void appendPlant(ModuleString& out, const ModuleString& s) {
    out.append(s, 0, s.size());
    out.plantStart.push_back(out.sym.size());
}

} // namespace

DeriveResult deriveCpu(const ir::Grammar& g, const DeriveOptions& options) {
    return deriveSpeciesCpu({g}, options);
}

DeriveResult deriveSpeciesCpu(const std::vector<ir::Grammar>& species, const DeriveOptions& options) {
    PlantControl control(species, options);
    DeriveResult result;
    result.string.stride = control.stride();
    result.string.plantStart.push_back(0);
    uint64_t used = 0;
    std::vector<std::vector<shared::ParticleState>> axiomParticles =
        options.particles ? stream::splitAxiomParticles(species, control.plants(), options)
                          : std::vector<std::vector<shared::ParticleState>>{};
    for (uint32_t plant = 0; plant < control.plants(); ++plant) {
        PlantDeriver deriver(control, plant, control.budget() - used, control.budget());
        std::optional<std::vector<shared::ParticleState>> particles;
        if (options.particles) particles = std::move(axiomParticles[plant]);
        deriver.run(particles);
        if (options.homomorphism) deriver.applyHomomorphism();
        used += deriver.result().size();
        appendPlant(result.string, deriver.result());
    }
    result.steps = control.mostStepsDerived();
    return result;
}

ModuleString applyHomomorphismCpu(const std::vector<ir::Grammar>& species, const ModuleString& derived,
                                  const DeriveOptions& options) {
    DeriveOptions adopted = options;
    adopted.plants = static_cast<uint32_t>(derived.plants());
    PlantControl control(species, adopted);
    uint64_t budget = options.maxModules ? options.maxModules : stream::defaultModuleBudget(derived.stride);
    ModuleString out;
    out.stride = std::max(derived.stride, control.stride());
    out.plantStart.push_back(0);
    for (uint32_t plant = 0; plant < derived.plants(); ++plant) {
        PlantDeriver deriver(control, plant, budget - std::min<uint64_t>(budget, out.size()), budget);
        deriver.adopt(derived, derived.plantStart[plant], derived.plantStart[plant + 1]);
        deriver.applyHomomorphism();
        appendPlant(out, deriver.result());
    }
    return out;
}

SteppedDerivation::SteppedDerivation(const std::vector<ir::Grammar>& species, const DeriveOptions& options)
    : species_(species), options_(options), control_(species, options) {
    string_ = control_.startAll();
    if (options.particles) {
        for (std::vector<shared::ParticleState>& plant :
             stream::splitAxiomParticles(species, control_.plants(), options))
            string_.particles.insert(string_.particles.end(), plant.begin(), plant.end());
    }
    if (string_.size() > control_.budget())
        throw ir::LimitError(fmt::format("the axioms alone exceed the module budget of {} modules", control_.budget()));
}

stream::SteppedState SteppedDerivation::save() const {
    stream::SteppedState state{string_, fieldStep_, {}};
    for (uint32_t plant = 0; plant < control_.plants(); ++plant) state.plants.push_back(control_.variables(plant));
    return state;
}

void SteppedDerivation::resume(const stream::SteppedState& state) {
    if (state.plants.size() != control_.plants() || state.string.plantStart.size() != control_.plants() + 1 ||
        state.string.particles.size() != (options_.particles ? state.string.size() : 0))
        throw std::invalid_argument("SteppedDerivation::resume: the state is not of this derivation's plants");
    for (uint32_t plant = 0; plant < control_.plants(); ++plant) control_.restore(plant, state.plants[plant]);
    string_ = state.string;
    fieldStep_ = state.fieldStep;
}

uint32_t SteppedDerivation::advance(const std::vector<uint8_t>& due) {
    if (due.size() != control_.plants()) throw std::invalid_argument("SteppedDerivation::advance: one flag per plant");
    std::vector<uint8_t> growing(control_.plants(), 0);
    uint32_t deriving = 0;
    for (uint32_t plant = 0; plant < control_.plants(); ++plant) {
        growing[plant] = due[plant] && control_.beginStep(plant, control_.stepsDerived(plant) + 1);
        deriving += growing[plant];
    }
    ++fieldStep_; // counted where none derives too, as in every batch of the field
    if (deriving == 0) return 0;
    ModuleString next;
    next.stride = string_.stride;
    next.plantStart.push_back(0);
    const uint64_t budget = control_.budget();
    for (uint32_t plant = 0; plant < control_.plants(); ++plant) {
        const size_t begin = string_.plantStart[plant], end = string_.plantStart[plant + 1];
        if (!growing[plant]) { // copied as it is
            next.append(string_, begin, end);
            next.plantStart.push_back(next.size());
            continue;
        }
        PlantDeriver deriver(control_, plant, budget - std::min<uint64_t>(budget, next.size()), budget);
        deriver.adopt(string_, begin, end, false);
        deriver.derive(fieldStep_);
        control_.endStep(plant, control_.stepsDerived(plant) + 1);
        appendPlant(next, deriver.result());
    }
    string_ = std::move(next);
    return deriving;
}

ModuleString SteppedDerivation::drawn(std::vector<uint32_t>* origins) const {
    if (!origins || string_.particles.empty()) return applyHomomorphismCpu(species_, string_, options_);
    // Each drawn module takes the state of the module it comes from: a copy whose states are stamped with their
    // modules' indices tells which, and the drawn modules then take the true states.
    ModuleString stamped = string_;
    for (size_t i = 0; i < stamped.size(); ++i) stamped.particles[i].value[0] = std::bit_cast<float>(uint32_t(i));
    ModuleString drawn = applyHomomorphismCpu(species_, stamped, options_);
    origins->resize(drawn.size());
    for (size_t j = 0; j < drawn.size(); ++j) {
        const uint32_t origin = std::bit_cast<uint32_t>(drawn.particles[j].value[0]);
        (*origins)[j] = origin;
        drawn.particles[j] = string_.particles[origin];
    }
    return drawn;
}

} // namespace simeco::cpu
