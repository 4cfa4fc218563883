// What a SimEco plant's organs look like to the turtle: a homomorphism that draws each segment by its organ and
// stage (lang/eco_compile lowers the Grow block; this adds the drawing), at the sizes its particle has grown to
// (the growth simulation) or at those its stage reaches at the end of its GrowTime (a derivation alone).
#pragma once

#include <cstdint>
#include <map>
#include <string>

#include "ir/eco_scene.h"
#include "ir/grammar.h"
#include "lang/eco_assets.h"

namespace simeco::lang {

// Adds to `g` (the plant's compiled grammar) one homomorphism production per organ stage the script
// describes and one per organ for every other stage, a colour palette with the stages' colours (tinted by
// their materials' diffuse factors), and the leaf surface:
//   stem S, root R:  ;(colour) !(width) G(length)   length = GrowRate x GrowTime, width = BroadenRate x GrowTime
//   leaf L:          ;(colour) ~ leaf(size)          size = the leaf model's, scaled by 1 + the growth of
//                                                    stages 0 to its own (leaves pass through their stages
//                                                    in order)
//   flower F:        ;(colour) ~ blossom(diameter)   the plant's blossom, diameter = GrowRate x GrowTime
//   fruit T:         ;(colour) @ O(diameter)         a sphere
//   apex A:          nothing
// A stage's unset properties come from the organ's Default stage, then from simeco's defaults below. These are
// the sizes the stage's growth reaches at the end of its GrowTime (EcoDrawing::Final).
// Grown: the sizes are kGrownValue codes (compute/shared/growth_layout.h) that the growth simulation replaces
// with each module's particle's; a stem segment also tilts by its particle's pitch and roll, bends by its
// geotropism and weight, turns toward the light by its phototropism, and is shed with the rest of its branch once
// its LifeTime has passed or it has stood its ShadeTime in deep shade; a leaf's colour follows its age (young,
// mature, old):
//   stem S, root R:  ;(colour) !(width) [tropism(bend)] [alive(a)] tilt(pitch, roll)
//                    [phototropism(e, light x, y, z)] G(length)
// `assets`: the models and textures the renderer holds (lang/eco_assets.h): a leaf, flower or fruit of a stage whose
// Model is among them is drawn with it, others with the built-in blade, blossom or sphere; a stage whose Texture is
// among them gets a colour of its own that tints the texture (ViewSettings::paletteTextures).
enum class EcoDrawing { Final, Grown };
void addEcoOrganGeometry(const ir::EcoPlant& plant, ir::Grammar& g, EcoDrawing drawing = EcoDrawing::Final,
                         const EcoAssets* assets = nullptr);

inline constexpr float kEcoDefaultGrowTime = 1.0f;
inline constexpr float kEcoDefaultStemLength = 1.0f;
inline constexpr float kEcoDefaultStemWidth = 0.1f;
inline constexpr float kEcoLeafModelSize = 1.0f;
inline constexpr float kEcoDefaultFlowerSize = 0.3f;

} // namespace simeco::lang
