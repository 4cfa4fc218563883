// A SimEco scene: the ecosystem, its plants, their organ stages and Grow blocks, as a `.eco` script
// describes them (Shih, "An Adaptive L-System", 2004, appendix B).
//
// The scene keeps what the script says and nothing drawn from it: `rand(a, b)` stays a range, to be drawn
// per plant (and per particle) by the simulation, so that two plants of one script can differ. Each plant's
// Grow block is kept as parsed rules with names already resolved to frame slots; lang/eco_compile lowers it
// to an ir::Grammar.
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "ir/eco_field.h"
#include "ir/expr.h"
#include "ir/source_loc.h"

namespace simeco::ir {

// A script number: a constant, or `rand(min, max)`, uniform on [min, max] and drawn later.
struct EcoNumber {
    float min = 0.0f;
    float max = 0.0f;
    bool random = false;
    SourceLoc loc;

    static EcoNumber constant(float v, SourceLoc l = {}) { return {v, v, false, std::move(l)}; }
    static EcoNumber range(float lo, float hi, SourceLoc l = {}) { return {lo, hi, true, std::move(l)}; }
    // The value of a constant; the middle of a range (for previews that draw nothing).
    float typical() const { return random ? 0.5f * (min + max) : min; }
};

struct EcoVector {
    EcoNumber x, y, z;
};

// `RGBA(r, g, b, a)`.
struct EcoColor {
    EcoNumber r, g, b, a;
};

// `MTRL(...)`: six numbers. The thesis does not name them; its scripts read as a diffuse then an ambient
// RGB factor (leaves use MTRL(1.8, 1.8, 1.3, 0.3, 0.3, 0.2)), so renderers should treat them that way.
struct EcoMaterial {
    std::array<EcoNumber, 6> values;
};

// The particle parameters of one stage of one organ. Unset properties fall back to the organ's Default
// stage, then to the simulation's own defaults.
struct EcoStage {
    std::optional<std::string> model;
    std::optional<std::string> texture;     // `Texture` or `TextureFront`
    std::optional<std::string> textureBack; // `TextureBack`: the back face of a leaf; front texture when unset
    std::optional<EcoNumber> growRate;
    std::optional<EcoNumber> growTime;
    std::optional<EcoNumber> lifeTime;
    std::optional<EcoNumber> broadenRate;
    std::optional<EcoNumber> weightFactor;
    std::optional<EcoNumber> coneNoise;
    std::optional<EcoNumber> noiseTime;
    std::optional<EcoNumber> strength;
    std::optional<EcoNumber> geotropism;
    std::optional<EcoNumber> phototropism; // simeco's: how far a stem turns toward the light
    std::optional<EcoNumber> shadeTime;    // simeco's: seconds an organ lives in deep shade before it is shed
    std::optional<EcoColor> color; // `Color` or `ColorFront`
    std::optional<EcoColor> colorBack;
    std::optional<EcoMaterial> material; // `Material` or `MaterialFront`
    std::optional<EcoMaterial> materialBack;
    SourceLoc loc;
};

// The organ kinds of appendix B, in the order of their segment letters A S L F T R.
enum class EcoOrganKind : int { Apex, Stem, Leaf, Flower, Fruit, Root };
inline constexpr int kEcoOrganKinds = 6;
// The largest stage number a script may use (stages are numbered from 0).
inline constexpr int kMostStage = 1000000;

// The Grow-block segment letter of each organ kind: A apex, S stem, L leaf, F flower, T fruit (the thesis
// leaves F and T unassigned; F = flower and T = fruit follow the order of its organ list), R root.
inline constexpr std::array<char, kEcoOrganKinds> kEcoSegmentLetters = {'A', 'S', 'L', 'F', 'T', 'R'};
inline constexpr std::array<const char*, kEcoOrganKinds> kEcoOrganNames = {"Apex",   "Stem",  "Leaf",
                                                                           "Flower", "Fruit", "Root"};

inline std::optional<EcoOrganKind> ecoOrganForLetter(char letter) {
    for (int k = 0; k < kEcoOrganKinds; ++k)
        if (kEcoSegmentLetters[k] == letter) return static_cast<EcoOrganKind>(k);
    return std::nullopt;
}

struct EcoOrgan {
    bool present = false; // declared in the script (possibly empty: `Apex {}`)
    std::map<int, EcoStage> stages;
    std::optional<EcoStage> defaultStage;
    SourceLoc loc;

