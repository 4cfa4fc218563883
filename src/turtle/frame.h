// The turtle's orientation and the rotations every turtle command is made of, as the turtle kernels
// compute them (compute/turtle/turtle_lib.glsl mirrors each function), so CPU and GPU agree closely.
#pragma once

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace simeco::turtle {

// Degrees to radians in float, as the turtle turns every angle given in degrees.
inline constexpr float kRadiansPerDegree = 3.14159265358979f / 180.0f;

// Heading, left and up: a right-handed frame with up = heading x left. A new turtle points up the y axis
// with left toward -x, as cpfg's does.
struct Frame {
    glm::vec3 heading{0, 1, 0};
    glm::vec3 left{-1, 0, 0};
    glm::vec3 up{0, 0, 1};
};

// Turns a toward b by `radians` in their common plane: a' = a cos + b sin, b' = b cos - a sin.
inline void turnToward(glm::vec3& a, glm::vec3& b, float radians) {
    float c = std::cos(radians), s = std::sin(radians);
    glm::vec3 na = a * c + b * s;
    glm::vec3 nb = b * c - a * s;
    a = na;
    b = nb;
}

// Rotates v about the unit axis by `radians` (Rodrigues), in float as the kernels do, or in double.
template <typename Vector>
inline Vector rotateAbout(Vector v, Vector axis, typename Vector::value_type radians) {
    using Scalar = typename Vector::value_type;
    Scalar c = std::cos(radians), s = std::sin(radians);
    return v * c + glm::cross(axis, v) * s + axis * (glm::dot(axis, v) * (Scalar(1) - c));
}

inline void rotateFrame(Frame& f, glm::vec3 axis, float radians) {
    f.heading = rotateAbout(f.heading, axis, radians);
    f.left = rotateAbout(f.left, axis, radians);
    f.up = rotateAbout(f.up, axis, radians);
}

// `$`: rolls about the heading so that left is horizontal and up is closest to the world's up (+y).
inline void rollLevel(Frame& f) {
    glm::vec3 l = glm::cross(glm::vec3(0, 1, 0), f.heading);
    float n = glm::length(l);
    if (n < 1e-6f) return; // heading vertical: every roll is level
    f.left = l / n;
    f.up = glm::cross(f.heading, f.left);
}

// cpfg's `@v`: the same plane, with cpfg's up (ours reversed) closest to the world's up.
inline void rollUpright(Frame& f) {
    glm::vec3 l = glm::cross(f.heading, glm::vec3(0, 1, 0));
    float n = glm::length(l);
    if (n < 1e-6f) return;
    f.left = l / n;
    f.up = glm::cross(f.heading, f.left);
}

// cpfg's `tropism direction:` bend after a move: the heading turns toward t's component along up, then toward its
// component along left, each by the arcsine of the elasticity times that component.
inline void bendAsCpfgDirection(Frame& f, glm::vec3 t, float elasticity) {
    if (elasticity == 0.0f) return;
    turnToward(f.heading, f.up, std::asin(std::clamp(elasticity * glm::dot(t, f.up), -1.0f, 1.0f)));
    turnToward(f.heading, f.left, std::asin(std::clamp(elasticity * glm::dot(t, f.left), -1.0f, 1.0f)));
}

// cpfg's `tropism:` lines, before every move: as `bend`, beyond a radian by cpfgTurnAngle (a negative elasticity
// turns away).
// The angle cpfg turns by for a bend or roll of x radians: x up to one radian; beyond, its quaternion (made for at
// most one) turns by 2 atan(|x| tan 0.5).
inline float cpfgTurnAngle(float x) {
    return std::abs(x) <= 1.0f ? x : std::copysign(2.0f * std::atan(std::abs(x) * std::tan(0.5f)), x);
}

inline void bendAsCpfgTropism(Frame& f, glm::vec3 t, float elasticity) {
    glm::vec3 axis = glm::cross(f.heading, t);
    float n = glm::length(axis);
    if (elasticity == 0.0f || n < 1e-6f) return;
    rotateFrame(f, axis / n, cpfgTurnAngle(elasticity * n));
}

// cpfg's torque (movements.c; w the sum of its `torque:` lines' directions times their elasticities): before each
// move, after the tropism's bend, the turtle rolls about its heading, its up turning away from w's part across the
// heading by w . L radians.
inline void rollByTorque(Frame& f, glm::vec3 w) {
    const float length = glm::length(w);
    if (!(length > 0.0f)) return;
    const glm::vec3 across = glm::cross(f.heading, w / length);
    const float a = glm::dot(w, f.left);
    if (!(glm::dot(across, across) > 1e-8f) || !(std::abs(a) >= 1e-7f)) return;
    const float angle = -cpfgTurnAngle(a);
    f.up = rotateAbout(f.up, f.heading, angle);
    f.left = rotateAbout(f.left, f.heading, angle);
}

// Tropism after a drawn segment: the heading bends toward t by elasticity * |H x t| about H x t.
inline void bend(Frame& f, glm::vec3 t, float elasticity) {
    glm::vec3 axis = glm::cross(f.heading, t);
    float n = glm::length(axis);
    if (elasticity == 0.0f || n < 1e-6f) return;
    rotateFrame(f, axis / n, elasticity * n);
}

// `@R`: heading set to h; without an up vector, the frame turns by the smallest rotation taking the old heading
// to the new one.
inline void setHeading(Frame& f, glm::vec3 h) {
    float n = glm::length(h);
    if (n < 1e-12f) return;
    h /= n;
    glm::vec3 axis = glm::cross(f.heading, h);
    float s = glm::length(axis), c = glm::dot(f.heading, h);
    if (s > 1e-6f) {
        rotateFrame(f, axis / s, std::atan2(s, c));
    } else if (c < 0) {
        rotateFrame(f, f.up, 3.14159265358979f);
    }
    f.heading = h;
}

inline void setHeadingAndUp(Frame& f, glm::vec3 h, glm::vec3 u) {
    if (glm::length(h) < 1e-12f || glm::length(u) < 1e-12f) return;
    h = glm::normalize(h);
    glm::vec3 l = glm::cross(u, h);
    if (glm::length(l) < 1e-6f) return setHeading(f, h);
    f.heading = h;
    f.left = glm::normalize(l);
    f.up = glm::cross(h, f.left);
}

// cpfg's tangent parameters before any `@Gt`: a generalized cylinder's tangents are 1.2 times its chord.
inline constexpr float kTubeTangentParameter = 1.2f;

// The point at t in [0, 1] of the cubic Hermite curve from p0 to p1 whose tangents are the unit headings h0
// and h1 scaled by the chord's length times cpfg's tangent parameter: how a generalized cylinder bends between
// two control points.
inline glm::vec3 tubeCurve(glm::vec3 p0, glm::vec3 h0, glm::vec3 p1, glm::vec3 h1, float chord, float t) {
    float t2 = t * t, t3 = t2 * t, tangent = kTubeTangentParameter * chord;
    return p0 * (2 * t3 - 3 * t2 + 1) + h0 * (tangent * (t3 - 2 * t2 + t)) + p1 * (-2 * t3 + 3 * t2) +
           h1 * (tangent * (t3 - t2));
}

} // namespace simeco::turtle
