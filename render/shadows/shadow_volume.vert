#version 460
// Shadow volume triangles written by shadow_volumes.comp, in world coordinates; w = 0 marks the point at
// infinity opposite the sun, which the projection maps to a finite place (depth clamp keeps it drawn).
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"

layout(location = 0) in vec4 inPosition;

layout(std140, set = 0, binding = 1) uniform Frame {
    DrawFrame frame;
};

void main() {
    gl_Position = frame.viewProj * inPosition;
}
