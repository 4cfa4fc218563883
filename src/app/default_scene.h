// The field `simeco run` grows when it is given no scene: the garden of the three SimEco species
// (scenes/garden.eco, built into the executable), a thousand plants of them.
#pragma once

#include <cstdint>

namespace simeco::app {

extern const char* const kDefaultSceneText;
inline constexpr const char* kDefaultSceneName = "scenes/garden.eco";
inline constexpr uint32_t kDefaultScenePlants = 1000;

} // namespace simeco::app
