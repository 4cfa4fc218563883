#include "turtle/turtle_cpu.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <glm/geometric.hpp>

#include "compute/shared/turtle_layout.h"
#include "compute/shared/turtle_state_layout.h"
#include "turtle/cylinder_mesh.h"
#include "turtle/finite_organs.h"
#include "turtle/frame.h"
#include "turtle/turtle_commands.h"

namespace simeco::turtle {

using namespace shared;

namespace {

constexpr float kDegrees = kRadiansPerDegree;

struct TurtleState {
    Frame frame;
    glm::vec3 position{0.0f};
    float width = 1.0f; // in world units: `!` and `#` apply the scale when they set it
    float color = 1.0f;
    float scale = 1.0f;
    float elasticity = 0.0f;
    // The last stem segment this branch drew, while the next one continues it (no move or branch between).
    int64_t lastStem = -1;
    // The generalized cylinder's last control point, when one is open, and the settings `@#`, `@Gt` and `@Gr`
    // made for the next one.
    bool cylinderOpen = false;
    CylinderPoint anchor;
    CylinderPoint cylinderSettings;
    int64_t lastTube = -1;
    // The last segment drawn while its end narrows (cpfg's tapered lines): until the next command that ends it.
    int64_t tapering = -1;
};

// Commands after which a tapering segment's end keeps the width it has (kEndsTaper in compute/turtle/taper.comp).
bool endsTaper(uint32_t command) {
    return command == kTurtleBranchOpen || command == kTurtleBranchClose || turtleDraws(command) ||
           turtleMovesOnly(command) || command == kTurtleSetPosition;
}

shared::vec4 v4(glm::vec3 v, float w) { return {v.x, v.y, v.z, w}; }

// cpfg's strips of a mesh's stretch: as many as `@Gc(n)` asks (n truncated, at least one), four without n.
int cylinderRings(bool given, float requested) {
    if (!given) return 4;
    if (!(requested >= 1.0f)) return 1;
    return int(std::min(std::trunc(requested), float(kTubeMaxSegments)));
}

uint32_t tubeSegments(float requested) {
    return uint32_t(std::clamp(std::floor(requested + 0.5f), 1.0f, float(kTubeMaxSegments)));
}
glm::vec3 v3(const shared::vec4& v) { return {v.x, v.y, v.z}; }

// An up vector for a segment along `heading`: the turtle's up with its heading component removed.
glm::vec3 perpendicularUp(glm::vec3 heading, const Frame& f) {
    glm::vec3 u = f.up - heading * glm::dot(f.up, heading);
    if (glm::length(u) < 1e-6f) u = f.left - heading * glm::dot(f.left, heading);
    return glm::normalize(u);
}

// Walks one plant's modules [begin, end) and calls visit(i, command, state after it) for each; organs go
// to `organs` (plant-local positions).
class PlantTurtle {
public:
    PlantTurtle(const stream::ModuleString& s, const TurtleCommands& commands, const TurtleSettings& t,
                uint32_t plant, std::vector<OrganInstance>& organs)
        : s_(s), commands_(commands), t_(t), plant_(plant), organs_(organs) {}

    template <typename Visit>
    void walk(size_t begin, size_t end, Visit visit) {
        TurtleState state;
        state.width = t_.width;
        state.color = t_.initialColor;
        state.elasticity = t_.elasticity;
        state.scale = t_.initialScale;
        std::vector<TurtleState> stack;
        calls_.clear();
        for (size_t i = begin; i < end; ++i) {
            uint32_t command = commands_.commandAt(s_, begin, end, i);
            if (endsTaper(command)) endTaper(state);
            if (command == kTurtleBranchOpen) {
                stack.push_back(state);
                state.lastStem = -1;
                state.lastTube = -1;
            } else if (command == kTurtleBranchClose) {
                if (!stack.empty()) {
                    state = stack.back();
                    stack.pop_back();
                }
            } else {
                apply(state, command, i);
            }
            visit(i, command, state);
        }
        endTaper(state);
    }

private:
    const stream::ModuleString& s_;
    const TurtleCommands& commands_;
    const TurtleSettings& t_;
    uint32_t plant_;
    std::vector<float> calls_; // the scales of the sub-L-system calls the walk is in, innermost last
    std::vector<OrganInstance>& organs_;
    std::vector<std::vector<glm::vec3>> polygons_;

