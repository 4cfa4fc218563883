#version 460
// The sunlit pass of a multisampled frame (see sunlit.frag): run for each sample, which adds its own sun's light
// where its own stencil is clear, so a shadow's edge is as smooth as an organ's.
layout(input_attachment_index = 0, set = 0, binding = 4) uniform subpassInputMS sunLight;

layout(location = 0) out vec4 outColor;

void main() {
    outColor = vec4(subpassLoad(sunLight, gl_SampleID).rgb, 0.0);
}
