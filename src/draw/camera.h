// The view and projection of a frame: a camera orbiting its target at an azimuth and elevation, at a given
// distance or framed on the bounds.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "draw/bounds.h"
#include "draw/render_settings.h"

namespace simeco::draw {

struct CameraView {
    glm::vec3 position{0.0f};
    glm::vec3 target{0.0f};
    glm::vec3 right{1, 0, 0}; // image x axis in the world
    glm::vec3 up{0, 1, 0};    // image y axis (upwards) in the world
    glm::mat4 view{1.0f};
    glm::mat4 projection{1.0f}; // Vulkan clip space: depth in [0, 1], image y downwards
    glm::mat4 viewProj{1.0f};
    float nearPlane = 0.1f;
    float farPlane = 100.0f;
    bool parallel = false;  // an orthographic projection
    float halfHeight = 0.0f; // of a parallel projection's view volume, in world units
};

// Where pixels see `bounds` (a box of at least a small size even when empty or flat) for an image of the
// given aspect ratio (width / height).
CameraView cameraView(const Camera& camera, const Bounds& bounds, float aspect);

// The box the camera frames: `bounds` grown to a minimum size so a point or a flat plant can be framed, or a
// unit box at the origin when nothing was drawn.
Bounds framedBounds(const Bounds& bounds);

} // namespace simeco::draw
