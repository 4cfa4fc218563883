// The turtle's rotations (mirroring turtle/frame.h function by function, so the CPU and GPU turtles agree
// closely), and how TurtleSteps compose and apply to a TurtleState. Needs shared/turtle_state_layout.h.

struct Frame {
    vec3 heading;
    vec3 left;
    vec3 up;
};

// Turns a toward b by `radians` in their common plane.
void turnToward(inout vec3 a, inout vec3 b, float radians) {
    float c = cos(radians), s = sin(radians);
    vec3 na = a * c + b * s;
    vec3 nb = b * c - a * s;
    a = na;
    b = nb;
}

vec3 rotateAbout(vec3 v, vec3 axis, float radians) {
    float c = cos(radians), s = sin(radians);
    return v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1.0 - c));
}

void rotateFrame(inout Frame f, vec3 axis, float radians) {
    f.heading = rotateAbout(f.heading, axis, radians);
    f.left = rotateAbout(f.left, axis, radians);
    f.up = rotateAbout(f.up, axis, radians);
}

void rollLevel(inout Frame f) {
    vec3 l = cross(vec3(0, 1, 0), f.heading);
    float n = length(l);
    if (n < 1e-6) return;
    f.left = l / n;
    f.up = cross(f.heading, f.left);
}

void rollUpright(inout Frame f) {
    vec3 l = cross(f.heading, vec3(0, 1, 0));
    float n = length(l);
    if (n < 1e-6) return;
    f.left = l / n;
    f.up = cross(f.heading, f.left);
}

void bendAsCpfgDirection(inout Frame f, vec3 t, float elasticity) {
    if (elasticity == 0.0) return;
    turnToward(f.heading, f.up, asin(clamp(elasticity * dot(t, f.up), -1.0, 1.0)));
    turnToward(f.heading, f.left, asin(clamp(elasticity * dot(t, f.left), -1.0, 1.0)));
}

// turtle/frame.h's cpfgTurnAngle: x up to one radian, beyond it 2 atan(|x| tan 0.5).
float cpfgTurnAngle(float x) { return abs(x) <= 1.0 ? x : sign(x) * (2.0 * atan(abs(x) * tan(0.5))); }

void bendAsCpfgTropism(inout Frame f, vec3 t, float elasticity) {
    vec3 axis = cross(f.heading, t);
    float n = length(axis);
    if (elasticity == 0.0 || n < 1e-6) return;
    rotateFrame(f, axis / n, cpfgTurnAngle(elasticity * n));
}

// turtle/frame.h's rollByTorque: about the heading, up turning away from w's part across it by w . L radians.
void rollByTorque(inout Frame f, vec3 w) {
    float len = length(w);
    if (!(len > 0.0)) return;
    vec3 across = cross(f.heading, w / len);
    float a = dot(w, f.left);
    if (!(dot(across, across) > 1e-8) || !(abs(a) >= 1e-7)) return;
    float angle = -cpfgTurnAngle(a);
    f.up = rotateAbout(f.up, f.heading, angle);
    f.left = rotateAbout(f.left, f.heading, angle);
}

void bend(inout Frame f, vec3 t, float elasticity) {
    vec3 axis = cross(f.heading, t);
    float n = length(axis);
    if (elasticity == 0.0 || n < 1e-6) return;
    rotateFrame(f, axis / n, elasticity * n);
}

void setHeading(inout Frame f, vec3 h) {
    float n = length(h);
    if (n < 1e-12) return;
    h /= n;
    vec3 axis = cross(f.heading, h);
    float s = length(axis), c = dot(f.heading, h);
    if (s > 1e-6) {
        rotateFrame(f, axis / s, atan(s, c));
    } else if (c < 0.0) {
        rotateFrame(f, f.up, 3.14159265358979);
    }
    f.heading = h;
}

void setHeadingAndUp(inout Frame f, vec3 h, vec3 u) {
    if (length(h) < 1e-12 || length(u) < 1e-12) return;
    h = normalize(h);
    vec3 l = cross(u, h);
    if (length(l) < 1e-6) {
        setHeading(f, h);
        return;
    }
    f.heading = h;
    f.left = normalize(l);
    f.up = cross(h, f.left);
}

// turtle/frame.h's tubeCurve: tangents 1.2 times the chord, cpfg's tangent parameters before any `@Gt`.
vec3 tubeCurve(vec3 p0, vec3 h0, vec3 p1, vec3 h1, float chord, float t) {
    float t2 = t * t, t3 = t2 * t, tangent = 1.2 * chord;
    return p0 * (2.0 * t3 - 3.0 * t2 + 1.0) + h0 * (tangent * (t3 - 2.0 * t2 + t)) + p1 * (-2.0 * t3 + 3.0 * t2) +
           h1 * (tangent * (t3 - t2));
}

