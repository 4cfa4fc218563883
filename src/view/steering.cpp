#include "view/steering.h"

#include <GLFW/glfw3.h>

namespace simeco::view {

Steering::Steering(GLFWwindow* window) : window_(window) {
    glfwSetWindowUserPointer(window, this);
    glfwSetScrollCallback(window, [](GLFWwindow* w, double, double y) {
        static_cast<Steering*>(glfwGetWindowUserPointer(w))->scroll_ += y;
    });
    glfwGetCursorPos(window, &last_.x, &last_.y);
    // A click quicker than a frame still reads as pressed once.
    glfwSetInputMode(window, GLFW_STICKY_MOUSE_BUTTONS, GLFW_TRUE);
}

std::optional<glm::dvec2> Steering::steer(OrbitCamera& camera, bool mouseTaken, bool keysTaken, float viewHeight) {
    std::optional<glm::dvec2> click;
    glm::dvec2 at;
    glfwGetCursorPos(window_, &at.x, &at.y);
    const glm::vec2 moved(at - last_);
    if (!mouseTaken) {
        const auto pressed = [&](int button) { return glfwGetMouseButton(window_, button) == GLFW_PRESS; };
        const bool left = pressed(GLFW_MOUSE_BUTTON_LEFT);
        const bool right = pressed(GLFW_MOUSE_BUTTON_RIGHT) || pressed(GLFW_MOUSE_BUTTON_MIDDLE);
        // A drag moves while the button stays down; a move before the press is not one.
        if (left && leftBefore_ && (moved.x != 0 || moved.y != 0)) {
            camera.orbit(moved.x, moved.y);
            dragged_ = true;
        }
        if (right) camera.pan(moved.x, moved.y, viewHeight);
        if (leftBefore_ && !left && !dragged_) click = at;
        if (!left) dragged_ = false;
        leftBefore_ = left;
        camera.zoom(float(scroll_));
    } else {
        leftBefore_ = false;
    }
    scroll_ = 0;
    last_ = at;
    if (!keysTaken) {
        const auto key = [&](int k) { return glfwGetKey(window_, k) == GLFW_PRESS; };
        if (key(GLFW_KEY_LEFT)) camera.orbit(-6, 0);
        if (key(GLFW_KEY_RIGHT)) camera.orbit(6, 0);
        if (key(GLFW_KEY_UP)) camera.orbit(0, 6);
        if (key(GLFW_KEY_DOWN)) camera.orbit(0, -6);
        if (key(GLFW_KEY_EQUAL) || key(GLFW_KEY_KP_ADD)) camera.zoom(0.2f);
        if (key(GLFW_KEY_MINUS) || key(GLFW_KEY_KP_SUBTRACT)) camera.zoom(-0.2f);
    }
    return click;
}

} // namespace simeco::view
