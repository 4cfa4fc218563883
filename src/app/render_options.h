// The image options the commands that render share (`render`, `run`): size, camera, style and shadows, as typed.
#pragma once

#include <string>

#include "draw/render_settings.h"
#include "ir/eco_field.h"

namespace simeco::app {

// Throws CommandLineError for a size other than WIDTHxHEIGHT (each 1 to 16384) or a camera other than
// azimuth,elevation[,distance] with the elevation within (-90, 90); an empty camera frames the plants.
draw::RenderSettings renderSettings(const std::string& size, const std::string& camera, const std::string& style,
                                    const std::string& shadows);

// A scene's sun, sky and ground (ir::EcoLight) in the settings: what it leaves unset stays as it is.
void applySceneLight(const ir::EcoLight& light, draw::RenderSettings& settings);

} // namespace simeco::app
