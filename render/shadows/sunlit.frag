#version 460
// The sunlit pass, after the shadow volumes: where the stencil says the sun reaches the visible surface (the
// pipeline's stencil test), the sun's light on it, which the organs' pass wrote beside the ambient colour, is added
// to the colour (by blending). One full-frame pass in place of drawing every organ again.
layout(input_attachment_index = 0, set = 0, binding = 4) uniform subpassInput sunLight;

layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(subpassLoad(sunLight).rgb, 0.0);
}
