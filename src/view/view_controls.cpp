#include "view/view_controls.h"

#include <charconv>
#include <cmath>
#include <optional>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "ir/picture_look.h"

namespace simeco::view {
namespace {

float number(std::string_view name, std::string_view text, float lowest, float highest) {
    float value = 0.0f;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value))
        throw SettingError(fmt::format("--set {}: '{}' is not a number", name, text));
    if (value < lowest || value > highest)
        throw SettingError(fmt::format("--set {}: {} is outside [{}, {}]", name, text, lowest, highest));
    return value;
}

std::uint32_t count(std::string_view name, std::string_view text, std::uint32_t highest) {
    std::uint32_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size())
        throw SettingError(fmt::format("--set {}: '{}' is not a whole number", name, text));
    if (value > highest) throw SettingError(fmt::format("--set {}: {} is over {}", name, text, highest));
    return value;
}

bool onOff(std::string_view name, std::string_view text) {
    if (text == "on" || text == "true" || text == "1") return true;
    if (text == "off" || text == "false" || text == "0") return false;
    throw SettingError(fmt::format("--set {}: '{}' is neither on nor off", name, text));
}

// species.K.property: the species by number or name.
SpeciesControls& speciesOf(ViewControls& controls, std::string_view name, std::string_view key) {
    std::uint32_t index = 0;
    const auto [end, error] = std::from_chars(key.data(), key.data() + key.size(), index);
    if (error == std::errc() && end == key.data() + key.size()) {
        if (index >= controls.species.size())
            throw SettingError(fmt::format("--set {}: the field has {} species, numbered from 0", name,
                                           controls.species.size()));
        return controls.species[index];
    }
    for (SpeciesControls& s : controls.species)
        if (s.name == key) return s;
    std::string names;
    for (const SpeciesControls& s : controls.species) names += fmt::format("{}'{}'", names.empty() ? "" : ", ", s.name);
    throw SettingError(fmt::format("--set {}: no species '{}' in the field (it has {})", name, key, names));
}

} // namespace

std::string settingNames() {
    return "sun.azimuth, sun.elevation, sun.intensity, sky, daylight, rain, soil_ph, gravity, time_scale, paused, "
           "seed, plants, density, shadows, style, render_scale, msaa, species.K.grow_rate, species.K.geotropism, "
           "species.K.strength";
}

void applySetting(ViewControls& c, std::string_view assignment) {
    const size_t equals = assignment.find('=');
    if (equals == std::string_view::npos)
        throw SettingError(fmt::format("--set '{}': write name=value", assignment));
    const std::string_view name = assignment.substr(0, equals);
    const std::string_view value = assignment.substr(equals + 1);
    if (name == "sun.azimuth") c.sunAzimuth = number(name, value, -360.0f, 360.0f);
    else if (name == "sun.elevation") c.sunElevation = number(name, value, 1.0f, 90.0f);
    else if (name == "sun.intensity") c.sunIntensity = number(name, value, 0.0f, 10.0f);
    else if (name == "sky") c.skyLight = number(name, value, 0.0f, 10.0f);
    else if (name == "daylight") c.dayLight = number(name, value, 0.0f, 24.0f);
    else if (name == "rain") c.rainRate = number(name, value, 0.0f, 10.0f);
    else if (name == "soil_ph") c.soilPH = number(name, value, 0.0f, 14.0f);
    else if (name == "gravity") c.gravity = number(name, value, 0.0f, 100.0f);
    else if (name == "time_scale") c.timeScale = number(name, value, 0.01f, 1000.0f);
    else if (name == "paused") c.paused = onOff(name, value);
    else if (name == "seed") c.seed = count(name, value, UINT32_MAX);
    else if (name == "plants") c.plants = count(name, value, 1000000);
    else if (name == "density") c.density = number(name, value, 0.01f, 100.0f);
    else if (name == "shadows") c.shadows = onOff(name, value);
    else if (name == "render_scale") c.renderScale = number(name, value, 0.25f, 2.0f);
    else if (name == "msaa") c.samples = count(name, value, 64); // the device's counts are checked as it draws
    else if (name == "style") {
        const std::optional<draw::Style> style = ir::pictureStyleNamed(std::string(value));
        if (!style)
            throw SettingError(fmt::format("--set style: '{}' is none of lit, toon, outline, paper-cut", value));
        c.style = *style;
    } else if (name.starts_with("species.")) {
        const std::string_view rest = name.substr(8);
        const size_t dot = rest.rfind('.');
        if (dot == std::string_view::npos) throw SettingError(fmt::format("--set {}: write species.K.property", name));
        SpeciesControls& s = speciesOf(c, name, rest.substr(0, dot));
        const std::string_view property = rest.substr(dot + 1);
        if (property == "grow_rate") s.factors.growRate = number(name, value, 0.0f, 10.0f);
        else if (property == "geotropism") s.factors.geotropism = number(name, value, -10.0f, 10.0f);
        else if (property == "strength") s.factors.strength = number(name, value, 0.0f, 10.0f);
        else throw SettingError(fmt::format("--set {}: a species has grow_rate, geotropism and strength", name));
    } else {
        throw SettingError(fmt::format("--set: no setting '{}' (there are {})", name, settingNames()));
    }
}

