#include "app/render_options.h"

#include <cstdio>

#include <fmt/format.h>

#include "app/error_report.h"

namespace simeco::app {

draw::RenderSettings renderSettings(const std::string& size, const std::string& camera, const std::string& style,
                                    const std::string& shadows) {
    draw::RenderSettings s;
    unsigned w = 0, h = 0;
    char x = 0;
    if (std::sscanf(size.c_str(), "%u%c%u", &w, &x, &h) != 3 || x != 'x' || w == 0 || h == 0 || w > 16384 || h > 16384)
        throw CommandLineError(fmt::format("--size '{}': expected WIDTHxHEIGHT, each 1 to 16384", size));
    s.width = w;
    s.height = h;
    if (!camera.empty()) {
        draw::Camera c;
        int read = std::sscanf(camera.c_str(), "%f,%f,%f", &c.azimuthDegrees, &c.elevationDegrees, &c.distance);
        if (read < 2 || c.elevationDegrees <= -90 || c.elevationDegrees >= 90)
            throw CommandLineError(fmt::format(
                "--camera '{}': expected azimuth,elevation[,distance] in degrees, elevation within (-90, 90)", camera));
        s.camera = c;
    }
    s.style = style == "toon" ? draw::Style::Toon : draw::Style::Lit;
    s.shadows = shadows == "none" ? draw::Shadows::None : draw::Shadows::Volume;
    return s;
}

void applySceneLight(const ir::EcoLight& light, draw::RenderSettings& settings) {
    if (light.sunDirection)
        settings.sunDirection = {(*light.sunDirection)[0], (*light.sunDirection)[1], (*light.sunDirection)[2]};
    if (light.sunIntensity) settings.sunColor *= *light.sunIntensity;
    if (light.skyLight) settings.skyColor *= *light.skyLight;
    if (light.groundSize) settings.groundSize = *light.groundSize;
}

} // namespace simeco::app