    // The stage's own settings, else the Default stage, else nothing.
    const EcoStage* stageFor(int stage) const {
        auto it = stages.find(stage);
        if (it != stages.end()) return &it->second;
        return defaultStage ? &*defaultStage : nullptr;
    }
};

// A module of a Grow block successor or axiom: a segment `S(3)` (name "S", one argument: the stage), a
// rotation `rotr(0.78)` (one argument: radians), or a bracket "[" / "]" (no arguments). Arguments are
// expressions over the rule's frame (Const in the axiom).
struct EcoModule {
    std::string name;
    std::vector<Expr> args;
    SourceLoc loc;
};

// A segment of a predecessor or context: `S(7)` (a literal stage) or `L(i)` (a variable). Both bind the
// stage to a frame slot; a literal adds the condition `slot == stage` when compiled.
struct EcoPatternSegment {
    char letter = 'S';
    std::optional<int> stage;
    int slot = 0;
    SourceLoc loc;
};

// One successor of a rule, after `->` or `|`.
struct EcoAlternative {
    std::optional<float> probability; // `prob(p)`; none: taken whenever it is reached
    // The condition of a step successor `L(i + 1, 1 < i < 6)`: the stage advances while it holds.
    std::optional<Expr> stepCondition;
    std::vector<EcoModule> modules; // empty for `null`
    bool erase = false;             // `null`: the module dies
    SourceLoc loc;
};

// `left < predecessor > right -> alternatives;`
struct EcoRule {
    std::vector<EcoPatternSegment> left;
    EcoPatternSegment predecessor;
    std::vector<EcoPatternSegment> right;
    std::vector<std::string> slotNames; // frame slots: pattern segments in text order (left, strict, right)
    std::optional<Expr> condition;      // `: expression` before `->` (simeco's: the environment, the stages)
    std::vector<EcoAlternative> alternatives;
    SourceLoc loc;
};

struct EcoGrow {
    std::vector<EcoModule> axiom; // `w = ...;`
    SourceLoc axiomLoc;
    std::vector<EcoRule> rules;
    SourceLoc loc;
};

struct EcoPlant {
    std::string name;
    // `Grammar = "file.l";` (a simeco extension): the plant's grammar is a cpfg `.l` or quick `.lsys` file,
    // relative to the scene's folder, instead of organ blocks and a Grow block.
    std::string grammar;
    SourceLoc grammarLoc;
    EcoVector position{EcoNumber::constant(0), EcoNumber::constant(0), EcoNumber::constant(0)};
    EcoVector direction{EcoNumber::constant(0), EcoNumber::constant(1), EcoNumber::constant(0)};
    // Seconds between derivation steps; particles grow continuously in between. 3 s is what every seed
    // script sets.
    EcoNumber deriveTime = EcoNumber::constant(3.0f);
    // `DerivationLength = n;` (a simeco extension; appendix B has none): derivation steps to run.
    std::optional<int> derivationLength;
    std::array<EcoOrgan, kEcoOrganKinds> organs;
    EcoGrow grow;
    SourceLoc loc;

    const EcoOrgan& organ(EcoOrganKind kind) const { return organs[static_cast<int>(kind)]; }
};

// A remark about input that was accepted but looks damaged (e.g. a stray `}`), printed as a warning.
struct EcoWarning {
    SourceLoc loc;
    std::string message;
};

struct EcoScene {
    std::string file;
    float version = 1.0f;
    std::string name;
    // Ecosystem attributes; unset ones keep the values every seed script uses.
    EcoNumber soilPH = EcoNumber::constant(7.0f);
    EcoNumber rainRate = EcoNumber::constant(0.9f);
    EcoNumber dayLight = EcoNumber::constant(12.0f); // hours
    EcoVector gravity{EcoNumber::constant(0), EcoNumber::constant(-9.8f), EcoNumber::constant(0)};
    std::vector<EcoPlant> plants;
    std::vector<EcoPopulation> populations;
    std::vector<EcoObstacle> obstacles;
    EcoLight light;
    std::vector<EcoWarning> warnings;
    SourceLoc loc;
};

} // namespace simeco::ir
