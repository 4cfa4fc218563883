#include "draw/camera.h"

#include <algorithm>
#include <cmath>

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace simeco::draw {
namespace {

// The frame keeps this fraction of its half-size around the projected box.
constexpr float kFrameFill = 0.92f;

} // namespace

Bounds framedBounds(const Bounds& bounds) {
    if (bounds.empty() || !bounds.finite()) {
        return {{-0.5f, 0.0f, -0.5f}, {0.5f, 1.0f, 0.5f}};
    }
    Bounds b = bounds;
    glm::vec3 extent = b.extent();
    float largest = std::max({extent.x, extent.y, extent.z});
    // A point or a flat plant still gets a box of some size, relative to where it is.
    float smallest = largest > 0.0f ? 1e-3f * largest : 1e-3f * std::max(1.0f, glm::length(b.centre()));
    for (int axis = 0; axis < 3; ++axis) {
        if (extent[axis] < smallest) {
            b.min[axis] -= 0.5f * smallest;
            b.max[axis] += 0.5f * smallest;
        }
    }
    return b;
}

CameraView cameraView(const Camera& camera, const Bounds& bounds, float aspect) {
    Bounds box = framedBounds(bounds);
    CameraView v;
    v.target = camera.target.value_or(box.centre());

    float azimuth = glm::radians(camera.azimuthDegrees);
    float elevation = glm::radians(std::clamp(camera.elevationDegrees, -89.5f, 89.5f));
    glm::vec3 towardsCamera(std::cos(elevation) * std::sin(azimuth), std::sin(elevation),
                            std::cos(elevation) * std::cos(azimuth));
    glm::vec3 forward = -towardsCamera;
    v.right = glm::normalize(glm::cross(forward, glm::vec3(0, 1, 0)));
    v.up = glm::cross(v.right, forward);

    float fovY = glm::radians(std::clamp(camera.fovYDegrees, 1.0f, 170.0f));
    float tanY = std::tan(0.5f * fovY) * kFrameFill;
    float tanX = tanY * aspect;
    float radius = 0.5f * glm::length(box.extent());

    // Each corner at (x, y) across the view and `depth` towards the camera from the target is in the frame
    // when the camera is at least depth + max(|x| / tanX, |y| / tanY) from the target.
    float distance = camera.distance;
    if (!(distance > 0.0f)) {
        distance = 0.0f;
        float nearest = -radius;
        for (int corner = 0; corner < 8; ++corner) {
            glm::vec3 c((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                        (corner & 4) ? box.max.z : box.min.z);
            glm::vec3 offset = c - v.target;
            float x = std::abs(glm::dot(offset, v.right));
            float y = std::abs(glm::dot(offset, v.up));
            float depth = glm::dot(offset, towardsCamera);
            distance = std::max(distance, depth + std::max(x / tanX, y / tanY));
            nearest = std::max(nearest, depth);
        }
        distance = std::max(distance, nearest + 0.01f * radius);
    }
    v.position = v.target + distance * towardsCamera;

    // The ground reaches past the bounds, so the near plane stays well in front of them and far behind.
    v.nearPlane = std::max(distance - 2.0f * radius, 0.02f * distance);
    v.farPlane = distance + 8.0f * radius;
    v.view = glm::lookAtRH(v.position, v.target, v.up);
    v.parallel = camera.parallel;
    if (v.parallel) {
        // The view volume's half height holds every corner of the box across the view, with the same margin.
        float half = 0.0f;
        for (int corner = 0; corner < 8; ++corner) {
            glm::vec3 c((corner & 1) ? box.max.x : box.min.x, (corner & 2) ? box.max.y : box.min.y,
                        (corner & 4) ? box.max.z : box.min.z);
            glm::vec3 offset = c - v.target;
            half = std::max({half, std::abs(glm::dot(offset, v.up)), std::abs(glm::dot(offset, v.right)) / aspect});
        }
        v.halfHeight = std::max(half, 1e-6f * std::max(radius, 1.0f)) / kFrameFill;
        v.projection = glm::orthoRH_ZO(-v.halfHeight * aspect, v.halfHeight * aspect, -v.halfHeight, v.halfHeight,
                                       v.nearPlane, v.farPlane);
    } else {
        v.projection = glm::perspectiveRH_ZO(fovY, aspect, v.nearPlane, v.farPlane);
    }
    v.projection[1][1] = -v.projection[1][1]; // Vulkan's image y runs downwards
    v.viewProj = v.projection * v.view;
    return v;
}

} // namespace simeco::draw
