// The grammar IR: one form for every input language.
//
// A grammar is an alphabet, an axiom, three rule sets (productions, decomposition, homomorphism), the
// context filter, global variables and arrays, control blocks and function tables. Front ends build it;
// the CPU reference engine runs it; the GPU back end compiles it.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "ir/expr.h"
#include "ir/contour_curve.h"
#include "ir/cylinder_contour.h"
#include "ir/function_curve.h"
#include "ir/leaf_model.h"
#include "ir/picture_look.h"

namespace simeco::ir {

using SymbolId = uint32_t;

// Symbols with fixed ids, so that every engine and kernel can test for them without a lookup.
inline constexpr SymbolId kBranchOpen = 0;  // [
inline constexpr SymbolId kBranchClose = 1; // ]
inline constexpr SymbolId kCut = 2;         // %

// Symbols by name. A file of several L-systems (cpfg's sub-L-systems) gives each L-system's modules symbols of
// their own, in the L-system's `space` (0: the main L-system, and every other language): `B` rewritten by a
// sub-L-system is another symbol than the main L-system's `B`, written and drawn alike, and context matches
// them by name (canonical()).
class Alphabet {
public:
    Alphabet();
    SymbolId intern(const std::string& name, uint32_t space = 0);
    std::optional<SymbolId> find(const std::string& name) const; // in space 0
    const std::string& name(SymbolId id) const { return names_[id]; }
    uint32_t space(SymbolId id) const { return spaces_[id]; }
    // The first symbol of this one's name: equal for symbols that context matching takes for each other.
    SymbolId canonical(SymbolId id) const { return canonical_[id]; }
    bool hasSpaces() const { return hasSpaces_; }
    size_t size() const { return names_.size(); }
    const std::vector<std::string>& names() const { return names_; }

private:
    std::vector<std::string> names_;
    std::vector<uint32_t> spaces_;
    std::vector<SymbolId> canonical_;
    std::unordered_map<std::string, SymbolId> ids_;       // by name, and name + '\x1f' + space outside space 0
    std::unordered_map<std::string, SymbolId> firstByName_;
    bool hasSpaces_ = false;
};

// A module with actual parameter values: an axiom entry, or a module of a derived string.
struct Module {
    SymbolId sym = 0;
    std::vector<float> params;
};

// A module in a predecessor or context: its formal parameters bind to frame slots.
struct PatternModule {
    SymbolId sym = 0;
    std::vector<int> paramSlots;
    SourceLoc loc;
};

// A module in a successor: its parameters are expressions over the production's frame and the globals.
struct SuccessorModule {
    SymbolId sym = 0;
    std::vector<Expr> args;
    SourceLoc loc;
};

// One successor of a production. cpfg productions have exactly one; SimEco's `prob(p) a | prob(q) b | c`
// has several, tried in order, each taken with its probability (1 for the last, unconditional one).
struct Alternative {
    float probability = 1.0f;
    std::vector<SuccessorModule> modules; // empty: the module is erased (`*`, `null`)
};

struct Production {
    std::vector<PatternModule> left;   // left context, in text order
    std::vector<PatternModule> strict; // strict predecessor (one or more modules)
    std::vector<PatternModule> right;  // right context, in text order
    std::vector<Stmt> before;          // statements run when the predecessor and contexts match
    std::optional<Expr> condition;     // none: always true (`*` or no condition)
    std::vector<Stmt> after;           // statements run once the condition holds
    std::vector<Alternative> alternatives;
    // cpfg stochastic factor (`--> succ : 40`); negative when the production has none. Among applicable
    // productions with factors, one is drawn with probability proportional to its factor.
    float weight = -1.0f;
    int frameSize = 0;                  // formal parameters and local variables
    std::vector<std::string> slotNames; // for messages and generated code
    SourceLoc loc;
};

struct RuleSet {
    std::vector<Production> productions;
    int maxDepth = 1; // decomposition and homomorphism: passes until no rule applies or this depth
    bool present = false;
};

struct GlobalArray {
    std::string name;
    std::vector<int> dims;
    std::vector<float> init; // row-major, size = product of dims
    SourceLoc loc;
};

struct FunctionCurve {
    std::string name;
    std::vector<float> xs, ys; // B-spline control points, repeated by their multiplicity
    int samples = 0;           // cpfg precomputes this many samples and interpolates; <= 2: exact
    std::vector<double> table; // the precomputed samples (see function_curve.h)
};

// Turtle settings a grammar brings with it (view file, directives); interpreted by later stages.
// How segments bend toward the tropism direction (ViewSettings::tropismDirection, by the elasticity).
enum class TropismRule {
    // After each drawn segment, about H x T by elasticity x |H x T| (ABOP's; the quick grammars' and the growth's).
    Torque,
    // cpfg's `tropism direction:` form: after every move (F G f g) the heading turns toward T's component along
    // up, then toward its component along left, each by the arcsine of the elasticity times that component.
    CpfgDirection,
    // cpfg's `tropism:` lines: before every move (F G f g), about H x T by elasticity x |H x T| (beyond a radian as
    // cpfg's quaternion turns, turtle/frame.h cpfgTurnAngle).
    CpfgTropism,
};

// How segments (F, G) are drawn: cpfg's `line style` (and the style word of `initial line width`).
enum class LineStyle {
    Cylinder, // shaded cylinders, widths in world units (the quick grammars' and the scenes')
    Polygon,  // flat bands facing the viewer, widths in world units (cpfg's `initial line width: x` alone)
    Pixel,    // flat lines facing the viewer, widths in pixels (cpfg's default, `p`, `pixels`)
};

struct ViewSettings {
    float angleIncrement = 45.0f;
    float stepSize = 1.0f;
    float lineWidth = 1.0f;
    float widthIncrement = 1.0f;
    float colorIncrement = 1.0f;
    float initialColor = 1.0f;
    // Tropism: after each drawn segment the heading bends toward `tropismDirection` by elasticity * |H x T|.
    std::array<float, 3> tropismDirection = {0.0f, -1.0f, 0.0f};
    float initialElasticity = 0.0f;
    float initialScale = 1.0f; // cpfg's `initial scale:`, the turtle's scale before any `@D` (lengths and `!` widths)
    float elasticityIncrement = 0.0f;
    TropismRule tropismRule = TropismRule::Torque;
    // cpfg's `torque:` lines: the sum of their directions times their elasticities (and intensities), which rolls
    // the turtle before every move (F G f g).
    std::array<float, 3> torque = {0.0f, 0.0f, 0.0f};
    LineStyle lineStyle = LineStyle::Cylinder;
    // cpfg's `tapered lines: on` (its default, and so in .l files unless the view says off): a segment narrows
    // from its width to the width set before the command that ends it (a branch, the next segment or move).
    bool taperedLines = false;
    // `$` rolls the turtle so that its left is horizontal (the quick grammars', ABOP's); in cpfg's .l files it ends
    // a sub-L-system call and leaves the turtle alone (cpfg rolls upright with `@v`).
    bool dollarRolls = true;
    // `;` colour indices to linear RGB (a model's colour map); empty: simeco's default palette.
    std::vector<std::array<float, 3>> palette;
    // Per palette entry (where shorter, -1 for the rest): the texture layer its colour tints, or -1 for none.
    std::vector<int> paletteTextures;
    // `~name` surfaces the view file names, with the file each was read from and its scale.
    struct Surface {
        std::string name, file;
        float scale = 1.0f;
        std::optional<uint32_t> shape; // the leaf shape that draws it, where a model names it (else its name's)
        // cpfg's `.s` surface read from `file` (at `scale`, which it already holds); null where none was read.
        std::shared_ptr<const SurfaceModel> model;
    };
    std::vector<Surface> surfaces;
    // Whether `~` of a name the view defines no surface for draws a built-in blade chosen by the name (simeco's
    // and the quick grammars' way) or nothing, as cpfg does in .l files.
    bool undefinedSurfacesDrawn = true;
    // Generalized cylinders as cpfg draws them (in .l files): with `line style: cylinder`, meshes of rings around
    // the contours `@#(id)` selects, `cylinderSides` points each (`contour sides:`, `polygonization level:`), the
    // rings turning with the turtle's roll where `twist of cylinders: on`; otherwise, and elsewhere, tubes of
    // segments.
    bool cpfgCylinders = false;
    int cylinderSides = 8;
    bool cylinderTwist = false;
    std::vector<CylinderContour> contours; // `contour: id file` lines, in the view's order
    PictureLook look; // simeco's own lines: the picture's style, ground and background
    bool present = false;
};

struct Grammar {
    std::string sourceFile;
    Alphabet alphabet;
    std::vector<SuccessorModule> axiom; // parameters are expressions, evaluated after the Start block
    SourceLoc axiomLoc;
    int derivationLength = 0;
    int lsystems = 1; // cpfg's: the main L-system and its sub-L-systems
    uint32_t seed = 0;
    bool ring = false;

    RuleSet productions;
    RuleSet decomposition;
    RuleSet homomorphism;

    // Per symbol: true when context matching skips it (from `ignore:` or the complement of `consider:`).
    std::vector<bool> contextSkip;
    // What a symbol first seen after `consider:` gets: skipped, since consider lists what is not.
    bool contextSkipDefault = false;

    std::vector<std::string> globalNames;
    std::vector<float> globalInit;
    std::vector<GlobalArray> arrays;
    std::vector<Stmt> startBlock, startEachBlock, endEachBlock, endBlock;
    std::vector<FunctionCurve> functions;
    std::vector<ContourCurve> curves; // curveX/Y/Z/GAL ids are 1-based in this order
    ViewSettings view;

    bool skippedInContext(SymbolId s) const { return s < contextSkip.size() && contextSkip[s]; }
    // A symbol by name, added to the alphabet (and the context filter) when new.
    SymbolId symbol(const std::string& name, uint32_t space = 0);
    // The largest parameter count of any module that can appear (sets the stride of the module stream).
    int maxParams() const;
};

} // namespace simeco::ir
