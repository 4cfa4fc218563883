// The viewer's camera: orbits its target with the mouse, pans it and zooms toward it, starting from the view the
// renderer frames the grown field with.
#pragma once

#include <glm/vec3.hpp>

#include "draw/camera.h"
#include "draw/render_settings.h"

namespace simeco::view {

class OrbitCamera {
public:
    // `framed`: the view the renderer made of `start` (its target and distance become the camera's own).
    OrbitCamera(const draw::Camera& start, const draw::CameraView& framed);

    // A drag of the mouse by pixels: the camera turns around its target (a third of a degree a pixel).
    void orbit(float dxPixels, float dyPixels);
    // A drag that moves the target across the view, by pixels of a view `viewHeight` pixels high.
    void pan(float dxPixels, float dyPixels, float viewHeight);
    // Steps of the mouse wheel: a tenth nearer each step up.
    void zoom(float steps);

    const draw::Camera& camera() const { return camera_; }

private:
    draw::Camera camera_;
};

} // namespace simeco::view
