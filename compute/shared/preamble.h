// The preamble of every header shared by C++ and GLSL, which lets one text be read by both languages.
//
// In C++ a shared header's names live in namespace simeco::shared (between SIMECO_SHARED_BEGIN and
// SIMECO_SHARED_END) and GLSL's `uint` and `vec4` are C++ types of the same size; SIMECO_CONST declares a
// constant (SIMECO_CONST_FLOAT a float one) and SIMECO_FN a function the same way in both. Only the layouts' own
// C++ extras (constructors, static_asserts) stay behind `#ifdef __cplusplus`.
#ifndef SIMECO_SHARED_PREAMBLE_H
#define SIMECO_SHARED_PREAMBLE_H

#ifdef __cplusplus
#include <cstdint>
namespace simeco::shared {
using uint = uint32_t;
struct vec4 {
    float x, y, z, w;
    bool operator==(const vec4&) const = default;
};
} // namespace simeco::shared
#define SIMECO_SHARED_BEGIN namespace simeco::shared {
#define SIMECO_SHARED_END }
#define SIMECO_CONST inline constexpr uint
#define SIMECO_CONST_FLOAT inline constexpr float
#define SIMECO_FN inline
#else
#define SIMECO_SHARED_BEGIN
#define SIMECO_SHARED_END
#define SIMECO_CONST const uint
#define SIMECO_CONST_FLOAT const float
#define SIMECO_FN
#endif

#endif