// Segments of the tube a cylinder point with parameter `requested` draws.
uint tubeSegments(float requested) { return uint(clamp(floor(requested + 0.5), 1.0, float(kTubeMaxSegments))); }

Frame frameOf(TurtleState s) { return Frame(s.heading.xyz, s.left.xyz, s.up.xyz); }

void setFrame(inout TurtleState s, Frame f) {
    s.heading.xyz = f.heading;
    s.left.xyz = f.left;
    s.up.xyz = f.up;
}

TurtleStep identityStep() {
    TurtleStep t;
    t.heading = vec4(1, 0, 0, 0);
    t.left = vec4(0, 1, 0, 0);
    t.up = vec4(0, 0, 1, 0);
    t.translation = vec4(0);
    t.scaledTranslation = vec4(0);
    t.widthColor = vec4(1, 0, 1, 0);
    t.scaleElasticity = vec4(1, 0, 1, 0);
    return t;
}

mat3 rotationOf(TurtleStep t) { return mat3(t.heading.xyz, t.left.xyz, t.up.xyz); }

// x -> a x + b after x -> a0 x + b0.
vec2 thenAffine(vec2 first, vec2 second) { return vec2(first.x * second.x, second.x * first.y + second.y); }

// `first`, then `second` (relative to the state `first` leaves).
TurtleStep composeSteps(TurtleStep first, TurtleStep second) {
    mat3 r = rotationOf(first);
    float scaleA = first.scaleElasticity.x, scaleB = first.scaleElasticity.y;
    TurtleStep t;
    t.heading = vec4(r * second.heading.xyz, 0);
    t.left = vec4(r * second.left.xyz, 0);
    t.up = vec4(r * second.up.xyz, 0);
    // translation.w: the width's share of the scale before the step (width -> a width + b + c scale).
    float widthScaled = second.widthColor.x * first.translation.w + second.translation.w * scaleA;
    float widthOffset = second.translation.w * scaleB;
    t.translation = vec4(first.translation.xyz + r * (second.translation.xyz + scaleB * second.scaledTranslation.xyz),
                         widthScaled);
    t.scaledTranslation = vec4(first.scaledTranslation.xyz + scaleA * (r * second.scaledTranslation.xyz), 0);
    t.widthColor = vec4(thenAffine(first.widthColor.xy, second.widthColor.xy) + vec2(0.0, widthOffset),
                        thenAffine(first.widthColor.zw, second.widthColor.zw));
    t.scaleElasticity = vec4(thenAffine(first.scaleElasticity.xy, second.scaleElasticity.xy),
                             thenAffine(first.scaleElasticity.zw, second.scaleElasticity.zw));
    return t;
}

TurtleState applyStep(TurtleState s, TurtleStep t) {
    mat3 frame = mat3(s.heading.xyz, s.left.xyz, s.up.xyz);
    float scale = s.up.w;
    TurtleState r;
    r.position.xyz = s.position.xyz + frame * (t.translation.xyz + scale * t.scaledTranslation.xyz);
    r.heading.xyz = frame * t.heading.xyz;
    r.left.xyz = frame * t.left.xyz;
    r.up.xyz = frame * t.up.xyz;
    r.heading.w = t.widthColor.x * s.heading.w + t.widthColor.y + t.translation.w * scale;
    r.left.w = t.widthColor.z * s.left.w + t.widthColor.w;
    r.up.w = t.scaleElasticity.x * scale + t.scaleElasticity.y;
    r.position.w = t.scaleElasticity.z * s.position.w + t.scaleElasticity.w;
    return r;
}

// A rotation step that turns axis a toward axis b (0 heading, 1 left, 2 up) by `radians`.
TurtleStep turnStep(int a, int b, float radians) {
    vec3 columns[3] = vec3[3](vec3(1, 0, 0), vec3(0, 1, 0), vec3(0, 0, 1));
    turnToward(columns[a], columns[b], radians);
    TurtleStep t = identityStep();
    t.heading.xyz = columns[0];
    t.left.xyz = columns[1];
    t.up.xyz = columns[2];
    return t;
}

// Floats as order-preserving ints, so that integer min/max atomics order them (draw/bounds.h).
int boundsKey(float value) {
    int bits = floatBitsToInt(value);
    return bits >= 0 ? bits : bits ^ 0x7FFFFFFF;
}

float boundsValue(int key) { return intBitsToFloat(key >= 0 ? key : key ^ 0x7FFFFFFF); }
