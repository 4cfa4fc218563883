#version 460
// The organs and the ground, several samples a pixel: colour, the ids as halves in floats (few devices multisample
// integer images), and the sun's light with the surface's depth in its alpha, for the resolve subpass.
#extension GL_GOOGLE_include_directive : require

#include "render/organs/organ_shading.glsl"
#include "render/samples/id_halves.glsl"

layout(location = 0) out vec4 outColor;
layout(location = 1) out vec4 outIds;
layout(location = 2) out vec4 outSun;

void main() {
    vec4 sun;
    shadeOrgan(outColor, sun);
    outIds = idHalves(inPlant, inOrgan);
    outSun = vec4(sun.rgb, gl_FragCoord.z);
}
