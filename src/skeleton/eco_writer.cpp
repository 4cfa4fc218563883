#include "skeleton/eco_writer.h"

#include <algorithm>

#include <fmt/format.h>

namespace simeco::skeleton {

namespace {

// How many derivation steps the prediction rules get after the skeleton has regrown, by default (the script's
// DerivationLength; `simeco run` derives no further).
constexpr int kPredictedSteps = 6;

std::string number(double v) { return fmt::format("{:.9g}", v); }
std::string number(float v) { return fmt::format("{:.9g}", double(v)); }

std::string range(const Range& r) {
    return r.min == r.max ? number(r.min) : fmt::format("rand({}, {})", number(r.min), number(r.max));
}

// The turn before a child: rotr then rotu, as the generator writes them (the turtle rolls by rotu first).
std::string turn(const Turn& t) { return fmt::format("rotr({}) rotu({})", number(t.pitch), number(t.roll)); }

const char* organLetter(OrganKind kind) {
    return kind == OrganKind::Leaf ? "L" : kind == OrganKind::Flower ? "F" : "T";
}

class EcoScript {
public:
    EcoScript(const Plant& plant, const Regrowth& g, const EcoScriptOptions& o) : plant_(plant), g_(g), o_(o) {
        const size_t n = g.internodes.size();
        // Stages: internode i is stage i + 1; then the templates, the apex that picks one, and the waiting apices.
        firstTemplate_ = int(n) + 1;
        const size_t templates = o.prediction ? o.prediction->templates.size() : 0;
        pick_ = firstTemplate_ + int(templates);
        waitFirst_ = pick_ + 1;
        levels_ = g.tree.levels;
    }

    std::string text() {
        std::string s = header();
        s += "EcoSystem 1.0 \"Inferred\" {\n";
        s += fmt::format("    Plant \"{}\" {{\n", plantName());
        const glm::dvec3 p = o_.position;
        s += fmt::format("        Position = vector({}, {}, {});\n", number(p.x), number(p.y), number(p.z));
        s += "        Direction = vector(0.0, 1.0, 0.0);\n";
        s += "        DeriveTime = 1.0;\n";
        s += fmt::format("        DerivationLength = {};\n", levels_ + (o_.prediction ? kPredictedSteps : 0));
        s += "        Apex {}\n";
        s += stems();
        s += organs();
        s += grow();
        return s + "    }\n}\n";
    }

private:
    const Plant& plant_;
    const Regrowth& g_;
    const EcoScriptOptions& o_;
    int firstTemplate_ = 0, pick_ = 0, waitFirst_ = 0, levels_ = 0;

    int stageOf(int internode) const { return internode + 1; }

    std::string plantName() const {
        std::string name = o_.name;
        if (o_.description && !o_.description->leafShape.empty()) name += " (" + o_.description->leafShape + ")";
        return name;
    }

    std::string header() const {
        std::string s = fmt::format("// Inferred by simeco infer from {}: {} internodes in {} levels.\n", o_.source,
                                    g_.internodes.size(), levels_);
        if (o_.description && !o_.description->understood.empty()) {
            std::string words;
            for (const std::string& w : o_.description->understood) words += (words.empty() ? "" : ", ") + w;
            s += "// Described as: " + words + ".\n";
        }
        if (!o_.dressing.empty()) s += "// Added to the skeleton: " + o_.dressing + ".\n";
        s += fmt::format("// Its first {} derivation steps regrow the skeleton (A(n) -> S(n) ...: internode n is stage "
                         "n,\n// GrowRate x GrowTime its length, BroadenRate x GrowTime its width).",
                         levels_);
        if (o_.prediction)
            s += fmt::format(" In the {} steps after them,\n// its tips grow on by the prediction rules at the end, "
                             "templates of its own rules (derive with\n// -n {} for the skeleton alone, or more to "
                             "grow further).",
                             kPredictedSteps, levels_);
        return s + "\n";
    }

    std::string stems() const {
        std::string s = "        Stem {\n";
        for (size_t i = 0; i < g_.internodes.size(); ++i) {
            const GrownInternode& n = g_.internodes[i];
            s += fmt::format("            Stage {} {{ GrowRate = {}; GrowTime = 1.0; BroadenRate = {}; }}\n",
                             stageOf(int(i)), number(n.length), number(n.width));
        }
        if (o_.prediction)
            for (size_t k = 0; k < o_.prediction->templates.size(); ++k) {
                const RuleTemplate& t = o_.prediction->templates[k];
                s += fmt::format("            Stage {} {{ GrowRate = {}; GrowTime = 1.0; BroadenRate = {}; }}\n",
                                 firstTemplate_ + int(k), range(t.length), range(t.width));
            }
        return s + "        }\n";
    }

