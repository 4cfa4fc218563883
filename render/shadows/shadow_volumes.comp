#version 460
// Stencil shadow volumes for the sun (a directional light), built from the instance buffer: each triangle of
// an organ's shadow hull that faces away from the sun becomes a closed volume of its own — the triangle as the
// near cap, its corners extruded away from the sun as the far cap, and a side per edge (draw_layout.h). Where the
// ground receives the shadows they are extruded to a plane just below it, which bounds the pixels a volume covers
// to those between the organ and its shadow; else to the point at infinity opposite the sun, where the sides
// meet. A point whose way to the sun crosses such a triangle lies inside its volume, and the z-fail stencil count
// of the overlapping volumes is nonzero exactly there (Carmack's reverse; Everitt and Kilgard, "Practical and
// Robust Stenciled Shadow Volumes for Hardware-Accelerated Rendering", 2002).
//
// Closed hulls (stems, spheres) are inscribed in the drawn mesh and cast from their faces turned away from the
// sun, so no lit surface lies on a near cap. Open surfaces (leaves, discs, polygon triangles) cast from every
// triangle, turned away from the sun and pushed a little along the light: the thin prism of a leaf.
#extension GL_GOOGLE_include_directive : require

#include "render/shared/draw_layout.h"
#include "render/organs/organ_transform.glsl"
#include "render/organs/view_sides.glsl"

layout(local_size_x = kDrawWorkgroupSize) in;

layout(std430, binding = 0) readonly buffer Instances {
    OrganInstance instances[];
};
layout(std430, binding = 1) readonly buffer Table {
    OrganTable table;
};
layout(std430, binding = 2) readonly buffer MeshVertices {
    MeshVertex meshVertices[];
};
layout(std430, binding = 3) readonly buffer MeshIndices {
    uint meshIndices[];
};
layout(std430, binding = 4) buffer Volumes {
    VolumeDraw volumes;
};
// The volume buffer in kVolumeWindows windows of push.window vertices each.
layout(std430, binding = 5) writeonly buffer VolumeWindow0 {
    vec4 volumeWindow0[];
};
layout(std430, binding = 8) writeonly buffer VolumeWindow1 {
    vec4 volumeWindow1[];
};
layout(std430, binding = 9) writeonly buffer VolumeWindow2 {
    vec4 volumeWindow2[];
};
layout(std430, binding = 10) writeonly buffer VolumeWindow3 {
    vec4 volumeWindow3[];
};
layout(std430, binding = 6) readonly buffer LeafHullTriangles {
    uvec2 leafHullTriangles[];  // per leaf shape: its first triangle in the leaf hull, and its count
};
layout(std430, binding = 11) readonly buffer LeafFarShadowTriangles {
    uvec2 leafFarShadowTriangles[];  // the same for each shape's far shadow, in the same hull (organ_meshes.h)
};
layout(std430, binding = 7) readonly buffer InteriorEdges {
    uint interiorEdges[];  // per triangle of the index buffer: bit k, its edge k is inside a flat sheet
};
layout(std430, binding = 12) readonly buffer Frame {
    DrawFrame frame;
};
layout(push_constant) uniform Push {
    ShadowVolumePush push;
};

OrganVertex hullVertex(OrganInstance o, uint corner) {
    MeshVertex m = meshVertices[uint(int(meshIndices[push.firstIndex + corner]) + push.vertexOffset)];
    return organVertex(o, push.kind, m.position, m.normal, push.cameraRight.xyz, push.cameraUp.xyz, vec4(0.0),
                       false);
}

void writeVolumeVertex(uint at, vec4 corner) {
    const uint window = at / push.window;
    const uint local = at - window * push.window;
    if (window == 0u) volumeWindow0[local] = corner;
    else if (window == 1u) volumeWindow1[local] = corner;
    else if (window == 2u) volumeWindow2[local] = corner;
    else volumeWindow3[local] = corner;
}

// The volume of triangle (a, b, c), wound so that (a, c, b) looks towards the sun, with the sides of the edges
// `inside` marks (bit k: the edge from corner k to the next) left out.
void castVolume(vec3 a, vec3 b, vec3 c, uint inside, vec3 away, bool capped) {
    // The capacity is a multiple of the vertices per triangle, so a claim either fits whole or starts past
    // the end; draw_args.comp clamps the draw to the capacity.
    uint base = atomicAdd(volumes.allocated, kVolumeVerticesPerTriangle);
    if (base + kVolumeVerticesPerTriangle > push.capacity) {
        return;
    }
    // shadow_volume.vert makes the faces. A triangle reaching below the plane goes to infinity whole. A near
    // corner's w says whether the side from it to the next corner is left out (3) or drawn (1).
    writeVolumeVertex(base + 0u, vec4(a, (inside & 1u) != 0u ? 3.0 : 1.0));
    writeVolumeVertex(base + 1u, vec4(b, (inside & 2u) != 0u ? 3.0 : 1.0));
    writeVolumeVertex(base + 2u, vec4(c, (inside & 4u) != 0u ? 3.0 : 1.0));
    bool toPlane = capped && min(a.y, min(b.y, c.y)) > push.capHeight;
    vec3 corners[3] = vec3[](a, b, c);
    for (uint k = 0u; k < 3u; ++k) {
        vec3 p = corners[k];
        writeVolumeVertex(base + 3u + k, toPlane ? vec4(p + away * ((p.y - push.capHeight) / -away.y), 1.0)
                                                 : vec4(away, 0.0));
    }
}

