// An organ instance's bounding box (turtle/turtle_cpu.cpp's organBounds) and where plant p stands in the
// field (turtle/interpretation.cpp's fieldCell). Needs shared/organ_layout.h.

struct Box {
    vec3 lo;
    vec3 hi;
};

void addPoint(inout Box b, vec3 p, float radius) {
    b.lo = min(b.lo, p - radius);
    b.hi = max(b.hi, p + radius);
}

// Whether every float of the organ is finite (turtle/finite_organs.h), tested on the bits, which no driver may
// assume away as it may assume a float is never infinite or NaN.
bool finiteBits(vec4 v) {
    return all(notEqual(floatBitsToUint(v) & uvec4(0x7F800000u), uvec4(0x7F800000u)));
}

bool organIsFinite(OrganInstance o) {
    return finiteBits(o.position) && finiteBits(o.heading) && finiteBits(o.up) && finiteBits(o.color) &&
           finiteBits(o.previousHeading) && finiteBits(o.nextHeading);
}

Box organBox(OrganInstance o) {
    if (!organIsFinite(o)) { // infinite bounds, which the outputs refuse
        float infinity = uintBitsToFloat(0x7F800000u);
        return Box(vec3(-infinity), vec3(infinity));
    }
    Box b = Box(vec3(1e30), vec3(-1e30));
    vec3 p = o.position.xyz, h = o.heading.xyz;
    if (o.kind == kOrganStem) {
        float r = o.shape == kLinePixel ? 0.0 : max(o.heading.w, o.up.w); // a pixel line's width is the picture's
        addPoint(b, p, r);
        addPoint(b, p + h * o.position.w, r);
    } else if (o.kind == kOrganLeaf && o.previousHeading.w == kLeafAroundBase) { // at most its largest scale away
        addPoint(b, p, max(o.position.w, max(o.heading.w, o.up.w)));
    } else if (o.kind == kOrganLeaf) {
        addPoint(b, p, 0.5 * o.heading.w);
        addPoint(b, p + h * o.position.w, 0.5 * o.heading.w);
    } else if (o.kind == kOrganTriangle) {
        addPoint(b, p, 0.0);
        addPoint(b, h, 0.0);
        addPoint(b, o.up.xyz, 0.0);
    } else {
        addPoint(b, p, o.heading.w);
    }
    return b;
}

// Columns of the field's grid: the smallest c with c * c >= plants, in integers so every device agrees.
uint fieldColumns(uint plants) {
    uint p = max(plants, 1u);
    uint c = uint(sqrt(float(p)));
    while (c * c < p) ++c;
    while (c > 1u && (c - 1u) * (c - 1u) >= p) --c;
    return c;
}

// A plant's point or direction in the field (shared/organ_layout.h's PlantPlacement; turtle_cpu.cpp does the same).
vec3 turnDirection(PlantPlacement m, vec3 v) { return vec3(dot(m.x.xyz, v), dot(m.y.xyz, v), dot(m.z.xyz, v)); }
vec3 placePoint(PlantPlacement m, vec3 p) { return turnDirection(m, p) + vec3(m.x.w, m.y.w, m.z.w); }
// A direction of the field turned into the plant's own frame (turnDirection's inverse: the rotation's transpose).
vec3 turnIntoPlant(PlantPlacement m, vec3 v) { return v.x * m.x.xyz + v.y * m.y.xyz + v.z * m.z.xyz; }

vec3 fieldCell(uint plant, uint plants) {
    uint columns = fieldColumns(plants);
    uint rows = (max(plants, 1u) + columns - 1u) / columns;
    float x = float(plant % columns) - 0.5 * float(columns - 1u);
    float z = float(plant / columns) - 0.5 * float(rows - 1u);
    return vec3(x, 0.0, z);
}
