#include "app/render_options.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include "app/error_report.h"
#include "lang/color_map.h"

namespace simeco::app {

void addPictureOptions(CLI::App& cmd, PictureOptions& options, const std::string& framed) {
    cmd.add_option("--size", options.size, fmt::format("image size WIDTHxHEIGHT (default {})", options.size));
    cmd.add_option("--antialias", options.antialias,
                   "samples along each side of a pixel: the frame drawn N times larger and each pixel averaged "
                   "(default 1: none)")
        ->check(CLI::Range(1u, 4u));
    cmd.add_option("--msaa", options.msaa,
                   "samples a pixel, multisampled: edges, thin stems and shadows drawn by the share of the pixel "
                   "they cover (1: none; 2, 4, 8 or 16 as the device has them; default 4 where it has them, else "
                   "1, and in the viewer 1 on a CPU device, where each sample costs as much as a pixel)")
        ->check(CLI::IsMember({1u, 2u, 4u, 8u, 16u}));
    cmd.add_option("--camera", options.camera,
                   fmt::format("azimuth,elevation[,distance] in degrees (default: framed on the {})", framed));
    cmd.add_option("--projection", options.projection,
                   "perspective or parallel (default: the view file's `projection:`, else perspective)")
        ->check(CLI::IsMember({"perspective", "parallel"}));
    cmd.add_option("--style", options.style,
                   "lit, toon (colour bands), outline (bands and ink outlines) or paper-cut (flat colour, cut where "
                   "the sun does not reach and along every edge) (default: the view file's, else lit)")
        ->check(CLI::IsMember({"lit", "toon", "outline", "paper-cut"}));
    cmd.add_option("--shadows", options.shadows,
                   "volume (the sun's shadow volumes) or none (default: the view file's, else volume)")
        ->check(CLI::IsMember({"volume", "none"}));
    cmd.add_option("--ground", options.ground, "on or off: the ground plane (default: the view file's, else on)")
        ->check(CLI::IsMember({"on", "off"}));
    cmd.add_option("--background", options.background,
                   "sky, paper, colormap (the colour map's entry 0, as cpfg) or #rrggbb (default: the view file's, "
                   "else sky)")
        ->check([](const std::string& name) {
            return lang::backgroundNamed(name) ? std::string() : "expected sky, paper, colormap or #rrggbb";
        });
}

namespace {

// The background's linear colour; `colormap` takes entry 0 of the model's colour map.
glm::vec3 backgroundColor(const ir::Background& background, const ir::ViewSettings& view, glm::vec3 sky) {
    switch (background.kind) {
    case ir::Background::Kind::Sky: return sky;
    case ir::Background::Kind::Paper: return draw::kPaperColor;
    case ir::Background::Kind::Color: return {background.color[0], background.color[1], background.color[2]};
    case ir::Background::Kind::Colormap:
        if (view.palette.empty())
            throw CommandLineError("background colormap: the model has no colour map (.map) to take entry 0 from");
        return {view.palette[0][0], view.palette[0][1], view.palette[0][2]};
    }
    return sky;
}

// A view file's viewpoint as the camera's angles, looking from it towards the reference point.
draw::Camera viewCamera(const ir::PictureLook& look) {
    const std::array<float, 3> from = look.viewpoint.value_or(std::array<float, 3>{0, 0, 1});
    const std::array<float, 3> to = look.viewReferencePoint.value_or(std::array<float, 3>{});
    const glm::vec3 d(from[0] - to[0], from[1] - to[1], from[2] - to[2]);
    draw::Camera c;
    const float length = glm::length(d);
    if (!(length > 0.0f)) return c; // the same point twice: no direction, the default view
    // Straight above or below has no azimuth; the camera stays just short of the pole.
    c.elevationDegrees = std::clamp(glm::degrees(std::asin(d.y / length)), -89.0f, 89.0f);
    c.azimuthDegrees = glm::degrees(std::atan2(d.x, d.z));
    return c;
}

} // namespace

std::pair<std::uint32_t, std::uint32_t> imageSize(const std::string& size) {
    unsigned w = 0, h = 0;
    char x = 0;
    if (std::sscanf(size.c_str(), "%u%c%u", &w, &x, &h) != 3 || x != 'x' || w == 0 || h == 0 || w > 16384 ||
        h > 16384)
        throw CommandLineError(fmt::format("--size '{}': expected WIDTHxHEIGHT, each 1 to 16384", size));
    return {w, h};
}

draw::RenderSettings renderSettings(const PictureOptions& options, const ir::ViewSettings& view) {
    draw::RenderSettings s;
    std::tie(s.width, s.height) = imageSize(options.size);
    s.antialias = options.antialias;
    s.samples = options.msaa;
    if (!options.camera.empty()) {
        draw::Camera c;
        int read = std::sscanf(options.camera.c_str(), "%f,%f,%f", &c.azimuthDegrees, &c.elevationDegrees,
                               &c.distance);
        if (read < 2 || c.elevationDegrees <= -90 || c.elevationDegrees >= 90)
            throw CommandLineError(fmt::format(
                "--camera '{}': expected azimuth,elevation[,distance] in degrees, elevation within (-90, 90)",
                options.camera));
        s.camera = c;
    }
    const ir::PictureLook& look = view.look;
    if (!s.camera && (look.viewpoint || look.viewReferencePoint)) s.camera = viewCamera(look);
    const bool parallel =
        !options.projection.empty() ? options.projection == "parallel" : look.parallel.value_or(false);
    if (parallel) {
        if (!s.camera) s.camera = draw::Camera{};
        s.camera->parallel = true;
    }
    if (!options.style.empty()) s.style = *ir::pictureStyleNamed(options.style);
    else if (look.style) s.style = *look.style;
    if (!options.shadows.empty())
        s.shadows = options.shadows == "none" ? draw::Shadows::None : draw::Shadows::Volume;
    else if (look.shadows)
        s.shadows = *look.shadows ? draw::Shadows::Volume : draw::Shadows::None;
    if (!options.ground.empty()) s.ground = options.ground == "on";
    else if (look.ground) s.ground = *look.ground;
    if (!options.background.empty())
        s.background = backgroundColor(*lang::backgroundNamed(options.background), view, s.background);
    else if (look.background) s.background = backgroundColor(*look.background, view, s.background);
    if (look.sunDirection) s.sunDirection = {(*look.sunDirection)[0], (*look.sunDirection)[1], (*look.sunDirection)[2]};
    return s;
}

void applySceneLight(const ir::EcoLight& light, draw::RenderSettings& settings) {
    if (light.sunDirection)
        settings.sunDirection = {(*light.sunDirection)[0], (*light.sunDirection)[1], (*light.sunDirection)[2]};
    if (light.sunIntensity) settings.sunColor *= *light.sunIntensity;
    if (light.skyLight) settings.skyColor *= *light.skyLight;
    if (light.groundSize) settings.groundSize = *light.groundSize;
}

draw::RenderSettings grownFieldSettings(const PictureOptions& options, const grow::GrowingSpecies& species) {
    draw::RenderSettings settings = renderSettings(options, species.species.front().view);
    if (species.scene) applySceneLight(species.scene->light, settings);
    return settings;
}

} // namespace simeco::app
