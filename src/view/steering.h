// The mouse and keys steering the viewer's camera: a left drag orbits, a right or middle drag pans, the wheel and
// +/- zoom, the arrow keys orbit; a left click without a drag asks for the plant under it.
#pragma once

#include <optional>

#include <glm/vec2.hpp>

#include "view/orbit_camera.h"

struct GLFWwindow;

namespace simeco::view {

class Steering {
public:
    // Installs the window's scroll callback: make it before the overlay, whose callbacks pass input on to it.
    explicit Steering(GLFWwindow* window);
    Steering(const Steering&) = delete;
    Steering& operator=(const Steering&) = delete;

    // A frame's input: the mouse where the panel does not take it (`mouseTaken`), the keys where it does not take
    // them. Returns where a click was, in window coordinates.
    std::optional<glm::dvec2> steer(OrbitCamera& camera, bool mouseTaken, bool keysTaken, float viewHeight);

private:
    GLFWwindow* window_;
    double scroll_ = 0; // wheel steps since the last frame
    glm::dvec2 last_{0.0};
    bool dragged_ = false, leftBefore_ = false;
};

} // namespace simeco::view
