// From an organ mesh vertex (organ-local, see MeshVertex) to the world, for every organ kind. organ.vert draws
// with it and shadow_volumes.comp casts with it, so a shadow's caster is exactly the geometry on screen.
// src/export/organ_geometry.cpp does the same on the CPU for mesh files: change both together (but for cpfg's flat
// lines and bands, which the mesh files keep as cylinders, as cpfg's own exporter writes them).
//
// Frame: H = heading, U = up, L = cross(U, H) (left); local x runs along H, y along L, z along U.

struct OrganVertex {
    vec3 position;
    vec3 normal;
    bool present;  // false: the vertex belongs to another leaf shape of the shared leaf mesh
};

vec3 organLeft(OrganInstance o) {
    return cross(o.up.xyz, o.heading.xyz);
}

// Where a stem's end ring meets the joint plane. The plane bisects this segment's heading and the joint's other
// heading, so both segments are cut on the same plane and a bent stem stays closed; no other heading means a
// flat end. The denominator is bounded so that a near reversal gives a long mitre rather than an infinite one.
vec3 stemRingPoint(vec3 ringCentre, vec3 offset, vec3 heading, vec3 otherHeading, out vec3 planeNormal) {
    planeNormal = heading;
    if (dot(otherHeading, otherHeading) > 1e-12) {
        vec3 bisector = heading + normalize(otherHeading);
        if (dot(bisector, bisector) > 1e-6) {
            planeNormal = normalize(bisector);
        }
    }
    float along = -dot(planeNormal, offset) / max(dot(planeNormal, heading), 0.2);
    return ringCentre + offset + along * heading;
}

// Whether a stem mesh vertex is the far band's (MeshVertex: normal.w is 1 on the caps, kStemBandVertex on the band).
bool isStemBandVertex(vec4 localNormal) {
    return localNormal.w > 0.5 * (1.0 + kStemBandVertex);
}

// `camera`: xyz the camera's position, w the world's size of a pixel at unit distance along the view (with a
// `parallel` projection: at any distance), for cpfg's flat lines and bands. The shadow volumes pass zero: a band
// casts the shadow of the cylinder of its width (pixel lines cast none).
OrganVertex organVertex(OrganInstance o, uint kind, vec4 local, vec4 localNormal, vec3 cameraRight, vec3 cameraUp,
                        vec4 camera, bool parallel) {
    OrganVertex v;
    v.present = true;
    vec3 H = o.heading.xyz;
    vec3 U = o.up.xyz;
    vec3 L = cross(U, H);
    if (kind == kOrganStem) {
        bool top = local.w > 0.5;
        float segmentLength = o.position.w;
        float radiusBottom = o.heading.w;
        float radiusTop = o.up.w;
        vec3 radial = local.y * L + local.z * U;  // unit on the rings, zero at the cap centres
        vec3 ringCentre = o.position.xyz + (top ? segmentLength : 0.0) * H;
        vec3 towardsCamera = camera.xyz - ringCentre;
        if (parallel) { // seen in parallel, every point looks along the view's axis
            vec3 backwards = cross(cameraRight, cameraUp);
            towardsCamera = backwards * max(dot(towardsCamera, backwards), 0.0);
        }
        bool drawnFlat = o.shape != kLineCylinder && camera.w > 0.0;
        // The far mesh's band (a stem a pixel or two wide), across the segment as the viewer sees it.
        bool band = isStemBandVertex(localNormal);
        vec3 across = cross(H, towardsCamera);
        across = dot(across, across) > 1e-12 ? normalize(across) : L;
        if (drawnFlat || band) radial = local.y * across;
        if (drawnFlat) {
            // cpfg's lines and polygons: flat, across the segment as the viewer sees it; a pixel line's radii are
            // pixels, as wide at any distance (at least one pixel across).
            if (o.shape == kLinePixel) {
                float depth = max(dot(-towardsCamera, cross(cameraUp, cameraRight)), 0.0);
                float pixel = parallel ? camera.w : camera.w * depth;
                radiusBottom = max(radiusBottom, 0.5) * pixel;
                radiusTop = max(radiusTop, 0.5) * pixel;
            }
        }
        vec3 planeNormal;
        v.position = stemRingPoint(ringCentre, (top ? radiusTop : radiusBottom) * radial, H,
                                   top ? o.nextHeading.xyz : o.previousHeading.xyz, planeNormal);
        if (drawnFlat) {
            // Flat shaded: facing the viewer across the whole width.
            v.normal = towardsCamera - H * dot(towardsCamera, H);
        } else if (band) {
            // Shaded as the round stem's visible half, tilted by the taper as the cone's side: the normal facing the
            // viewer at the middle, at the edges half way between it and the silhouette's, so that the normals
            // interpolated across the band light it on average as the round stem's are lit.
            vec3 facing = cross(across, H);
            v.normal = (radial + (1.0 - 0.5 * abs(local.y)) * facing) * max(segmentLength, 1e-6) +
                       (radiusBottom - radiusTop) * H;
        } else if (localNormal.w > 0.5) {
            v.normal = top ? planeNormal : -planeNormal;
        } else {
            // The side of a cone: the radial direction tilted by the taper.
            v.normal = radial * max(segmentLength, 1e-6) + (radiusBottom - radiusTop) * H;
        }
    } else if (kind == kOrganSphere) {
        vec3 direction = local.x * H + local.y * L + local.z * U;
        v.position = o.position.xyz + o.heading.w * direction;
        v.normal = direction;
    } else if (kind == kOrganDisc) {
        vec3 axisA = H;
        vec3 axisB = L;
        if (o.shape == kDiscFacesViewer) {
            axisA = cameraUp;
            axisB = -cameraRight;
        }
        v.position = o.position.xyz + o.heading.w * (local.x * axisA + local.y * axisB);
        v.normal = cross(axisA, axisB);
    } else if (kind == kOrganLeaf) {
        // The leaf mesh holds every shape (the built-in blades, flat, then any leaf models); a vertex of another
        // shape collapses onto the base, so its triangles have no area and draw nothing. Scaled by its length
        // along H, its width across (L) and its thickness out of the blade (U); normals by the inverse.
        v.present = uint(localNormal.w + 0.5) == o.shape;
        v.position = o.position.xyz;
        if (v.present) {
            v.position += local.x * o.position.w * H + local.y * o.heading.w * L + local.z * o.up.w * U;
        }
        vec3 inverse = 1.0 / max(vec3(o.position.w, o.heading.w, o.up.w), vec3(1e-20));
        v.normal = localNormal.x * inverse.x * H + localNormal.y * inverse.y * L + localNormal.z * inverse.z * U;
    } else {
        // kOrganTriangle: the mesh is three vertices numbered by local.x.
        vec3 a = o.position.xyz;
        vec3 b = o.heading.xyz;
        vec3 c = o.up.xyz;
        uint corner = uint(local.x + 0.5);
        v.position = corner == 0u ? a : (corner == 1u ? b : c);
        v.normal = cross(b - a, c - a);
        if (o.shape == kTriangleOfCylinder) { // smooth across the cylinder, turned to the triangle's side
            vec3 n = corner == 0u ? o.previousHeading.xyz
                                  : (corner == 1u ? o.nextHeading.xyz : vec3(o.position.w, o.heading.w, o.up.w));
            if (dot(n, n) > 0.0) v.normal = dot(n, v.normal) < 0.0 ? -n : n;
        }
    }
    return v;
}
