// `simeco view`: a field grown live in a window, its environment tuned from a panel while it grows. The same
// simulation and renderer as `simeco run`: the field ticks as the clock says (view/growth_clock.h; unless paused),
// each frame the renderer draws it into
// an offscreen target at the window's size, the presenter copies that into the window's image and the panel is
// drawn on top. Frames are in flight: the host prepares the next while the device draws the last, and waits for
// them only before the field's organs are drawn again.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "draw/render_settings.h"
#include "field/simulation.h"

namespace simeco::view {

struct ViewOptions {
    field::SimulationOptions simulation;
    // The picture's settings for a field (its view file's and scene's look, the command line's options).
    std::function<draw::RenderSettings(const field::Simulation&)> settingsFor;
    std::uint32_t width = 1280, height = 720;
    std::uint32_t frames = 0;  // frames to draw before closing, each a second of the growth clock; 0: none
    double seconds = 0;        // seconds of the clock before closing; 0: until the window is closed (or `frames`)
    double startTime = 0;      // simulated seconds the field grows before the first frame
    std::string screenshot;    // a .png or .exr written of the last frame (and of the panel's screenshot button)
    std::vector<std::string> settings; // name=value, as the panel's controls (view_controls.h)
    std::string device;
    // Seconds between looks at the scene file for changes (it reloads when it changes on disk).
    double watchSeconds = 0.5;
};

// Runs until the window closes, `frames` are drawn or `seconds` have passed. Throws WindowError where no window
// opens, SettingError for a bad `settings` entry, and what loading the scene throws at the start (a scene that fails
// to reload later is reported in the window and on stderr, and the field before it goes on).
void runViewer(const ViewOptions& options);

} // namespace simeco::view
