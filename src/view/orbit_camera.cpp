#include "view/orbit_camera.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace simeco::view {

namespace {
constexpr float kDegreesPerPixel = 0.33f;
constexpr float kHighestElevation = 89.0f;
} // namespace

OrbitCamera::OrbitCamera(const draw::Camera& start, const draw::CameraView& framed) : camera_(start) {
    camera_.target = framed.target;
    camera_.distance = glm::length(framed.position - framed.target);
}

void OrbitCamera::orbit(float dxPixels, float dyPixels) {
    camera_.azimuthDegrees = std::remainder(camera_.azimuthDegrees - dxPixels * kDegreesPerPixel, 360.0f);
    camera_.elevationDegrees = std::clamp(camera_.elevationDegrees + dyPixels * kDegreesPerPixel,
                                          -kHighestElevation, kHighestElevation);
}

void OrbitCamera::pan(float dxPixels, float dyPixels, float viewHeight) {
    const float a = glm::radians(camera_.azimuthDegrees), e = glm::radians(camera_.elevationDegrees);
    const glm::vec3 towardsCamera{std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)};
    const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), towardsCamera));
    const glm::vec3 up = glm::cross(towardsCamera, right);
    // A pixel at the target's depth covers this much of the world.
    const float perPixel =
        2.0f * camera_.distance * std::tan(glm::radians(camera_.fovYDegrees) / 2.0f) / std::max(viewHeight, 1.0f);
    camera_.target = *camera_.target + (-dxPixels * right + dyPixels * up) * perPixel;
}

void OrbitCamera::zoom(float steps) { camera_.distance *= std::pow(0.9f, steps); }

} // namespace simeco::view
