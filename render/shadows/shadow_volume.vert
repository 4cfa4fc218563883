#version 460
// Shadow volumes written by shadow_volumes.comp, one instance each: its near cap's corners a, b, c and far cap's
// a', b', c' in world coordinates (w = 0: the point at infinity opposite the sun, which the projection maps to a
// finite place; depth clamp keeps it drawn), made into 8 triangles wound outwards: the near cap (a, c, b) towards
// the sun, the far cap (a', b', c') away from it, and two per side. With the far corners at infinity the far cap
// and one triangle of each side vanish.
//
// The draw is indexed (the renderer's kVolumeFaces), so that a volume's vertices are shaded once each rather than
// once per triangle corner: vertices 0-2 are a, b, c, 3-5 a', b', c', and 6 + 2s, 7 + 2s the far corners of side s
// (s = ab, bc, ca) once more, which a side inside a flat sheet (its first near corner's w is 3) puts on that near
// corner instead: both its triangles then have no area and draw nothing.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"

layout(location = 0) in vec4 inCorners[kVolumeVerticesPerTriangle];

layout(std140, set = 0, binding = 1) uniform Frame {
    DrawFrame frame;
};

void main() {
    uint corner = gl_VertexIndex;
    if (corner >= 6u) {
        const uint side = (corner - 6u) / 2u;
        const uint end = (side + (corner - 6u) % 2u) % 3u;
        corner = inCorners[side].w > 2.0 ? side : end + 3u;
    }
    const vec4 p = inCorners[corner];
    gl_Position = frame.viewProj * (corner < 3u ? vec4(p.xyz, 1.0) : p);
}
