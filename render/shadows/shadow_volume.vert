#version 460
// Shadow volumes written by shadow_volumes.comp, one instance each: its near cap's corners a, b, c and far cap's
// a', b', c' in world coordinates (w = 0: the point at infinity opposite the sun, which the projection maps to a
// finite place; depth clamp keeps it drawn), made into 8 triangles wound outwards: the near cap (a, c, b) towards
// the sun, the far cap (a', b', c') away from it, and two per side. With the far corners at infinity the far cap
// and one triangle of each side vanish.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"

layout(location = 0) in vec4 inCorners[kVolumeVerticesPerTriangle];

layout(std140, set = 0, binding = 1) uniform Frame {
    DrawFrame frame;
};

// Corners 0-2: a, b, c; 3-5: a', b', c'.
const uint kFaces[kVolumeCorners] = uint[](0u, 2u, 1u,  // near cap
                                           3u, 4u, 5u,  // far cap
                                           0u, 1u, 4u, 0u, 4u, 3u,  // side a b
                                           1u, 2u, 5u, 1u, 5u, 4u,  // side b c
                                           2u, 0u, 3u, 2u, 3u, 5u); // side c a

void main() {
    const uint corner = kFaces[gl_VertexIndex];
    // A side inside a flat sheet (its first near corner's w is 3) is left out: its triangles go outside the view.
    const uint face = gl_VertexIndex / 3u;
    const uint side = face >= 2u ? (face - 2u) / 2u : 3u;
    if (side < 3u && inCorners[side].w > 2.0) {
        gl_Position = vec4(2.0, 0.0, 0.5, 1.0);
        return;
    }
    const vec4 p = inCorners[corner];
    gl_Position = frame.viewProj * (corner < 3u ? vec4(p.xyz, 1.0) : p);
}
