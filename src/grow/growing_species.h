// The species of a field that grows: an `.eco` scene's plants drawn at the sizes their particles grow to
// (lang::EcoDrawing::Grown), with the scene they come from, or the grammar of a cpfg `.l` or quick `.lsys` file.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ir/eco_scene.h"
#include "ir/grammar.h"
#include "ir/draw_assets.h"

namespace simeco::grow {

struct GrowingSpecies {
    std::unique_ptr<const ir::EcoScene> scene;  // null for a grammar file; ecoPlants point into it
    std::vector<ir::Grammar> species;           // one alphabet (ir::unifySpecies)
    std::vector<const ir::EcoPlant*> ecoPlants; // per species: its plant in the scene, or null
    // The models and textures its stages name and simeco reads (lang/eco_assets.h).
    ir::DrawAssets assets;
    // Whether species s is a SimEco plant whose organs grow as particles (not a grammar file's).
    bool growsOrgans(size_t s) const { return ecoPlants[s] && ecoPlants[s]->grammar.empty(); }

    // The scene's gravity as a multiple of Earth's (9.81 m/s^2); 1 for a grammar file.
    float relativeGravity() const;
};

// A parsed scene's plants: SimEco plants compiled, plants that name a Grammar file loaded from it (their
// warnings go to `warnings` when given).
GrowingSpecies growingSpecies(ir::EcoScene scene, std::vector<ir::EcoWarning>* warnings = nullptr);
// Reads any input as lang::loadSpecies does; a scene's warnings go to `warnings` when given.
GrowingSpecies loadGrowingSpecies(const std::string& path, std::vector<ir::EcoWarning>* warnings = nullptr);

} // namespace simeco::grow
