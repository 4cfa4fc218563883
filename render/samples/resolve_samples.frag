#version 460
// The resolve subpass of a multisampled frame: a full-frame triangle writing each pixel from its samples. Colour
// and alpha are the samples' mean (in linear light; alpha the organs' coverage); plant, organ and depth are those
// of the nearest sample, so ids stay ids and the outlines and picking see a surface that is there. As
// draw::downsample does for a supersampled frame.
#extension GL_GOOGLE_include_directive : require

#include "render/samples/id_halves.glsl"

layout(constant_id = 0) const int kSamples = 4;

// The organs' pass leaves each sample's depth in the alpha of its sun's light.
layout(input_attachment_index = 0, set = 0, binding = 4) uniform subpassInputMS sunSamples;
layout(input_attachment_index = 1, set = 0, binding = 5) uniform subpassInputMS colorSamples;
layout(input_attachment_index = 2, set = 0, binding = 6) uniform subpassInputMS idSamples;

layout(location = 0) out vec4 outColor;
layout(location = 1) out uint outPlant;
layout(location = 2) out uint outOrgan;
layout(location = 3) out float outDepth;

void main() {
    vec4 sum = vec4(0.0);
    int nearest = 0;
    float nearestDepth = 2.0;
    for (int s = 0; s < kSamples; ++s) {
        sum += subpassLoad(colorSamples, s);
        float depth = subpassLoad(sunSamples, s).a;
        if (depth < nearestDepth) {
            nearestDepth = depth;
            nearest = s;
        }
    }
    outColor = sum / float(kSamples);
    vec4 ids = subpassLoad(idSamples, nearest);
    outPlant = plantOfHalves(ids);
    outOrgan = organOfHalves(ids);
    outDepth = nearestDepth;
}
