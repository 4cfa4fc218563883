// cpfg's generalized cylinders drawn as meshes (`line style: cylinder`), as turtle/cylinder_mesh.cpp draws them:
// rings of the points' contours along the Hermite curve between two control points, joined by strips of
// triangles. Needs turtle_math.glsl, turtle_modules.glsl, plant_bounds.glsl and these buffers: states, marks,
// cylinderAnchors, contourRings, the four setters' searches (contourSetters, tangentSetters, radiusScaleSetters,
// radiusTangentSetters) and instances.

// A control point as cpfg keeps it, in cpfg's frame (its up is ours reversed): where a contour's x runs along up
// and its y against left.
struct CylinderPoint {
    vec3 position;
    vec3 heading;
    vec3 left;
    vec3 up;
    float width;
    uint contour;
    vec2 tangents; // into the point, out of it
    vec2 radiusIn;
    vec2 radiusOut;
    float scaleRadius;
};

uint cylinderContours(TurtleSpecies sp) { return sp.cylinders >> kCylinderContoursShift; }

// cpfg's smallest rotation taking heading a to b, applied to v: by the arcsine of |a x b|.
vec3 turnedWithHeading(vec3 a, vec3 b, vec3 v, float least) {
    vec3 axis = cross(a, b);
    float s = length(axis);
    if (!(s > least)) return v;
    return rotateAbout(v, axis / s, asin(min(s, 1.0)));
}

vec2 radiusTangent(uint j, uint k) {
    float radians = paramAt(j, k, 0.0) * (3.14159265358979 / 180.0), l = paramAt(j, k + 1u, 0.0);
    return vec2(cos(radians) * l, sin(radians) * l);
}

// The control point the turtle makes at module m (state s): the settings `@#`, `@Gt` and `@Gr` made before it.
CylinderPoint controlPointAt(uint m, TurtleState s, TurtleSpecies sp) {
    CylinderPoint p;
    p.position = s.position.xyz;
    p.heading = s.heading.xyz;
    p.left = s.left.xyz;
    p.up = -s.up.xyz;
    p.width = s.heading.w;
    p.contour = 0u;
    uint j = contourSetters[m];
    if (j != kNoModule) { // an id no `contour:` line gives selects the circle
        float id = paramAt(j, 0u, 0.0);
        uint stride = cylinderSides(sp) + 1u;
        for (uint k = 1u; k < cylinderContours(sp); ++k)
            if (contourRings[sp.contourFirst + k * stride].w == id) {
                p.contour = k;
                break;
            }
    }
    p.tangents = vec2(1.2); // cpfg's before any `@Gt`
    j = tangentSetters[m];
    if (j != kNoModule) p.tangents = vec2(paramAt(j, 0u, 0.0), paramAt(j, 1u, paramAt(j, 0u, 0.0)));
    j = radiusScaleSetters[m];
    p.scaleRadius = j != kNoModule ? paramAt(j, 0u, 0.0) : 0.0;
    p.radiusIn = vec2(0.0);
    p.radiusOut = vec2(0.0);
    j = radiusTangentSetters[m];
    if (j != kNoModule) {
        p.radiusIn = radiusTangent(j, 0u);
        p.radiusOut = paramCountAt(j) >= 4u ? radiusTangent(j, 2u) : p.radiusIn;
    }
    return p;
}

// The longest chain of control points a carried frame is followed back along: far beyond any model's.
const uint kMostCarriedPoints = 1u << 16;

// cpfg's up at control point a where the view does not twist: the cylinder's first up carried from point to point
// by the smallest rotations of the headings (turtle_cpu.cpp keeps it as it goes; here it is followed back).
vec3 carriedUp(uint a) {
    mat3 carried = mat3(1.0);
    uint j = a;
    for (uint steps = 0u; (marks[j] & kMarkCylinderStart) == 0u && steps < kMostCarriedPoints; ++steps) {
        uint previous = cylinderAnchors[j];
        if (previous == kNoModule) break;
        vec3 from = states[previous].heading.xyz, to = states[j].heading.xyz;
        carried = carried * mat3(turnedWithHeading(from, to, vec3(1, 0, 0), 0.0),
                                 turnedWithHeading(from, to, vec3(0, 1, 0), 0.0),
                                 turnedWithHeading(from, to, vec3(0, 0, 1), 0.0));
        j = previous;
    }
    return carried * -states[j].up.xyz;
}

// The roll of `to`'s frame against `from`'s carried to its heading (turtle/cylinder_mesh.cpp cylinderTwist).
float cylinderTwist(CylinderPoint from, CylinderPoint to) {
    vec3 carried = turnedWithHeading(from.heading, to.heading, from.up, 1e-6);
    float angle = asin(min(1.0, length(cross(to.up, carried))));
    if (dot(to.up, carried) < 0.0) angle = 3.14159265358979 - angle;
    if (dot(to.left, carried) < 0.0) angle = -angle;
    return angle;
}

// A ring: its contours' points (blended by `blend`, times `radius`) at x along up, y against left, z along depth.
struct CylinderRing {
    vec3 centre;
    vec3 up;
    vec3 left;
    vec3 depth;
    float radius;
    float blend;
};

vec3 contourPoint(CylinderRing r, uint first, uint second, uint k) {
    return r.radius * ((1.0 - r.blend) * contourRings[first + k].xyz + r.blend * contourRings[second + k].xyz);
}

vec3 ringVertex(CylinderRing r, uint first, uint second, uint k) {
    vec3 p = contourPoint(r, first, second, k);
    return r.centre + p.x * r.up - p.y * r.left + p.z * r.depth;
}