    float param(size_t i, size_t k, float otherwise) const {
        return s_.paramCount[i] > k ? s_.paramsOf(i)[k] : otherwise;
    }
    bool hasParam(size_t i) const { return s_.paramCount[i] > 0; }
    float angle(size_t i) const { return param(i, 0, t_.angleDegrees) * kDegrees; }

    OrganInstance& emit(uint32_t kind, size_t module, const TurtleState& st) {
        OrganInstance o{};
        o.kind = kind;
        o.plant = plant_;
        o.module = uint32_t(module);
        glm::vec4 c = t_.color(st.color);
        o.color = {c.r, c.g, c.b, c.a};
        organs_.push_back(o);
        return organs_.back();
    }

    // cpfg's tapered lines: a segment narrows from the width it was drawn with to the width set before the command
    // that ends it (a branch, the next segment or move, the plant's end).
    void endTaper(TurtleState& st) {
        if (st.tapering >= 0) organs_[size_t(st.tapering)].up.w = 0.5f * st.width;
        st.tapering = -1;
    }

    void polygonVertex(size_t module, const TurtleState& st) {
        std::vector<glm::vec3>& polygon = polygons_.back();
        polygon.push_back(st.position);
        if (polygon.size() < 3) return;
        OrganInstance& o = emit(kOrganTriangle, module, st);
        o.position = v4(polygon.front(), 0);
        o.heading = v4(polygon[polygon.size() - 2], 0);
        o.up = v4(polygon.back(), 0);
    }

    void drawStem(TurtleState& st, size_t module, float length) {
        float radius = 0.5f * st.width;
        OrganInstance& o = emit(kOrganStem, module, st);
        o.position = v4(st.position, length);
        o.heading = v4(st.frame.heading, radius);
        o.up = v4(st.frame.up, radius);
        o.shape = lineStyleCode(t_.lineStyle);
        int64_t index = int64_t(organs_.size()) - 1;
        if (t_.taperedLines) st.tapering = index;
        if (st.lastStem >= 0) {
            o.previousHeading = v4(v3(organs_[size_t(st.lastStem)].heading), 0);
            organs_[size_t(st.lastStem)].nextHeading = v4(st.frame.heading, 0);
        }
        st.lastStem = index;
    }

    CylinderPoint controlPoint(const TurtleState& st) const {
        CylinderPoint p = st.cylinderSettings;
        p.position = st.position;
        p.frame = st.frame;
        p.width = st.width;
        return p;
    }

