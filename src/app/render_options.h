// The image options the commands that render share (`render`, `run`): size, camera, projection, style, shadows,
// ground and background, as typed.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include <CLI/CLI.hpp>

#include "draw/render_settings.h"
#include "ir/eco_field.h"
#include "grow/growing_species.h"
#include "ir/grammar.h"

namespace simeco::app {

// Empty projection, style, shadows, ground and background take the model's view file (cpfg's `projection:`, and
// simeco's `render style:`, `shadows:`, `ground:`, `background:` lines), else the defaults.
struct PictureOptions {
    std::string size = "960x720";
    std::uint32_t antialias = 1;
    std::uint32_t msaa = 0; // 0: the device's default (draw::defaultSamples)
    std::string camera;
    std::string projection;
    std::string style;
    std::string shadows;
    std::string ground;
    std::string background;
};

// --size, --antialias, --msaa, --camera, --projection, --style, --shadows, --ground and --background; `framed` says
// what the default camera frames.
void addPictureOptions(CLI::App& cmd, PictureOptions& options, const std::string& framed);

// WIDTHxHEIGHT; throws CommandLineError for another form or a side outside 1 to 16384.
std::pair<std::uint32_t, std::uint32_t> imageSize(const std::string& size);

// Throws CommandLineError for a size other than WIDTHxHEIGHT (each 1 to 16384), a camera other than
// azimuth,elevation[,distance] with the elevation within (-90, 90), or a background that names the colour map of
// a model without one. `view` is the first species' (an empty camera frames the plants).
draw::RenderSettings renderSettings(const PictureOptions& options, const ir::ViewSettings& view);

// A scene's sun, sky and ground (ir::EcoLight) in the settings: what it leaves unset stays as it is.
void applySceneLight(const ir::EcoLight& light, draw::RenderSettings& settings);

// The picture of a growing field: the options over its first species' view, then its scene's light.
draw::RenderSettings grownFieldSettings(const PictureOptions& options, const grow::GrowingSpecies& species);

} // namespace simeco::app
