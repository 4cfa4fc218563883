// The viewer's controls and camera without a window: `--set name=value` and the panel change the same values, and
// map onto the environment a field grows in; the camera orbits, pans and zooms about its target.
#include <array>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "draw/camera.h"
#include "draw/renderer.h"
#include "view/orbit_camera.h"
#include "view/view_controls.h"

namespace simeco::view {
namespace {

ViewControls twoSpecies() {
    field::LiveEnvironment environment;
    environment.species.resize(2);
    environment.light.sunDirection = std::array<float, 3>{0.0f, 1.0f, 1.0f};
    return controlsFor(environment, draw::RenderSettings{}, {"Oxalis", "Rosa rugosa"});
}

TEST(ViewControls, SettingsChangeTheControlsTheyName) {
    ViewControls c = twoSpecies();
    EXPECT_NEAR(c.sunAzimuth, 0.0f, 1e-4f);
    EXPECT_NEAR(c.sunElevation, 45.0f, 1e-4f);
    applySetting(c, "sun.azimuth=90");
    applySetting(c, "sun.elevation=30");
    applySetting(c, "daylight=6.5");
    applySetting(c, "paused=on");
    applySetting(c, "shadows=off");
    applySetting(c, "style=paper-cut");
    applySetting(c, "time_scale=2.5");
    applySetting(c, "density=0.5");
    applySetting(c, "render_scale=0.5");
    applySetting(c, "species.1.grow_rate=0.5");
    applySetting(c, "species.Oxalis.geotropism=-2");
    EXPECT_EQ(c.sunAzimuth, 90.0f);
    EXPECT_EQ(c.sunElevation, 30.0f);
    EXPECT_EQ(c.dayLight, 6.5f);
    EXPECT_TRUE(c.paused);
    EXPECT_FALSE(c.shadows);
    EXPECT_EQ(c.style, draw::Style::PaperCut);
    EXPECT_EQ(c.timeScale, 2.5f);
    EXPECT_EQ(c.density, 0.5f);
    EXPECT_EQ(c.renderScale, 0.5f);
    EXPECT_EQ(c.species[1].factors.growRate, 0.5f);
    EXPECT_EQ(c.species[0].factors.geotropism, -2.0f);
    EXPECT_EQ(c.species[0].factors.growRate, 1.0f);
}

TEST(ViewControls, BadSettingsSayWhatIsWrong) {
    ViewControls c = twoSpecies();
    const auto message = [&](const char* setting) {
        try {
            applySetting(c, setting);
        } catch (const SettingError& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_NE(message("sun.colour=red").find("no setting 'sun.colour'"), std::string::npos);
    EXPECT_NE(message("gravity").find("write name=value"), std::string::npos);
    EXPECT_NE(message("gravity=heavy").find("'heavy' is not a number"), std::string::npos);
    EXPECT_NE(message("sun.elevation=95").find("outside [1, 90]"), std::string::npos);
    EXPECT_NE(message("shadows=maybe").find("neither on nor off"), std::string::npos);
    EXPECT_NE(message("style=watercolour").find("none of lit"), std::string::npos);
    EXPECT_NE(message("species.2.grow_rate=1").find("2 species"), std::string::npos);
    EXPECT_NE(message("species.Lantana.grow_rate=1").find("'Oxalis', 'Rosa rugosa'"), std::string::npos);
    EXPECT_NE(message("species.0.height=1").find("grow_rate, geotropism and strength"), std::string::npos);
    EXPECT_EQ(c.sunElevation, 45.0f); // nothing refused was applied
}

TEST(ViewControls, TheControlsSetTheFieldsEnvironment) {
    ViewControls c = twoSpecies();
    applySetting(c, "sun.azimuth=-90");
    applySetting(c, "sun.elevation=30");
    applySetting(c, "sun.intensity=2");
    applySetting(c, "rain=0.3");
    applySetting(c, "soil_ph=5");
    applySetting(c, "gravity=3");
    applySetting(c, "species.1.strength=2");
    const field::LiveEnvironment e = environmentOf(c, field::LiveEnvironment{{}, 12, 0.9f, 7, 9.81f, {{}, {}}});
    ASSERT_TRUE(e.light.sunDirection);
    const std::array<float, 3> sun = *e.light.sunDirection;
    EXPECT_NEAR(sun[0], -std::cos(0.5236f), 1e-4f); // from -x, 30 degrees up
    EXPECT_NEAR(sun[1], 0.5f, 1e-4f);
    EXPECT_NEAR(sun[2], 0.0f, 1e-4f);
    EXPECT_EQ(e.light.sunIntensity, 2.0f);
    EXPECT_EQ(e.rainRate, 0.3f);
    EXPECT_EQ(e.soilPH, 5.0f);
    EXPECT_EQ(e.gravity, 3.0f);
    EXPECT_EQ(e.species[1].strength, 2.0f);
    // And back: the angles of the direction the controls set.
    float azimuth = 0, elevation = 0;
    sunAngles({sun[0], sun[1], sun[2]}, azimuth, elevation);
    EXPECT_NEAR(azimuth, -90.0f, 1e-3f);
    EXPECT_NEAR(elevation, 30.0f, 1e-3f);
}

TEST(OrbitCamera, OrbitsPansAndZoomsAboutItsTarget) {
    const draw::Bounds bounds{{-1, 0, -1}, {1, 2, 1}};
    const draw::Camera start;
    const draw::CameraView framed = draw::frameCamera(bounds, draw::RenderSettings{});
    OrbitCamera orbit(start, framed);
    ASSERT_TRUE(orbit.camera().target);
    const float distance = orbit.camera().distance;
    EXPECT_NEAR(distance, glm::length(framed.position - framed.target), 1e-5f);
    // The first view is the framed one.
    const draw::CameraView same = draw::cameraView(orbit.camera(), bounds, 960.0f / 720.0f);
    EXPECT_LT(glm::length(same.position - framed.position), 1e-4f * distance);

    orbit.orbit(30.0f, 3000.0f); // right, and far up: held short of the pole
    EXPECT_NEAR(orbit.camera().azimuthDegrees, start.azimuthDegrees - 30.0f * 0.33f, 1e-3f);
    EXPECT_EQ(orbit.camera().elevationDegrees, 89.0f);
    orbit.zoom(2.0f);
    EXPECT_NEAR(orbit.camera().distance, distance * 0.81f, 1e-4f * distance);
    // A pan moves the target across the view, not toward it.
    OrbitCamera panned(start, framed);
    panned.pan(100.0f, 0.0f, 720.0f);
    const glm::vec3 moved = *panned.camera().target - framed.target;
    EXPECT_GT(glm::length(moved), 0.0f);
    EXPECT_NEAR(glm::dot(moved, glm::normalize(framed.position - framed.target)), 0.0f, 1e-4f);
    EXPECT_NEAR(moved.y, 0.0f, 1e-5f);
}

} // namespace
} // namespace simeco::view
