#include "grow/environment.h"

#include <algorithm>
#include <cmath>

namespace simeco::grow {

namespace {

// Saturating: x / (x + half), scaled to 1 at `reference`; nothing below zero.
float saturating(float x, float half, float reference) {
    x = std::max(x, 0.0f);
    return x / (x + half) * (reference + half) / reference;
}

} // namespace

float dayLightResponse(float hours) {
    return saturating(std::min(hours, 24.0f), 6.0f, 12.0f);
}

float rainResponse(float rainRate) {
    return saturating(rainRate, 0.3f, 0.9f);
}

float soilResponse(float pH) {
    const float distance = pH < 6.0f ? 6.0f - pH : pH > 7.5f ? pH - 7.5f : 0.0f;
    return std::exp(-(distance / 1.5f) * (distance / 1.5f));
}

float climateGrowthFactor(float dayLightHours, float rainRate, float soilPH) {
    return dayLightResponse(dayLightHours) * rainResponse(rainRate) * soilResponse(soilPH);
}

float environmentGrowthFactor(const ir::EcoScene& scene) {
    return climateGrowthFactor(scene.dayLight.typical(), scene.rainRate.typical(), scene.soilPH.typical());
}

} // namespace simeco::grow
