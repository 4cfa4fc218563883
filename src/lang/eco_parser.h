// SimEco `.eco` scripts: the ecosystem scene, and each plant's Grow block as a grammar.
//
// Syntax: appendix B of Shih, "An Adaptive L-System" (2004), as its own scripts and those of the
// L-grammar generator actually use it. Keywords are case-insensitive; every malformed input throws
// ir::InputError at the offending line and column.
#pragma once

#include <string>

#include "ir/eco_scene.h"
#include "ir/grammar.h"
#include "lang/eco_geometry.h"

namespace simeco::lang {

ir::EcoScene parseEcoFile(const std::string& path);
// `file` names the text in error messages and in the scene.
ir::EcoScene parseEcoText(const std::string& text, const std::string& file);

// The Grow block of one plant as a grammar (each plant is its own grammar), its organs drawn as `drawing` says
// (lang/eco_geometry.h). Throws InputError when the scene has no plant `plantIndex`.
ir::Grammar compileEcoPlant(const ir::EcoScene& scene, size_t plantIndex, EcoDrawing drawing = EcoDrawing::Final,
                            const EcoAssets* assets = nullptr);

// Derivation steps of a plant whose script sets no `DerivationLength` (see eco_compile.cpp).
inline constexpr int kDefaultEcoDerivationLength = 10;

} // namespace simeco::lang
