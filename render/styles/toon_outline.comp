#version 460
// Toon outlines over the frame copied to buffers: a pixel turns to the line colour where the plant changes
// next to an organ, or where the depth of an organ bends sharply (a fold or an organ in front of another).
// Depth is compared as 1/z (as z in a parallel projection), which is affine across any plane on screen, so its
// second difference vanishes on flat and gently curved surfaces and spikes at creases and occlusion edges.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"

layout(local_size_x = kDrawWorkgroupSize) in;

layout(std430, binding = 0) readonly buffer ColorIn {
    vec4 colorIn[];
};
layout(std430, binding = 1) readonly buffer Depth {
    float depth[];  // depth buffer values in [0, 1]
};
layout(std430, binding = 2) readonly buffer Plant {
    uint plant[];
};
layout(std430, binding = 3) writeonly buffer ColorOut {
    vec4 colorOut[];
};
layout(push_constant) uniform Push {
    OutlinePush push;
};

const uint kNoId = 0xFFFFFFFFu;

// A measure of depth that is affine across any plane on screen: 1/z up to a constant factor from a depth value of a
// [0, 1] perspective projection, or the distance z itself from a parallel one's.
float inverseDepth(uint pixel) {
    float f = push.farPlane;
    float n = push.nearPlane;
    if (push.parallel != 0u) return n + depth[pixel] * (f - n);
    return (f / (f - n) - depth[pixel]) * (f - n) / (f * n);
}

uint pixelAt(ivec2 p) {
    ivec2 clamped = clamp(p, ivec2(0), ivec2(int(push.width) - 1, int(push.height) - 1));
    return uint(clamped.y) * push.width + uint(clamped.x);
}

void main() {
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint pixel = group * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (pixel >= push.width * push.height) {
        return;
    }
    ivec2 p = ivec2(pixel % push.width, pixel / push.width);
    int r = int(push.radius);
    uint neighbours[4] = uint[4](pixelAt(p + ivec2(-r, 0)), pixelAt(p + ivec2(r, 0)), pixelAt(p + ivec2(0, -r)),
                                 pixelAt(p + ivec2(0, r)));
    uint centrePlant = plant[pixel];
    bool edge = false;
    bool allOrgans = centrePlant != kNoId;
    for (int i = 0; i < 4; ++i) {
        uint other = plant[neighbours[i]];
        allOrgans = allOrgans && other != kNoId;
        if (other != centrePlant && (other != kNoId || centrePlant != kNoId)) {
            edge = true;
        }
    }
    if (!edge && allOrgans) {
        float centre = inverseDepth(pixel);
        float bendX = abs(inverseDepth(neighbours[0]) + inverseDepth(neighbours[1]) - 2.0 * centre);
        float bendY = abs(inverseDepth(neighbours[2]) + inverseDepth(neighbours[3]) - 2.0 * centre);
        edge = max(bendX, bendY) > push.threshold * centre;
    }
    colorOut[pixel] = edge ? vec4(push.lineColor.rgb, 1.0) : colorIn[pixel];
}
