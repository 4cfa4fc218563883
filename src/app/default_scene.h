// The field `simeco run` grows when it is given no scene: the garden of the three SimEco species
// (scenes/garden.eco, built into the executable), a thousand plants of them.
#pragma once

#include <cstdint>

namespace simeco::app {

extern const char* const kDefaultSceneText;
inline constexpr const char* kDefaultSceneName = "scenes/garden.eco";
inline constexpr uint32_t kDefaultScenePlants = 1000;
// `simeco view` with no scene grows fewer, so that the field stays interactive on a CPU's Vulkan.
inline constexpr uint32_t kDefaultViewPlants = 100;

} // namespace simeco::app
