// What a frame looks like: size, camera, style, shadows and light. World up is +y (the turtle's initial
// heading); the ground plane lies under the bounds at their lowest y.
#pragma once

#include <cstdint>
#include <optional>

#include <glm/vec3.hpp>

#include "ir/picture_look.h"

namespace simeco::draw {

// The `paper` background: a warm off-white, linear.
inline constexpr glm::vec3 kPaperColor{0.83f, 0.77f, 0.62f};

struct Camera {
    float azimuthDegrees = 30.0f;   // around +y, from +z towards +x
    float elevationDegrees = 20.0f; // above the horizon, within (-90, 90)
    // From the target; 0 or less: as close as keeps the whole bounding box in the frame with a small margin.
    float distance = 0.0f;
    std::optional<glm::vec3> target; // what the camera looks at; default: the centre of the bounds
    float fovYDegrees = 35.0f;       // vertical field of view of the perspective projection
    // A parallel (orthographic) projection, as cpfg's `projection: parallel`: framed on the bounds whatever the
    // distance, which only places the camera.
    bool parallel = false;
};

// Lit, toon, outline or paper-cut (ir/picture_look.h).
using Style = ir::PictureStyle;

enum class Shadows {
    Volume, // stencil shadow volumes of the sun
    None,
};

struct RenderSettings {
    std::uint32_t width = 960;
    std::uint32_t height = 720;
    // Samples along each side of a pixel (supersampling): Renderer::render draws the frame at this many times the
    // size and averages each pixel's samples, so thin stems and leaf edges are smooth rather than stepped or broken.
    // Pixel lines and outlines keep their widths in the frame's own pixels.
    std::uint32_t antialias = 1;
    // Samples a pixel (multisampling, draw::checkSamples says which the device has): each organ covers the samples
    // within it, each pixel is their mean, so edges and thin stems are smooth at the cost of drawing the samples,
    // not of shading them (shadows' edges are shaded per sample). 1: none; 0: draw::defaultSamples. With
    // `antialias`, of each supersample.
    std::uint32_t samples = 1;
    // Empty: the default view angles, framed automatically on the bounds.
    std::optional<Camera> camera;
    Style style = Style::Lit;
    Shadows shadows = Shadows::Volume;
    glm::vec3 sunDirection{-0.45f, 0.80f, 0.40f}; // towards the sun; need not be unit length
    glm::vec3 sunColor{1.00f, 0.95f, 0.88f};      // linear irradiance
    glm::vec3 skyColor{0.30f, 0.36f, 0.45f};      // ambient from above
    glm::vec3 groundBounce{0.10f, 0.09f, 0.07f};  // ambient from below
    glm::vec3 background{0.62f, 0.74f, 0.88f};    // linear colour where nothing is drawn
    bool ground = true;
    glm::vec3 groundColor{0.36f, 0.31f, 0.23f};
    float groundSize = 0.0f; // the side of the ground square, centred under the scene; 0: 5 times its radius
    std::uint32_t toonBands = 3;
    glm::vec3 outlineColor{0.02f, 0.02f, 0.02f};
    // Paper-cut: where the sun's cosine on a surface falls below this, the paper shows through.
    float paperCutThreshold = 0.02f;
    // Organs a few pixels across on screen drawn with coarser meshes (their kind's shadow hull: a 6-sided stem, a
    // leaf's coarser cut, a sphere of fewer bands); off: every organ with the finest.
    bool levelsOfDetail = true;
    // Organs wholly outside the view left out of the draws, and their shadow volumes where their shadows fall
    // outside it too.
    bool cullOutsideView = true;
    // Shadow volume vertices take 16 bytes each; a scene needing more than this (or than the device binds in
    // shared::kVolumeWindows storage buffers) draws the volumes that fit.
    std::uint64_t maxShadowVolumeBytes = 512ull << 20;
    // The bytes of each storage binding the volumes are written through; 0: as many as the device binds (its
    // maxStorageBufferRange). Smaller, the same volumes spread over more windows (for tests).
    std::uint64_t shadowVolumeWindowBytes = 0;
};

} // namespace simeco::draw