// The normal across the ring at point k, from its neighbours (around the seam of a closed contour, whose last
// point repeats its first); zero where the ring has no width.
vec3 ringNormal(CylinderRing r, uint first, uint second, uint k, uint sides, bool closed) {
    uint before = k > 0u ? k - 1u : (closed ? sides - 1u : 0u), after = k < sides ? k + 1u : (closed ? 1u : sides);
    vec3 along = contourPoint(r, first, second, after) - contourPoint(r, first, second, before);
    vec3 across = along.y * r.up + along.x * r.left;
    float n = length(across);
    return n > 0.0 ? across / n : vec3(0.0);
}

// A triangle and its corners' normals (organ_layout.h kTriangleOfCylinder).
void writeCylinderTriangle(inout OrganInstance o, inout uint slot, vec3 a, vec3 b, vec3 c, vec3 na, vec3 nb,
                           vec3 nc) {
    o.position = vec4(a, nc.x);
    o.heading = vec4(b, nc.y);
    o.up = vec4(c, nc.z);
    o.previousHeading = vec4(na, 0);
    o.nextHeading = vec4(nb, 0);
    instances[slot] = o;
    growPlantBounds(o.plant, o);
    ++slot;
}

// The Hermite curve between two control points and the radius curve along it, whose parameter r spaces a mesh's
// rings and a tube's pieces (turtle/cylinder_mesh.cpp's CylinderCurve).
struct CylinderCurve {
    float len;
    vec3 c0, c1, c2, c3;
    vec2 r0, r1;
    float startRadius, half_;
};

CylinderCurve cylinderCurve(CylinderPoint a, CylinderPoint b) {
    CylinderCurve c;
    c.len = length(b.position - a.position);
    vec3 t0 = a.heading * (c.len * a.tangents.y), t1 = b.heading * (c.len * b.tangents.x);
    vec3 d = a.position - b.position;
    c.c0 = a.position;
    c.c1 = t0;
    c.c2 = -3.0 * d - 2.0 * t0 - t1;
    c.c3 = 2.0 * d + t0 + t1;
    c.startRadius = 0.5 * a.width;
    c.half_ = 0.5 * (b.width - a.width);
    c.r0 = a.radiusOut;
    c.r1 = b.radiusIn;
    if (b.scaleRadius != 0.0) {
        c.r0.y *= c.len;
        c.r1.y *= c.len;
    }
    if (c.r0 == vec2(0.0)) c.r0 = vec2(1.0, c.half_);
    if (c.r1 == vec2(0.0)) c.r1 = vec2(1.0, c.half_);
    return c;
}

float curveParameter(CylinderCurve c, float r) {
    return r * c.r0.x + r * r * (3.0 - 2.0 * c.r0.x - c.r1.x) + r * r * r * (-2.0 + c.r0.x + c.r1.x);
}
vec3 curvePoint(CylinderCurve c, float t) { return ((c.c3 * t + c.c2) * t + c.c1) * t + c.c0; }
vec3 curveSlope(CylinderCurve c, float t) { return (3.0 * c.c3 * t + 2.0 * c.c2) * t + c.c1; }
float curveRadius(CylinderCurve c, float r) {
    return c.startRadius + r * c.r0.y + r * r * (3.0 * c.half_ - 2.0 * c.r0.y - c.r1.y) +
           r * r * r * (-2.0 * c.half_ + c.r0.y + c.r1.y);
}

// The mesh from control point `a` to `b` in `rings` strips of 2 `sides` triangles each, from `slot` on.
void cylinderMesh(OrganInstance o, uint slot, CylinderPoint a, CylinderPoint b, uint rings, float twist,
                  TurtleSpecies sp) {
    CylinderCurve curve = cylinderCurve(a, b);
    float len = curve.len;
    uint sides = cylinderSides(sp), stride = sides + 1u;
    uint first = sp.contourFirst + a.contour * stride, second = sp.contourFirst + b.contour * stride;
    bool closed = contourRings[first] == contourRings[first + sides] &&
                  contourRings[second] == contourRings[second + sides];

    CylinderRing previous = CylinderRing(a.position, a.up, a.left, a.heading * a.tangents.y, 0.5 * a.width, 0.0);
    float step = 1.0 / float(rings), r = step;
    for (uint k = 1u; k <= rings; ++k) {
        CylinderRing next;
        if (k == rings) {
            next = CylinderRing(b.position, b.up, b.left, b.heading * b.tangents.x, 0.5 * b.width, 1.0);
        } else {
            float t = curveParameter(curve, r);
            vec3 heading = normalize(curveSlope(curve, t));
            vec3 up = rotateAbout(turnedWithHeading(a.heading, heading, a.up, 0.0), heading, -twist * t);
            next = CylinderRing(curvePoint(curve, t), up, cross(heading, up), heading / len, curveRadius(curve, r), t);
            r += step;
        }
        // Each corner once a strip, carried on to the quad after it.
        vec3 a0 = ringVertex(previous, first, second, 0u), b0 = ringVertex(next, first, second, 0u);
        vec3 na0 = ringNormal(previous, first, second, 0u, sides, closed);
        vec3 nb0 = ringNormal(next, first, second, 0u, sides, closed);
        for (uint i = 1u; i <= sides; ++i) {
            vec3 a1 = ringVertex(previous, first, second, i), b1 = ringVertex(next, first, second, i);
            vec3 na1 = ringNormal(previous, first, second, i, sides, closed);
            vec3 nb1 = ringNormal(next, first, second, i, sides, closed);
            writeCylinderTriangle(o, slot, b0, b1, a0, nb0, nb1, na0);
            writeCylinderTriangle(o, slot, a0, b1, a1, na0, nb1, na1);
            a0 = a1;
            b0 = b1;
            na0 = na1;
            nb0 = nb1;
        }
        previous = next;
    }
}