    // The generalized cylinder from the last control point to this one: a mesh around its contours (cpfg's
    // cylinder line style), or a tube along the curve the headings there and here describe in as many segments as
    // the point asks for, each joined to the one before.
    void cylinderPoint(TurtleState& st, size_t module) {
        if (!st.cylinderOpen) return;
        CylinderPoint here = controlPoint(st);
        const float shortest = kTubeEpsilon * (1.0f + glm::length(st.anchor.position));
        if (t_.cylinderMeshes) {
            float twist = 0.0f;
            if (t_.cylinderTwist) twist = cylinderTwist(st.anchor, here);
            else here.frame = carriedFrame(st.anchor.frame, here.frame);
            cylinderMesh(st.anchor, here, cylinderRings(hasParam(module), param(module, 0, 0.0f)), twist, t_.cylinderSides,
                         t_.contourRings, shortest,
                         [&](const MeshCorner& a, const MeshCorner& b, const MeshCorner& c) {
                             OrganInstance& o = emit(kOrganTriangle, module, st);
                             o.position = v4(a.position, c.normal.x);
                             o.heading = v4(b.position, c.normal.y);
                             o.up = v4(c.position, c.normal.z);
                             o.previousHeading = v4(a.normal, 0);
                             o.nextHeading = v4(b.normal, 0);
                             o.shape = kTriangleOfCylinder;
                         });
            st.anchor = here;
            return;
        }
        glm::vec3 chord = st.position - st.anchor.position;
        float length = glm::length(chord);
        if (length > shortest) {
            // cpfg's (general.c): `@Gc(n)`'s n pieces (four without n) through the points a mesh's rings would
            // have, as wide as the last control point, the last piece narrowing to this one's where polygons taper.
            const bool cpfg = t_.cpfgTubes;
            const uint32_t segments = cpfg ? uint32_t(cylinderRings(hasParam(module), param(module, 0, 0.0f)))
                                           : tubeSegments(param(module, 0, 1.0f));
            const std::vector<glm::vec3> inner =
                cpfg ? tubePoints(st.anchor, here, int(segments)) : std::vector<glm::vec3>{};
            const float r0 = 0.5f * st.anchor.width, r1 = 0.5f * st.width;
            const bool lastTapers = t_.lineStyle == ir::LineStyle::Polygon && t_.taperedLines;
            glm::vec3 from = st.anchor.position;
            for (uint32_t k = 0; k < segments; ++k) {
                float t0 = float(k) / float(segments), t1 = float(k + 1) / float(segments);
                glm::vec3 to = k + 1 == segments ? st.position
                               : cpfg            ? inner[k]
                                                 : tubeCurve(st.anchor.position, st.anchor.frame.heading, st.position,
                                                             st.frame.heading, length, t1);
                glm::vec3 d = to - from;
                float l = glm::length(d);
                glm::vec3 heading = l > 0.0f ? d / l : chord / length;
                OrganInstance& o = emit(kOrganStem, module, st);
                o.position = v4(from, l);
                if (cpfg) {
                    o.heading = v4(heading, r0);
                    o.up = v4(perpendicularUp(heading, st.frame), k + 1 == segments && lastTapers ? r1 : r0);
                    o.shape = lineStyleCode(t_.lineStyle);
                } else {
                    o.heading = v4(heading, r0 + (r1 - r0) * t0);
                    o.up = v4(perpendicularUp(heading, st.frame), r0 + (r1 - r0) * t1);
                }
                int64_t index = int64_t(organs_.size()) - 1;
                if (st.lastTube >= 0) {
                    o.previousHeading = v4(v3(organs_[size_t(st.lastTube)].heading), 0);
                    organs_[size_t(st.lastTube)].nextHeading = v4(heading, 0);
                }
                st.lastTube = index;
                from = to;
            }
        }
        st.anchor = here;
    }

    void move(TurtleState& st, size_t i, uint32_t command) {
        const bool draw = turtleDraws(command);
        if (t_.tropismRule == ir::TropismRule::CpfgTropism) bendAsCpfgTropism(st.frame, t_.tropism, st.elasticity);
        rollByTorque(st.frame, t_.torque);
        float length = param(i, 0, t_.step) * st.scale;
        if (draw) drawStem(st, i, length);
        else st.lastStem = -1;
        st.position += st.frame.heading * length;
        if (t_.tropismRule == ir::TropismRule::CpfgDirection) bendAsCpfgDirection(st.frame, t_.tropism, st.elasticity);
        else if (draw && t_.tropismRule == ir::TropismRule::Torque) bend(st.frame, t_.tropism, st.elasticity);
        if (!polygons_.empty() && turtleAddsVertex(command)) polygonVertex(i, st);
    }