// A triangle of a sheet with nothing to keep it off lit surfaces (a stem's ribbon, inside the stem), turned to
// look away from the sun.
void castSheet(vec3 a, vec3 b, vec3 c, uint inside, vec3 away, bool capped) {
    float facing = dot(cross(b - a, c - a), away);
    if (facing == 0.0 || isnan(facing)) return;
    if (facing < 0.0) {
        castVolume(a, c, b, ((inside >> 2u) & 1u) | (inside & 2u) | ((inside & 1u) << 2u), away, capped);
    } else {
        castVolume(a, b, c, inside, away, capped);
    }
}

void main() {
    uint group = gl_WorkGroupID.y * gl_NumWorkGroups.x + gl_WorkGroupID.x;
    uint index = group * gl_WorkGroupSize.x + gl_LocalInvocationID.x;
    if (index >= table.count[push.kind]) {
        return;
    }
    OrganInstance o = instances[table.first[push.kind] + index];
    // cpfg's pixel lines cast no shadow: their width is the picture's, not the world's.
    if (push.kind == kOrganStem && o.shape == kLinePixel) {
        return;
    }
    vec3 away = push.awayFromSun.xyz;
    bool capped = push.capped != 0u && away.y < 0.0;
    // Ended at the plane below the ground, an organ's volumes lie within its bounding sphere swept along the light
    // to the plane, where the sphere's shadow is stretched by the light's slant: outside the view when both ends are
    // outside one of its sides.
    if (push.cull != 0u && capped) {
        const vec4 sphere = organBounds(o);
        const vec3 end = sphere.xyz + away * (max(sphere.y - push.capHeight, 0.0) / -away.y);
        const vec4 shadow = vec4(end, sphere.w / max(-away.y, 0.05));
        if ((sidesOutside(frame.viewProj, sphere) & sidesOutside(frame.viewProj, shadow)) != 0u) return;
    }
    // A round stem casts the shadow of its silhouette: the ribbon through its axis across the light, as wide as the
    // drawn stem is across its flats, in two triangles (their shared diagonal's sides cancel). Along the light it
    // casts from its hull.
    if (push.kind == kOrganStem && o.shape == kLineCylinder) {
        vec3 across = cross(o.heading.xyz, away);
        float width = length(across);
        if (width > 1e-3) {
            across *= kStemRibbonHalfWidth / width;
            vec3 p0 = o.position.xyz;
            vec3 p1 = p0 + o.position.w * o.heading.xyz;
            vec3 a0 = p0 - o.heading.w * across, b0 = p0 + o.heading.w * across;
            vec3 a1 = p1 - o.up.w * across, b1 = p1 + o.up.w * across;
            castSheet(a0, a1, b1, 4u, away, capped);
            castSheet(a0, b1, b0, 1u, away, capped);
            return;
        }
    }

    // A leaf casts from its own shape's triangles of the hull all shapes share; when it is a few pixels across on
    // screen (as render/organs/draw_lists.comp draws it coarse), from its far shadow: its silhouette quadrilateral
    // of its own area, whose volume has four sides where its lobes' and leaflets' had many.
    uvec2 triangles = uvec2(0u, push.triangleCount);
    if (push.kind == kOrganLeaf) {
        const float depth = dot(push.viewDepth, vec4(o.position.xyz, 1.0));
        const bool far = depth > 0.0 &&
                         max(o.position.w, o.heading.w) < push.farLeafPixels * push.pixelAtUnitDepth * depth;
        triangles = o.shape >= uint(leafHullTriangles.length()) ? uvec2(0u)
                    : far                                        ? leafFarShadowTriangles[o.shape]
                                                                 : leafHullTriangles[o.shape];
    }
    for (uint t = triangles.x; t < triangles.x + triangles.y; ++t) {
        OrganVertex va = hullVertex(o, 3u * t);
        OrganVertex vb = hullVertex(o, 3u * t + 1u);
        OrganVertex vc = hullVertex(o, 3u * t + 2u);
        if (!va.present || !vb.present || !vc.present) {
            continue;
        }
        vec3 a = va.position;
        vec3 b = vb.position;
        vec3 c = vc.position;
        float facing = dot(cross(b - a, c - a), away);
        // Edges k = (a, b), (b, c), (c, a) inside a flat sheet: neighbouring volumes' sides there cancel.
        uint inside = push.closedHull != 0u ? 0u : interiorEdges[push.firstIndex / 3u + t];
        if (push.closedHull != 0u) {
            if (!(facing > 0.0)) {
                continue;  // lit (or edge-on, or degenerate): the volume starts at the far side of the hull
            }
        } else {
            if (facing == 0.0 || isnan(facing)) {
                continue;
            }
            if (facing < 0.0) {
                vec3 swap = b;
                b = c;
                c = swap;
                // (a, c, b): its edges are the old (c, a), (b, c), (a, b).
                inside = ((inside >> 2u) & 1u) | (inside & 2u) | ((inside & 1u) << 2u);
            }
            // The push is relative to the organ, so it stays small next to the organ at any scene scale.
            float size = push.kind == kOrganTriangle ? max(distance(a, b), max(distance(b, c), distance(c, a)))
                                                     : o.heading.w;
            vec3 shift = push.awayFromSun.w * size * away;
            a += shift;
            b += shift;
            c += shift;
        }
        castVolume(a, b, c, inside, away, capped);
    }
}
