// The viewer's Dear ImGui panel: the controls (ViewControls) as sliders and buttons, the field's figures, a plot of
// leaf area and light per species, the picked plant, and the last error of a scene that failed to load.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "view/view_controls.h"

namespace simeco::view {

// A species' leaf area and light over the last ticks.
struct SpeciesHistory {
    std::string name;
    std::vector<float> leafArea, light;
};

struct PickedPlant {
    std::uint32_t plant = 0;
    std::string species;
    double age = 0;
    std::uint64_t modules = 0;
    float light = 0, leafArea = 0, height = 0;
};

struct PanelFigures {
    double frameSeconds = 0;
    double growthPerSecond = 0; // simulated seconds a second of the clock, lately (GrowthRate)
    double tickSeconds = 0;     // the last tick's
    double time = 0;
    std::uint32_t plants = 0;
    std::uint64_t modules = 0;
    std::uint64_t instances = 0; // organs drawn
    std::vector<SpeciesHistory> history;
    std::optional<PickedPlant> picked;
    std::string error; // of the last reload, empty when it loaded
    std::uint32_t drawableSamples = 1; // the counts of samples a pixel the device draws, a bit each
};

// What the user asked for besides changed controls.
struct PanelActions {
    bool environmentChanged = false; // sun, climate, gravity or a species' factors
    bool step = false;
    bool reset = false;
    bool screenshot = false;
};

PanelActions drawPanel(ViewControls& controls, const PanelFigures& figures);

} // namespace simeco::view