    void apply(TurtleState& st, uint32_t command, size_t i) {
        Frame& f = st.frame;
        switch (command) {
        case kTurtleDraw:
        case kTurtleDrawNoVertex:
        case kTurtleMove:
        case kTurtleMoveNoVertex: move(st, i, command); break;
        case kTurtleTurnLeft: turnToward(f.heading, f.left, angle(i)); break;
        case kTurtleTurnRight: turnToward(f.heading, f.left, -angle(i)); break;
        case kTurtlePitchDown: turnToward(f.heading, f.up, -angle(i)); break;
        case kTurtlePitchUp: turnToward(f.heading, f.up, angle(i)); break;
        // cpfg's up is ours reversed (L x H where ours is H x L): its roll left `\` turns its up toward left, so
        // ours turns away from it.
        case kTurtleRollLeft: turnToward(f.up, f.left, -angle(i)); break;
        case kTurtleRollRight: turnToward(f.up, f.left, angle(i)); break;
        case kTurtleTurnAround:
            f.heading = -f.heading;
            f.left = -f.left;
            break;
        case kTurtleRollLevel:
            if (t_.dollarRolls) {
                rollLevel(f);
            } else if (t_.subLsystems) { // cpfg's `$`: the return from a sub-L-system call, to the caller's scale
                const float back = 1.0f / (calls_.empty() ? 1.0f : calls_.back());
                if (!calls_.empty()) calls_.pop_back();
                st.scale *= back;
                st.width *= back;
            }
            break;
        // A sub-L-system's lengths and widths are its call's scale times the caller's, until its `$`. The calls
        // nest in the string's order, which branches do not change.
        case kTurtleSubLsystemCall:
            if (hasParam(i) && t_.subLsystems) {
                const float s = param(i, 1, 1.0f);
                calls_.push_back(s != 0.0f && std::isfinite(s) ? s : 1.0f); // compute/turtle's callScale
                st.scale *= calls_.back();
                st.width *= calls_.back();
            }
            break;
        case kTurtleRollUpright: rollUpright(f); break;
        case kTurtlePitchRadians: turnToward(f.heading, f.up, -param(i, 0, 0)); break;
        case kTurtleRollRadians: turnToward(f.up, f.left, param(i, 0, 0)); break;
        case kTurtleTilt:
            turnToward(f.up, f.left, param(i, 1, 0));
            turnToward(f.heading, f.up, -param(i, 0, 0));
            turnToward(f.up, f.left, -param(i, 1, 0));
            break;
        case kTurtleRotateWorldX: rotateFrame(f, {1, 0, 0}, param(i, 0, 0)); break;
        case kTurtleRotateWorldY: rotateFrame(f, {0, 1, 0}, param(i, 0, 0)); break;
        case kTurtleRotateWorldZ: rotateFrame(f, {0, 0, 1}, param(i, 0, 0)); break;
        // As in cpfg, a width is set in the scale of its time: `@D` scales the widths `!` and `#` set after it.
        case kTurtleWidthUp:
            st.width = hasParam(i) ? param(i, 0, 0) * st.scale : st.width + t_.widthIncrement * st.scale;
            break;
        case kTurtleWidthDown:
            st.width = hasParam(i) ? param(i, 0, 0) * st.scale : st.width - t_.widthIncrement * st.scale;
            break;
        case kTurtleColorUp: st.color = hasParam(i) ? param(i, 0, 0) : st.color + t_.colorIncrement; break;
        case kTurtleColorDown: st.color = hasParam(i) ? param(i, 0, 0) : st.color - t_.colorIncrement; break;
        case kTurtleScaleSet: st.scale = param(i, 0, st.scale); break;
        case kTurtleScaleUp:
        case kTurtleAlive: st.scale *= param(i, 0, 1.0f); break;
        case kTurtleScaleDown: st.scale /= (param(i, 0, 1.0f) != 0.0f ? param(i, 0, 1.0f) : 1.0f); break;
        case kTurtleElasticitySet: st.elasticity = param(i, 1, st.elasticity); break;
        case kTurtleElasticityUp: st.elasticity += param(i, 1, t_.elasticityIncrement); break;
        case kTurtleElasticityDown: st.elasticity -= param(i, 1, t_.elasticityIncrement); break;
        case kTurtleTropism: st.elasticity = param(i, 0, st.elasticity); break;
        case kTurtleElasticityStep:
            st.elasticity = hasParam(i) ? param(i, 0, 0) : st.elasticity + t_.elasticityIncrement;
            break;
        case kTurtlePhototropism: {
            const glm::vec3 d(param(i, 1, 0), param(i, 2, 0), param(i, 3, 0));
            if (glm::length(d) > 0.0f) bend(f, glm::normalize(d), param(i, 0, 0));
            break;
        }
        case kTurtleSetPosition:
            st.position = {param(i, 0, st.position.x), param(i, 1, st.position.y), param(i, 2, st.position.z)};
            st.lastStem = -1;
            break;
        case kTurtleSetHeading:
            if (s_.paramCount[i] >= 6)
                setHeadingAndUp(f, {param(i, 0, 0), param(i, 1, 0), param(i, 2, 0)},
                                {param(i, 3, 0), param(i, 4, 0), param(i, 5, 0)});
            else if (s_.paramCount[i] >= 3)
                setHeading(f, {param(i, 0, 0), param(i, 1, 0), param(i, 2, 0)});
            break;
        case kTurtleSphere:
        case kTurtleDisc:
        case kTurtleDiscFacing: {
            float radius = 0.5f * (hasParam(i) ? param(i, 0, 0) * st.scale : st.width);
            uint32_t kind = command == kTurtleSphere ? kOrganSphere : kOrganDisc;
            OrganInstance& o = emit(kind, i, st);
            o.position = v4(st.position, 0);
            o.heading = v4(f.heading, radius);
            o.up = v4(f.up, radius);
            o.shape = command == kTurtleDiscFacing ? kDiscFacesViewer : 0u;
            break;
        }
        case kTurtleSurface: {
            // `~id(s)` scales the surface by s, `~id(sx, sy, sz)` across, along and out of it (cpfg's order: left,
            // heading, up); then the turtle moves to the surface's end point, scaled by the first.
            const uint32_t id = s_.sym[i];
            if (t_.surfaceDrawn[id] == kSurfaceNone) break;
            const float first = param(i, 0, 1.0f);
            const bool three = s_.paramCount[i] >= 3;
            const float scale = t_.surfaceScale[id] * st.scale;
            OrganInstance& o = emit(kOrganLeaf, i, st);
            o.position = v4(st.position, (three ? param(i, 1, 1.0f) : first) * scale);
            o.heading = v4(f.heading, first * scale);
            o.up = v4(f.up, (three ? param(i, 2, 1.0f) : first) * scale);
            o.shape = t_.surfaceShape[id];
            o.previousHeading.w = t_.surfaceDrawn[id] == kSurfaceAroundBase ? kLeafAroundBase : 0.0f;
            const glm::vec3 end = t_.surfaceEnd[id];
            if (end != glm::vec3(0.0f)) {
                st.position += first * st.scale * (end.x * f.heading + end.y * f.left + end.z * f.up);
                st.lastStem = -1;
            }
            break;
        }
        case kTurtlePolygonBegin: // `{(type)` starts a generalized cylinder, `{` a polygon
            if (hasParam(i)) apply(st, kTurtleCylinderStart, i);
            else polygons_.emplace_back();
            break;
        case kTurtlePolygonEnd:
            if (hasParam(i)) apply(st, kTurtleCylinderPoint, i);
            else if (!polygons_.empty()) polygons_.pop_back();
            break;
        case kTurtlePolygonVertex:
            if (!polygons_.empty()) polygonVertex(i, st);
            break;
        case kTurtleCylinderStart:
            st.cylinderOpen = true;
            st.anchor = controlPoint(st);
            st.lastTube = -1;
            break;
        case kTurtleContour: {
            // An id no `contour:` line gives selects the circle, as in cpfg.
            const float id = param(i, 0, 0.0f);
            st.cylinderSettings.contour = 0;
            for (size_t k = 1; k < t_.contourIds.size(); ++k)
                if (float(t_.contourIds[k]) == id) {
                    st.cylinderSettings.contour = uint32_t(k);
                    break;
                }
            break;
        }
        case kTurtleCylinderTangents:
            if (hasParam(i)) st.cylinderSettings.tangents = {param(i, 0, 0.0f), param(i, 1, param(i, 0, 0.0f))};
            break;
        case kTurtleRadiusTangents: {
            std::vector<float> params(s_.paramsOf(i), s_.paramsOf(i) + s_.paramCount[i]);
            setRadiusTangents(st.cylinderSettings, params);
            break;
        }
        case kTurtleCylinderPoint: cylinderPoint(st, i); break;
        default: break;
        }
    }
};


void translate(OrganInstance& o, glm::vec3 d) {
    o.position.x += d.x, o.position.y += d.y, o.position.z += d.z;
    if (o.kind == kOrganTriangle) {
        o.heading.x += d.x, o.heading.y += d.y, o.heading.z += d.z;
        o.up.x += d.x, o.up.y += d.y, o.up.z += d.z;
    }
}

void turnDirection(const shared::PlantPlacement& m, shared::vec4& v) {
    glm::vec3 t = turtle::turnDirection(m, glm::vec3(v.x, v.y, v.z));
    v.x = t.x, v.y = t.y, v.z = t.z;
}

void placePoint(const shared::PlantPlacement& m, shared::vec4& p) {
    turnDirection(m, p);
    p.x += m.x.w, p.y += m.y.w, p.z += m.z.w;
}

// The organ in the field: a triangle's three vectors are its corners, every other organ's a point and directions.
void place(OrganInstance& o, const shared::PlantPlacement& m) {
    placePoint(m, o.position);
    if (o.kind == kOrganTriangle) {
        placePoint(m, o.heading);
        placePoint(m, o.up);
        if (o.shape == kTriangleOfCylinder) { // its corners' normals
            turnDirection(m, o.previousHeading);
            turnDirection(m, o.nextHeading);
            shared::vec4 n{o.position.w, o.heading.w, o.up.w, 0.0f};
            turnDirection(m, n);
            o.position.w = n.x, o.heading.w = n.y, o.up.w = n.z;
        }
        return;
    }
    turnDirection(m, o.heading);
    turnDirection(m, o.up);
    turnDirection(m, o.previousHeading);
    turnDirection(m, o.nextHeading);
}

} // namespace

Bounds organBounds(const OrganInstance& o) {
    Bounds b;
    if (!organIsFinite(o)) { // infinite bounds, which the outputs refuse (finite_organs.h)
        b.add(glm::vec3(-INFINITY));
        b.add(glm::vec3(INFINITY));
        return b;
    }
    glm::vec3 p = v3(o.position), h = v3(o.heading);
    switch (o.kind) {
    case kOrganStem: {
        // A pixel line's width is the picture's: the frame holds its ends.
        float r = o.shape == kLinePixel ? 0.0f : std::max(o.heading.w, o.up.w);
        b.add(p, r);
        b.add(p + h * o.position.w, r);
        break;
    }
    case kOrganLeaf:
        if (o.previousHeading.w == kLeafAroundBase) { // at most its largest scale from its base
            b.add(p, std::max({o.position.w, o.heading.w, o.up.w}));
            break;
        }
        b.add(p, 0.5f * o.heading.w);
        b.add(p + h * o.position.w, 0.5f * o.heading.w);
        break;
    case kOrganTriangle:
        b.add(p);
        b.add(h);
        b.add(v3(o.up));
        break;
    default: b.add(p, o.heading.w); break;
    }
    return b;
}

Interpretation interpretCpu(const stream::ModuleString& string, const TurtleCommands& commands,
                            const std::vector<TurtleSettings>& species, const FieldOptions& field) {
    Interpretation result;
    uint32_t plants = uint32_t(string.plants());
    std::vector<std::vector<OrganInstance>> perPlant(plants);
    std::vector<Bounds> plantBounds(plants);
    for (uint32_t p = 0; p < plants; ++p) {
        PlantTurtle turtle(string, commands, species[p % species.size()], p, perPlant[p]);
        turtle.walk(string.plantStart[p], string.plantStart[p + 1], [](size_t, uint32_t, const TurtleState&) {});
        for (const OrganInstance& o : perPlant[p]) plantBounds[p].add(organBounds(o));
    }
    float spacing = fieldSpacing(field, plantBounds);
    result.spacing = spacing;
    const bool placed = !field.placements.empty();
    if (placed && field.placements.size() != plants)
        throw std::invalid_argument("interpretCpu: one placement per plant");
    result.scattered = !placed && field.scattered;
    for (uint32_t p = 0; p < plants; ++p) {
        const bool turned = placed || result.scattered;
        const shared::PlantPlacement placement =
            placed ? field.placements[p] : result.scattered ? scatteredPlacement(p, plants, spacing) : PlantPlacement{};
        const glm::vec3 origin = turned ? plantOrigin(placement) : fieldCell(p, plants) * spacing;
        result.plantOrigins.push_back(origin);
        for (OrganInstance& o : perPlant[p]) {
            if (turned) place(o, placement);
            else translate(o, origin);
            result.bounds.add(organBounds(o));
            ++result.count[o.kind];
        }
    }
    for (uint32_t k = 1; k < kOrganKinds; ++k) result.first[k] = result.first[k - 1] + result.count[k - 1];
    result.organs.resize(result.first[kOrganKinds - 1] + result.count[kOrganKinds - 1]);
    // Plants in order, and each plant's organs in module order: within a kind, instances follow the string.
    std::array<uint32_t, kOrganKinds> next = result.first;
    for (uint32_t p = 0; p < plants; ++p)
        for (const OrganInstance& o : perPlant[p]) result.organs[next[o.kind]++] = o;
    return result;
}

void fillQueries(stream::ModuleString& string, const TurtleCommands& commands,
                 const std::vector<TurtleSettings>& species) {
    std::vector<OrganInstance> unused;
    for (uint32_t p = 0; p < string.plants(); ++p) {
        PlantTurtle turtle(string, commands, species[p % species.size()], p, unused);
        turtle.walk(string.plantStart[p], string.plantStart[p + 1],
                    [&](size_t i, uint32_t command, const TurtleState& st) {
                        glm::vec3 v;
                        switch (command) {
                        case kTurtleQueryPosition: v = st.position; break;
                        case kTurtleQueryHeading: v = st.frame.heading; break;
                        case kTurtleQueryLeft: v = st.frame.left; break;
                        case kTurtleQueryUp: v = st.frame.up; break;
                        default: return;
                        }
                        float* params = string.params.data() + i * size_t(string.stride);
                        for (size_t k = 0; k < std::min<size_t>(string.paramCount[i], 3); ++k) params[k] = v[int(k)];
                    });
        unused.clear();
    }
}

std::vector<EnvironmentQuery> environmentQueries(const stream::ModuleString& string, const TurtleCommands& commands,
                                                 const std::vector<TurtleSettings>& species) {
    std::vector<EnvironmentQuery> queries;
    std::vector<OrganInstance> unused;
    for (uint32_t p = 0; p < string.plants(); ++p) {
        PlantTurtle turtle(string, commands, species[p % species.size()], p, unused);
        turtle.walk(string.plantStart[p], string.plantStart[p + 1],
                    [&](size_t i, uint32_t command, const TurtleState& st) {
                        if (command == kTurtleQueryEnvironment) queries.push_back({i, p, st.position});
                    });
        unused.clear();
    }
    return queries;
}

} // namespace simeco::turtle
