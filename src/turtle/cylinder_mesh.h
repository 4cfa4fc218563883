// cpfg's generalized cylinders drawn as meshes (`line style: cylinder`): between two control points, rings of the
// contours the points select, placed along the Hermite curve their headings and tangent settings describe, their
// radius along the curve the points' radius settings give, joined by strips of triangles.
#pragma once

#include <functional>
#include <vector>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include "turtle/frame.h"

namespace simeco::turtle {

// A control point as cpfg keeps it: where the turtle was, its frame (with the roll cpfg carries along the cylinder
// where the view does not twist it), its width and the settings `@#`, `@Gt` and `@Gr` had made.
struct CylinderPoint {
    glm::vec3 position{0.0f};
    Frame frame;
    float width = 0.0f;
    uint32_t contour = 0;                        // index into the species' contours, 0 the circle
    glm::vec2 tangents{kTubeTangentParameter};   // into this point (x) and out of it (y), times the chord
    glm::vec2 radiusIn{0.0f}, radiusOut{0.0f};   // the radius curve's tangents into and out of it; zero: linear
    float scaleRadius = 0.0f;                    // non-zero: the tangents' radius parts are per unit of the chord
};

// `@Gr(s)` sets whether the radius tangents scale with the chord; `@Gr(a1, l1[, a2, l2])` the tangents, angles in
// degrees and lengths (a1, l1 into the point and out of it, unless a2, l2 give the latter).
void setRadiusTangents(CylinderPoint& p, const std::vector<float>& params);

// The roll of the frame the turtle brought to `to` against the one carried from `from` by the smallest rotation
// of its heading: what `twist of cylinders: on` spreads along the cylinder.
float cylinderTwist(const CylinderPoint& from, const CylinderPoint& to);

// `to`'s frame with the roll of `from`'s carried to its heading: what cpfg keeps where the view does not twist.
Frame carriedFrame(const Frame& from, const Frame& to);

// The Hermite curve between two control points and the radius curve along it, whose parameter r spaces a mesh's
// rings and a tube's pieces; cpfg's coefficients, in float as it keeps them.
class CylinderCurve {
public:
    CylinderCurve(const CylinderPoint& a, const CylinderPoint& b);
    double chord() const { return len_; }
    float parameterAt(float r) const; // the curve's t at the radius curve's r
    glm::vec3 pointAt(float t) const;
    glm::vec3 slopeAt(float t) const;
    float radiusAt(float r) const;

private:
    double len_;
    glm::vec3 c0_, c1_, c2_, c3_;
    glm::vec2 r0_, r1_;
    float startRadius_, half_;
};

// The points inside a tube of `pieces` pieces from a to b, where cpfg's pixel and polygon line styles draw a
// generalized cylinder: at r = k / pieces for k = 1 .. pieces - 1, as a mesh's rings.
std::vector<glm::vec3> tubePoints(const CylinderPoint& a, const CylinderPoint& b, int pieces);

// A mesh's corner: where it is and the normal across the cylinder's surface there (zero where the ring has no
// width to turn about).
struct MeshCorner {
    glm::vec3 position{0.0f};
    glm::vec3 normal{0.0f};
};

// The triangles from `a` to `b` in `rings` strips, each contour's ring at `contourRings[k * (sides + 1)]`, to
// `triangle(c0, c1, c2)` in cpfg's order. Draws nothing where the points lie closer than `shortest`.
void cylinderMesh(const CylinderPoint& a, const CylinderPoint& b, int rings, float twist, int sides,
                  const std::vector<glm::vec3>& contourRings, float shortest,
                  const std::function<void(const MeshCorner&, const MeshCorner&, const MeshCorner&)>& triangle);

} // namespace simeco::turtle
