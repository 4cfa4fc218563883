// Lighting of organs and ground: the sun (Lambert) plus a sky/ground hemisphere ambient, the toon and outline
// styles' colour bands, or the paper-cut style's two tones. Surfaces are lit from the side the camera sees, since
// leaves and discs are single sheets. Included by the fragment shaders of one sample a pixel (organ.frag) and of
// several (organ_samples.frag), which differ in how they write the ids.

#include "render/shared/draw_layout.h"

layout(location = 0) in vec3 inWorld;
layout(location = 1) in vec3 inNormal;
layout(location = 2) flat in vec3 inAlbedo;
layout(location = 3) flat in uint inPlant;
layout(location = 4) flat in uint inOrgan;
layout(location = 5) in vec2 inUv;
layout(location = 6) flat in int inTexture;

layout(std140, set = 0, binding = 1) uniform Frame {
    DrawFrame frame;
};
layout(push_constant) uniform Push {
    DrawPush push;
};
// A stage's Texture, tinted by the organ's colour (src/draw/texture_array.h).
layout(set = 0, binding = 2) uniform sampler2DArray textures;

// The surface's colour, and with shadow volumes the sun's light on it, which the sunlit pass adds where the sun
// reaches it. Discards a texture's transparent pixels.
void shadeOrgan(out vec4 outColor, out vec4 outSun) {
    vec3 albedo = inAlbedo;
    if (inTexture >= 0) {
        vec4 texel = texture(textures, vec3(inUv, float(inTexture)));
        // A texture's transparent pixels cut the organ's outline (a leaf image on its blade).
        if (texel.a < 0.5) discard;
        albedo *= texel.rgb;
    }
    vec3 normal = normalize(inNormal);
    if (dot(normal, frame.cameraPosition.xyz - inWorld) < 0.0) {
        normal = -normal;
    }
    float sun = max(dot(normal, frame.sunDirection.xyz), 0.0);
    if (frame.options.x == kStylePaperCut) {
        // A paper cut is flat: the organ's colour where the sun reaches it, the paper behind where it does not.
        // (The renderer draws this style without shadow volumes, in one full pass.)
        bool cut = sun < uintBitsToFloat(frame.options.z);
        outColor = vec4(cut ? frame.background.rgb : albedo, 1.0);
        outSun = vec4(0.0);
        return;
    }
    float skyWeight = 0.5 + 0.5 * normal.y;  // world up is +y
    if (frame.options.x == kStyleToon || frame.options.x == kStyleOutline) {
        float bands = float(max(frame.options.y, 1u));
        sun = min(floor(sun * bands + 0.5), bands) / bands;
        skyWeight = skyWeight > 0.5 ? 1.0 : 0.5;
    }
    vec3 ambient = mix(frame.groundBounce.rgb, frame.skyColor.rgb, skyWeight);
    vec3 sunlight = sun * frame.sunColor.rgb;
    outColor = vec4((push.pass == kPassAmbient ? ambient : ambient + sunlight) * albedo, 1.0);
    outSun = vec4(push.pass == kPassAmbient ? sunlight * albedo : vec3(0.0), 0.0);
}