    // One stage per organ kind, at the kind's typical size: a leaf's drawn size is its model's (1) grown by the
    // stage, a flower's or fruit's diameter the stage's growth.
    std::string organs() const {
        std::string s;
        for (OrganKind kind : {OrganKind::Leaf, OrganKind::Flower, OrganKind::Fruit}) {
            std::vector<double> sizes;
            for (const Organ& o : plant_.organs)
                if (o.kind == kind && o.size > 0.0) sizes.push_back(o.size);
            if (sizes.empty()) continue;
            std::nth_element(sizes.begin(), sizes.begin() + long(sizes.size() / 2), sizes.end());
            double size = sizes[sizes.size() / 2];
            double growth = kind == OrganKind::Leaf ? size - 1.0 : size;
            const char* block = kind == OrganKind::Leaf ? "Leaf" : kind == OrganKind::Flower ? "Flower" : "Fruit";
            s += fmt::format("        {} {{\n            Stage 0 {{ GrowRate = {}; GrowTime = 1.0; }}\n        }}\n",
                             block, number(growth));
        }
        return s;
    }

    std::string organBrackets(const std::vector<GrownOrgan>& organs) const {
        std::string s;
        for (const GrownOrgan& o : organs)
            s += fmt::format(" [{} {}(0)]", turn(o.turn), organLetter(plant_.organs[size_t(o.organ)].kind));
        return s;
    }

    std::string grow() const {
        std::string s = "        Grow {\n            w =";
        // The axiom: the other stems standing on the base in brackets, then the trunk.
        s += organBrackets(g_.baseOrgans);
        for (size_t k = 1; k < g_.roots.size(); ++k)
            s += fmt::format(" [{} A({})]", turn(g_.roots[k].turn), stageOf(g_.roots[k].internode));
        s += fmt::format(" {} A({});\n", turn(g_.roots.front().turn), stageOf(g_.roots.front().internode));
        for (size_t i = 0; i < g_.internodes.size(); ++i) s += rule(int(i));
        if (o_.prediction) s += prediction();
        return s + "        }\n";
    }

    std::string rule(int i) const {
        const GrownInternode& n = g_.internodes[size_t(i)];
        std::string s = fmt::format("            A({}) -> S({})", stageOf(i), stageOf(i));
        if (n.rollAfter != 0.0f) s += fmt::format(" rotu({})", number(n.rollAfter));
        s += organBrackets(n.organs);
        for (size_t c = 1; c < n.children.size(); ++c)
            s += fmt::format(" [{} A({})]", turn(n.children[c].turn), stageOf(n.children[c].internode));
        if (!n.children.empty())
            s += fmt::format(" {} A({})", turn(n.children.front().turn), stageOf(n.children.front().internode));
        else if (o_.prediction) // a tip waits for the rest of the skeleton, then grows on
            s += fmt::format(" A({})", waitFirst_ + g_.tree.internodes[size_t(i)].level + 1);
        return s + ";\n";
    }

    // A tip's apex counts the steps until the skeleton has regrown (the thesis' step function), turns as main
    // children turn and grows on: each apex picks a template by the share of the young growth's rules of its shape
    // and puts out the template's children as apices that pick again, a level a step.
    std::string prediction() const {
        const Prediction& p = *o_.prediction;
        const int done = waitFirst_ + levels_;
        Range pitch{1.0f, 0.0f}, roll{1.0f, 0.0f};
        for (const RuleTemplate& t : p.templates)
            if (t.goesOn) {
                pitch.add(t.pitch[0].min);
                pitch.add(t.pitch[0].max);
                roll.add(t.roll[0].min);
                roll.add(t.roll[0].max);
            }
        std::string s = "            // Prediction: templates of the young growth's rules, by shape, with the ranges "
                        "their numbers span.\n";
        s += fmt::format("            A(i) -> A(i + 1, {} < i < {});\n", waitFirst_, done);
        s += fmt::format("            A({}) ->{} A({});\n", done,
                         pitch.empty() ? "" : fmt::format(" rotr({}) rotu({})", range(pitch), range(roll)), pick_);
        s += fmt::format("            A({}) ->", pick_);
        double left = 1.0;
        for (size_t k = 0; k < p.templates.size(); ++k) {
            const double share = double(p.templates[k].members) / double(std::max<size_t>(p.internodes, 1));
            const bool last = k + 1 == p.templates.size();
            if (k > 0) s += "\n                |";
            if (!last) s += fmt::format(" prob({})", number(std::min(1.0, share / left)));
            s += templateSuccessor(p.templates[k], firstTemplate_ + int(k));
            left -= share;
        }
        return s + ";\n";
    }

    std::string templateSuccessor(const RuleTemplate& t, int stage) const {
        std::string s = fmt::format(" S({})", stage);
        for (size_t l = 0; l < t.leaves; ++l)
            s += fmt::format(" [rotr({}) rotu({}) L(0)]", range(t.leafPitch), range(t.leafRoll));
        for (size_t c = 1; c < t.pitch.size(); ++c)
            s += fmt::format(" [rotr({}) rotu({}) A({})]", range(t.pitch[c]), range(t.roll[c]), pick_);
        if (t.goesOn) s += fmt::format(" rotr({}) rotu({}) A({})", range(t.pitch[0]), range(t.roll[0]), pick_);
        return s;
    }
};

} // namespace

std::string ecoScript(const Plant& plant, const Regrowth& growth, const EcoScriptOptions& options) {
    return EcoScript(plant, growth, options).text();
}

} // namespace simeco::skeleton
