// The inferred plant as a SimEco script (`simeco infer -o plant.eco`): a stage per internode whose GrowRate x
// GrowTime is its length and BroadenRate x GrowTime its width, and the initial-state grammar, a rule per internode
// in the thesis' shape with the growth point made an apex (an Apex organ, which draws nothing):
//     A(n) -> S(n) [rotr(..) rotu(..) A(branch)] ... rotr(..) rotu(..) A(main);
// A stem S(n) keeps its stage, so the derivation alone draws every internode at its length (the thesis writes
// S(n) -> S(0) [...] S(main), which keeps a stem's length only where its particle carries it on) and the growth
// simulation grows each from its birth. Leaves, flowers and fruits sit at their points in brackets. The skeleton
// has regrown after as many derivation steps as it has levels; with prediction rules the DerivationLength is six
// steps more, in which its tips grow on.
#pragma once

#include <string>

#include "skeleton/infer.h"
#include "skeleton/plant_description.h"
#include "skeleton/prediction.h"

namespace simeco::skeleton {

struct EcoScriptOptions {
    std::string name = "Inferred";   // the plant's name
    std::string source;              // what the skeleton came from, for the script's opening comment
    glm::dvec3 position{0.0};        // where the plant stands (its skeleton's base)
    std::string dressing;            // what a description added to the skeleton, for the comment
    const Prediction* prediction = nullptr;          // rules to grow on by; none: the initial state alone
    const PlantDescription* description = nullptr;   // its leaf shape names the plant's leaf
};

// `growth` must be a SimEco regrowth (Dialect::SimEco).
std::string ecoScript(const Plant& plant, const Regrowth& growth, const EcoScriptOptions& options);

} // namespace simeco::skeleton
