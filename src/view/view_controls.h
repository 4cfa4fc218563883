// The viewer's panel as values: the environment a field grows in (sun, climate, soil, gravity, each species'
// factors on its stage properties), how fast it grows, how it is drawn. The panel's widgets and `--set
// name=value` on the command line change the same values, so a test or a demo sets what a user would slide.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "draw/render_settings.h"
#include "field/simulation.h"

namespace simeco::view {

struct SpeciesControls {
    std::string name;
    field::LiveEnvironment::SpeciesFactors factors;
};

struct ViewControls {
    float sunAzimuth = 0.0f;   // degrees around +y, from +z towards +x (as the camera's azimuth)
    float sunElevation = 45.0f; // degrees above the horizon
    float sunIntensity = 1.0f;
    float skyLight = 1.0f;
    float dayLight = 12.0f; // hours
    float rainRate = 0.9f;
    float soilPH = 7.0f;
    float gravity = 9.81f;   // m/s²
    float timeScale = 1.0f; // simulated seconds a second of the viewer's clock while running (view/growth_clock.h)
    bool paused = false;
    // Take effect at a reset: the field's seed, its plants (0: as the scene places them) and the factor on its
    // populations' plants.
    std::uint32_t seed = 0;
    std::uint32_t plants = 0;
    float density = 1.0f;
    bool shadows = true;
    draw::Style style = draw::Style::Lit;
    // The frame's size relative to the window's: below 1 a faster, coarser picture; 2 draws four samples a pixel,
    // averaged as the frame is scaled into the window (supersampling).
    float renderScale = 1.0f;
    std::uint32_t samples = 1; // a pixel, multisampled (draw::RenderSettings::samples)
    std::vector<SpeciesControls> species;
};

// A setting that does not name a control or whose value does not fit it.
class SettingError : public std::invalid_argument {
public:
    using std::invalid_argument::invalid_argument;
};

// Applies `name=value`: sun.azimuth, sun.elevation, sun.intensity, sky, daylight, rain, soil_ph, gravity,
// time_scale, paused, seed, plants, density, shadows (on/off), style (lit/toon/outline/paper-cut), render_scale,
// msaa (samples a pixel), and per species species.K.grow_rate, species.K.geotropism, species.K.strength with K a
// species' number (from 0) or name.
void applySetting(ViewControls& controls, std::string_view assignment);
// Every name applySetting takes, for the help and the error messages.
std::string settingNames();

// The controls of a field growing in `environment`, drawn with `settings`.
ViewControls controlsFor(const field::LiveEnvironment& environment, const draw::RenderSettings& settings,
                         const std::vector<std::string>& speciesNames);
// The environment the controls set.
field::LiveEnvironment environmentOf(const ViewControls& controls, const field::LiveEnvironment& base);
// Towards the sun, a unit vector, from its azimuth and elevation; and back.
glm::vec3 sunDirection(float azimuthDegrees, float elevationDegrees);
void sunAngles(glm::vec3 towardsSun, float& azimuthDegrees, float& elevationDegrees);

} // namespace simeco::view
