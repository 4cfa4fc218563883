#version 460
// The organs and the ground, one sample a pixel: colour, plant and organ ids, and the sun's light beside.
#extension GL_GOOGLE_include_directive : require

#include "render/organs/organ_shading.glsl"

layout(location = 0) out vec4 outColor;
layout(location = 1) out uint outPlant;
layout(location = 2) out uint outOrgan;
layout(location = 3) out vec4 outSun;

void main() {
    shadeOrgan(outColor, outSun);
    outPlant = inPlant;
    outOrgan = inOrgan;
}
