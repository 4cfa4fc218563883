// How a scene's climate and soil modulate growth (the thesis' light, water and nutrients): a factor on every
// organ's GrowRate and BroadenRate from the EcoSystem block's DayLight, RainRate and SoilPH, each through a
// response curve that gives 1 at the thesis' example values (12 hours, 0.9, 7.0).
#pragma once

#include "ir/eco_scene.h"

namespace simeco::grow {

// Day length: the light of a day, saturating: D / (D + 6) scaled to 1 at 12 hours (0.75 at 6, 1.2 at 24, 0 at 0).
float dayLightResponse(float hours);
// Water: R / (R + 0.3) scaled to 1 at 0.9 (0.67 at 0.3, 1.16 at 2, 0 without rain).
float rainResponse(float rainRate);
// Soil: 1 for a pH from 6 to 7.5, falling off outside as exp(-(distance / 1.5)^2) (0.37 at 4.5 and at 9).
float soilResponse(float pH);

// Their product.
float climateGrowthFactor(float dayLightHours, float rainRate, float soilPH);
// Their product for the scene's values (a range's midpoint where the script gives one).
float environmentGrowthFactor(const ir::EcoScene& scene);

} // namespace simeco::grow
