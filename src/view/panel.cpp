#include "view/panel.h"

#include <algorithm>

#include <fmt/format.h>
#include <imgui.h>

namespace simeco::view {
namespace {

// A slider that reports a change of the environment.
void slider(const char* label, float& value, float lowest, float highest, bool& changed, const char* format = "%.2f") {
    changed |= ImGui::SliderFloat(label, &value, lowest, highest, format);
}

void environment(ViewControls& c, PanelActions& actions) {
    bool& changed = actions.environmentChanged;
    if (!ImGui::CollapsingHeader("Environment", ImGuiTreeNodeFlags_DefaultOpen)) return;
    slider("sun azimuth", c.sunAzimuth, -180.0f, 180.0f, changed, "%.0f deg");
    slider("sun elevation", c.sunElevation, 1.0f, 90.0f, changed, "%.0f deg");
    slider("sun intensity", c.sunIntensity, 0.0f, 3.0f, changed);
    slider("sky light", c.skyLight, 0.0f, 3.0f, changed);
    slider("DayLight", c.dayLight, 0.0f, 24.0f, changed, "%.1f h");
    slider("RainRate", c.rainRate, 0.0f, 3.0f, changed);
    slider("SoilPH", c.soilPH, 3.0f, 11.0f, changed, "%.1f");
    slider("gravity", c.gravity, 0.0f, 30.0f, changed, "%.1f m/s2");
}

void species(ViewControls& c, PanelActions& actions) {
    if (!ImGui::CollapsingHeader("Species")) return;
    for (size_t s = 0; s < c.species.size(); ++s) {
        ImGui::PushID(int(s));
        ImGui::TextUnformatted(c.species[s].name.c_str());
        field::LiveEnvironment::SpeciesFactors& f = c.species[s].factors;
        slider("GrowRate x", f.growRate, 0.0f, 3.0f, actions.environmentChanged);
        slider("Geotropism x", f.geotropism, -3.0f, 3.0f, actions.environmentChanged);
        slider("Strength x", f.strength, 0.0f, 3.0f, actions.environmentChanged);
        ImGui::PopID();
    }
}

void simulation(ViewControls& c, PanelActions& actions) {
    if (!ImGui::CollapsingHeader("Simulation", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::Checkbox("paused", &c.paused);
    ImGui::SameLine();
    actions.step = ImGui::Button("step");
    ImGui::SameLine();
    actions.reset = ImGui::Button("reset");
    ImGui::SliderFloat("time scale (s a second)", &c.timeScale, 0.1f, 100.0f, "%.3g", ImGuiSliderFlags_Logarithmic);
    int seed = int(c.seed);
    if (ImGui::InputInt("seed (at reset)", &seed)) c.seed = std::uint32_t(std::max(seed, 0));
    int plants = int(c.plants);
    if (ImGui::InputInt("plants (at reset, 0: the scene's)", &plants, 10, 100))
        c.plants = std::uint32_t(std::clamp(plants, 0, 1000000));
    ImGui::SliderFloat("population density x (at reset)", &c.density, 0.1f, 4.0f, "%.2f",
                       ImGuiSliderFlags_Logarithmic);
}

void look(ViewControls& c, const PanelFigures& f, PanelActions& actions) {
    if (!ImGui::CollapsingHeader("Look", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::Checkbox("shadows", &c.shadows);
    const char* styles[] = {"lit", "toon", "outline", "paper-cut"};
    int style = int(c.style);
    if (ImGui::Combo("style", &style, styles, 4)) c.style = draw::Style(style);
    ImGui::SliderFloat("resolution x", &c.renderScale, 0.25f, 2.0f, "%.2f");
    // Multisampling: the counts the device draws.
    if (ImGui::BeginCombo("msaa", fmt::format("{} a pixel", c.samples).c_str())) {
        for (std::uint32_t count = 1; count <= 64; count *= 2) {
            if ((f.drawableSamples & count) == 0) continue;
            if (ImGui::Selectable(fmt::format("{} a pixel", count).c_str(), c.samples == count)) c.samples = count;
        }
        ImGui::EndCombo();
    }
    actions.screenshot = ImGui::Button("screenshot");
}

void figures(const PanelFigures& f) {
    ImGui::Text("%.1f ms a frame, %.3g s of growth a second", f.frameSeconds * 1e3, f.growthPerSecond);
    ImGui::Text("a tick %.1f ms", f.tickSeconds * 1e3);
    ImGui::Text("t = %.1f s, %u plants", f.time, f.plants);
    ImGui::Text("%llu modules, %llu organs drawn",
                static_cast<unsigned long long>(f.modules), static_cast<unsigned long long>(f.instances));
    for (const SpeciesHistory& h : f.history) {
        if (h.leafArea.empty()) continue;
        ImGui::Text("%s: leaf area %.1f, light %.1f", h.name.c_str(), h.leafArea.back(), h.light.back());
        if (h.leafArea.size() < 2) continue; // a plot needs two ticks
        ImGui::PushID(h.name.c_str());
        ImGui::PlotLines("##leaf area", h.leafArea.data(), int(h.leafArea.size()), 0, "leaf area", 0.0f, FLT_MAX,
                         ImVec2(0, 32));
        ImGui::PlotLines("##light", h.light.data(), int(h.light.size()), 0, "light", 0.0f, FLT_MAX, ImVec2(0, 32));
        ImGui::PopID();
    }
    if (f.picked) {
        const PickedPlant& p = *f.picked;
        ImGui::Separator();
        ImGui::Text("plant %u: %s", p.plant, p.species.c_str());
        ImGui::Text("age %.1f s, %llu modules, height %.2f", p.age, static_cast<unsigned long long>(p.modules),
                    p.height);
        ImGui::Text("leaf area %.3f, light %.3f", p.leafArea, p.light);
    }
    if (!f.error.empty()) {
        ImGui::Separator();
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", f.error.c_str());
        ImGui::PopStyleColor();
    }
}

} // namespace

PanelActions drawPanel(ViewControls& controls, const PanelFigures& f) {
    PanelActions actions;
    ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(400, 0), ImGuiCond_FirstUseEver);
    ImGui::Begin("simeco");
    figures(f);
    environment(controls, actions);
    species(controls, actions);
    simulation(controls, actions);
    look(controls, f, actions);
    ImGui::End();
    return actions;
}

} // namespace simeco::view