glm::vec3 sunDirection(float azimuthDegrees, float elevationDegrees) {
    const float a = glm::radians(azimuthDegrees), e = glm::radians(elevationDegrees);
    return {std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
}

void sunAngles(glm::vec3 towardsSun, float& azimuthDegrees, float& elevationDegrees) {
    const glm::vec3 d = glm::normalize(towardsSun);
    azimuthDegrees = glm::degrees(std::atan2(d.x, d.z));
    elevationDegrees = glm::degrees(std::asin(std::clamp(d.y, -1.0f, 1.0f)));
}

ViewControls controlsFor(const field::LiveEnvironment& environment, const draw::RenderSettings& settings,
                         const std::vector<std::string>& speciesNames) {
    ViewControls c;
    const ir::EcoLight& light = environment.light;
    const glm::vec3 sun =
        light.sunDirection ? glm::vec3((*light.sunDirection)[0], (*light.sunDirection)[1], (*light.sunDirection)[2])
                           : settings.sunDirection;
    sunAngles(sun, c.sunAzimuth, c.sunElevation);
    c.sunIntensity = light.sunIntensity.value_or(1.0f);
    c.skyLight = light.skyLight.value_or(1.0f);
    c.dayLight = environment.dayLight;
    c.rainRate = environment.rainRate;
    c.soilPH = environment.soilPH;
    c.gravity = environment.gravity;
    c.shadows = settings.shadows == draw::Shadows::Volume;
    c.style = settings.style;
    c.renderScale = float(settings.antialias);
    c.samples = settings.samples;
    for (size_t s = 0; s < environment.species.size(); ++s)
        c.species.push_back({s < speciesNames.size() ? speciesNames[s] : fmt::format("{}", s),
                             environment.species[s]});
    return c;
}

field::LiveEnvironment environmentOf(const ViewControls& c, const field::LiveEnvironment& base) {
    field::LiveEnvironment e = base;
    const glm::vec3 sun = sunDirection(c.sunAzimuth, c.sunElevation);
    e.light.sunDirection = std::array<float, 3>{sun.x, sun.y, sun.z};
    e.light.sunIntensity = c.sunIntensity;
    e.light.skyLight = c.skyLight;
    e.dayLight = c.dayLight;
    e.rainRate = c.rainRate;
    e.soilPH = c.soilPH;
    e.gravity = c.gravity;
    for (size_t s = 0; s < e.species.size() && s < c.species.size(); ++s) e.species[s] = c.species[s].factors;
    return e;
}

} // namespace simeco::view
