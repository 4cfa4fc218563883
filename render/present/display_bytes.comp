#version 460
// A rendered frame for a window: each pixel's linear colour mapped to a byte per channel as the PNG writer maps
// it (draw::previewByte: the ACES filmic curve, then sRGB's encoding unless the window's format encodes itself),
// packed RGBA8 for a copy into an image the window's swapchain is blitted from.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"

layout(local_size_x = kDrawWorkgroupSize) in;

layout(std430, binding = 0) readonly buffer Color {
    vec4 color[];
};
layout(std430, binding = 1) writeonly buffer Bytes {
    uint bytes[];
};
layout(push_constant) uniform Push {
    DisplayPush push;
};

float mapped(float linear) {
    const float x = isnan(linear) || isinf(linear) ? 0.0 : max(linear, 0.0);
    return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

float encoded(float m) {
    return m <= 0.0031308 ? 12.92 * m : 1.055 * pow(m, 1.0 / 2.4) - 0.055;
}

void main() {
    const uint pixel = gl_GlobalInvocationID.x;
    if (pixel >= push.pixels) return;
    vec3 rgb = vec3(mapped(color[pixel].r), mapped(color[pixel].g), mapped(color[pixel].b));
    if (push.encodeSrgb != 0u) rgb = vec3(encoded(rgb.r), encoded(rgb.g), encoded(rgb.b));
    bytes[pixel] = packUnorm4x8(vec4(rgb, 1.0));
}
