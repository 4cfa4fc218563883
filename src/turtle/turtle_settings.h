// The turtle's settings for one species, resolved from its grammar's view settings: defaults filled in, the
// colour palette complete, and every symbol that may name a `~` surface given a scale and a leaf shape.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "ir/grammar.h"

namespace simeco::turtle {

inline constexpr size_t kPaletteSize = 256;

struct TurtleSettings {
    float angleDegrees = 45.0f;
    float step = 1.0f;
    float width = 1.0f;
    float widthIncrement = 1.0f;
    float colorIncrement = 1.0f;
    float initialColor = 1.0f;
    glm::vec3 tropism{0.0f, -1.0f, 0.0f}; // unit
    float elasticity = 0.0f;
    float elasticityIncrement = 0.0f;
    float initialScale = 1.0f;
    ir::TropismRule tropismRule = ir::TropismRule::Torque;
    ir::LineStyle lineStyle = ir::LineStyle::Cylinder;
    bool taperedLines = false; // ir::ViewSettings::taperedLines
    bool dollarRolls = true;   // ir::ViewSettings::dollarRolls
    glm::vec3 torque{0.0f};    // ir::ViewSettings::torque
    bool subLsystems = false;  // the grammar has sub-L-systems, whose calls `$` returns from
    // ir::ViewSettings' generalized cylinders: meshes (cpfg's `line style: cylinder`) or tubes of segments. Contour
    // index k (0 the circle, then the view's in its order) has the id contourIds[k] and its ring at
    // contourRings[k * (cylinderSides + 1)], as contour_ring.h samples it.
    bool cylinderMeshes = false;
    // Tubes as cpfg draws them in its pixel and polygon line styles (else the quick grammars' and the scenes').
    bool cpfgTubes = false;
    bool cylinderTwist = false;
    int cylinderSides = 8;
    std::vector<int> contourIds;
    std::vector<glm::vec3> contourRings;
    std::vector<glm::vec4> palette;       // kPaletteSize linear RGBA colours
    // Per symbol id, for `~` and that symbol: the surface's scale and leaf shape (kLeaf*), how it draws (kSurface*)
    // and where it leaves the turtle (per unit of its first scale and the turtle's, in its heading, left and up).
    std::vector<float> surfaceScale;
    std::vector<uint32_t> surfaceShape;
    std::vector<glm::vec3> surfaceEnd;
    std::vector<uint32_t> surfaceDrawn;

    glm::vec4 color(float index) const;
};

// `grammar` supplies the view settings; `alphabet` the symbols (the species' shared alphabet).
TurtleSettings turtleSettings(const ir::Grammar& grammar, const ir::Alphabet& alphabet);

// The stem organs' shape code of a line style (kLine*, compute/shared/organ_layout.h).
uint32_t lineStyleCode(ir::LineStyle style);

// simeco's palette for models without a colour map: 0 black, then bark, greens, flower and fruit colours,
// then a ramp of hues.
std::vector<glm::vec4> defaultPalette();

// A surface's shape from its name or file name: a blossom where it says `blossom` or `flower` and not `leaf` (a
// flower head for Lantana, a rose's for Rosa, else five petals), else a leaf blade: trifoliate, cordate,
// lanceolate, compound, serrate, else ovate.
uint32_t surfaceShapeOf(const std::string& name);

} // namespace simeco::turtle
