#include "draw/organ_meshes.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "draw/leaf_silhouette.h"
#include "vk/context.h"

namespace simeco::draw {
namespace {

using shared::MeshVertex;
constexpr float kPi = std::numbers::pi_v<float>;

// Appends meshes to the shared arrays; indices are local to the mesh, which the draw's vertexOffset rebases.
class MeshBuilder {
public:
    explicit MeshBuilder(OrganMeshData& data) : data_(data) {}

    void begin() {
        firstIndex_ = static_cast<std::uint32_t>(data_.indices.size());
        base_ = static_cast<std::uint32_t>(data_.vertices.size());
    }

    std::uint32_t vertex(glm::vec3 p, glm::vec3 n, float positionW = 0.0f, float normalW = 0.0f) {
        data_.vertices.push_back({{p.x, p.y, p.z, positionW}, {n.x, n.y, n.z, normalW}});
        return static_cast<std::uint32_t>(data_.vertices.size()) - 1 - base_;
    }

    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        data_.indices.insert(data_.indices.end(), {a, b, c});
    }

    // Whether polygons are fanned from their first outline point (n - 2 triangles, for the coarsest cuts) rather
    // than from an interior point (n triangles). The first point must see the whole polygon.
    void fanFromOutline(bool fromOutline) { fanFromOutline_ = fromOutline; }

    // A polygon given counter-clockwise around +z, fanned from an interior point that sees all of it.
    void fan(glm::vec2 centre, std::span<const glm::vec2> outline, float normalW) {
        fanIn(glm::vec3(0), glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), centre, outline, normalW, 0.0f);
    }

    // The same in the plane through `origin` spanned by `a` and `b` (outline point (u, v) at origin + u a + v b),
    // facing a x b; `tint` goes to every vertex's position.w (MeshVertex).
    void fanIn(glm::vec3 origin, glm::vec3 a, glm::vec3 b, glm::vec2 centre, std::span<const glm::vec2> outline,
               float normalW, float tint) {
        const glm::vec3 normal = glm::normalize(glm::cross(a, b));
        auto at = [&](glm::vec2 p) { return vertex(origin + p.x * a + p.y * b, normal, tint, normalW); };
        if (fanFromOutline_) {
            const std::uint32_t first = at(outline[0]);
            std::uint32_t previous = at(outline[1]);
            for (std::size_t i = 2; i < outline.size(); ++i) {
                const std::uint32_t next = at(outline[i]);
                triangle(first, previous, next);
                previous = next;
            }
            return;
        }
        std::uint32_t middle = at(centre);
        std::uint32_t first = at(outline[0]);
        std::uint32_t previous = first;
        for (std::size_t i = 1; i < outline.size(); ++i) {
            std::uint32_t next = at(outline[i]);
            triangle(middle, previous, next);
            previous = next;
        }
        triangle(middle, previous, first);
    }

    // Triangles in the index buffer so far.
    std::uint32_t triangles() const { return static_cast<std::uint32_t>(data_.indices.size()) / 3; }

    MeshRange end() const {
        return {firstIndex_, static_cast<std::uint32_t>(data_.indices.size()) - firstIndex_,
                static_cast<std::int32_t>(base_)};
    }

private:
    OrganMeshData& data_;
    bool fanFromOutline_ = false;
    std::uint32_t firstIndex_ = 0;
    std::uint32_t base_ = 0;
};

// The unit stem: rings around the x axis at x = 0 and x = 1 (position.w tells which), closed by flat caps
// (normal.w = 1). The vertex shader scales, tapers and mitres it.
MeshRange addStem(MeshBuilder& b, std::uint32_t sides) {
    b.begin();
    auto radial = [&](std::uint32_t i) {
        float angle = 2.0f * kPi * static_cast<float>(i % sides) / static_cast<float>(sides);
        return glm::vec3(0, std::cos(angle), std::sin(angle));
    };
    std::uint32_t bottom = 0;
    for (std::uint32_t ring = 0; ring < 2; ++ring) {
        for (std::uint32_t i = 0; i < sides; ++i) {
            std::uint32_t v =
                b.vertex(radial(i) + glm::vec3(static_cast<float>(ring), 0, 0), radial(i), static_cast<float>(ring));
            if (ring == 0 && i == 0) {
                bottom = v;
            }
        }
    }
    std::uint32_t top = bottom + sides;
    for (std::uint32_t i = 0; i < sides; ++i) {
        std::uint32_t j = (i + 1) % sides;
        b.triangle(bottom + i, bottom + j, top + i);
        b.triangle(bottom + j, top + j, top + i);
    }
    for (std::uint32_t ring = 0; ring < 2; ++ring) {
        float x = static_cast<float>(ring);
        glm::vec3 normal(ring == 0 ? -1.0f : 1.0f, 0, 0);
        std::uint32_t centre = b.vertex(glm::vec3(x, 0, 0), normal, x, 1.0f);
        std::uint32_t first = b.vertex(radial(0) + glm::vec3(x, 0, 0), normal, x, 1.0f);
        for (std::uint32_t i = 1; i < sides; ++i) {
            b.vertex(radial(i) + glm::vec3(x, 0, 0), normal, x, 1.0f);
        }
        for (std::uint32_t i = 0; i < sides; ++i) {
            std::uint32_t v0 = first + i;
            std::uint32_t v1 = first + (i + 1) % sides;
            if (ring == 0) {
                b.triangle(centre, v1, v0);
            } else {
                b.triangle(centre, v0, v1);
            }
        }
    }
    return b.end();
}

// A stem a pixel or two wide on screen: a band across the unit stem (local y from -1 to 1 at z = 0; normal.w =
// kStemBandVertex), which the vertex shader turns to face the viewer and shades as the cylinder's visible half: 6
// vertices where the 6-sided hull has 26. Wound to face -z, the side the shader turns towards the viewer.
MeshRange addStemBand(MeshBuilder& b) {
    b.begin();
    constexpr std::uint32_t kAcross = 3;
    for (std::uint32_t ring = 0; ring < 2; ++ring)
        for (std::uint32_t i = 0; i < kAcross; ++i)
            b.vertex(glm::vec3(static_cast<float>(ring), -1.0f + 2.0f * static_cast<float>(i) / (kAcross - 1), 0),
                     glm::vec3(0, 0, -1), static_cast<float>(ring), shared::kStemBandVertex);
    for (std::uint32_t i = 0; i + 1 < kAcross; ++i) {
        const std::uint32_t bottom = i, top = kAcross + i;
        b.triangle(bottom, bottom + 1, top);
        b.triangle(bottom + 1, top + 1, top);
    }
    return b.end();
}

// The unit sphere with its poles on the x axis; `stacks` bands of latitude, `slices` of longitude.
MeshRange addSphere(MeshBuilder& b, std::uint32_t slices, std::uint32_t stacks) {
    b.begin();
    std::uint32_t first = 0;
    for (std::uint32_t j = 0; j <= stacks; ++j) {
        float latitude = kPi * (static_cast<float>(j) / static_cast<float>(stacks) - 0.5f);
        for (std::uint32_t i = 0; i < slices; ++i) {
            float longitude = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
            glm::vec3 p(std::sin(latitude), std::cos(latitude) * std::cos(longitude),
                        std::cos(latitude) * std::sin(longitude));
            if (j == 0) {
                p = glm::vec3(-1, 0, 0);
            } else if (j == stacks) {
                p = glm::vec3(1, 0, 0);
            }
            std::uint32_t v = b.vertex(p, p);
            if (j == 0 && i == 0) {
                first = v;
            }
        }
    }
    for (std::uint32_t j = 0; j < stacks; ++j) {
        for (std::uint32_t i = 0; i < slices; ++i) {
            std::uint32_t a = first + j * slices + i;
            std::uint32_t bb = first + j * slices + (i + 1) % slices;
            std::uint32_t c = bb + slices;
            std::uint32_t d = a + slices;
            // The rings at the poles are single points: one triangle of each quad there has no area.
            if (j != 0) {
                b.triangle(a, bb, d);
            }
            if (j + 1 != stacks) {
                b.triangle(bb, c, d);
            }
        }
    }
    return b.end();
}

MeshRange addDisc(MeshBuilder& b, std::uint32_t sides) {
    b.begin();
    std::vector<glm::vec2> outline;
    for (std::uint32_t i = 0; i < sides; ++i) {
        float angle = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(sides);
        outline.emplace_back(std::cos(angle), std::sin(angle));
    }
    b.fan(glm::vec2(0), outline, 0.0f);
    return b.end();
}

// A blade from its half-width along the midrib (x in [0, 1], width 1 at most), counter-clockwise: from the
// tip down the left side (+y) to the base and back up the right side.
std::vector<glm::vec2> bladeOutline(float (*halfWidth)(float), std::uint32_t pointsPerSide) {
    std::vector<glm::vec2> outline;
    outline.emplace_back(1.0f, 0.0f);
    for (std::uint32_t i = 1; i < pointsPerSide; ++i) {
        float x = 1.0f - static_cast<float>(i) / static_cast<float>(pointsPerSide);
        outline.emplace_back(x, halfWidth(x));
    }
    outline.emplace_back(0.0f, 0.0f);
    for (std::uint32_t i = pointsPerSide - 1; i >= 1; --i) {
        float x = 1.0f - static_cast<float>(i) / static_cast<float>(pointsPerSide);
        outline.emplace_back(x, -halfWidth(x));
    }
    return outline;
}

// Widest at a third of the length, narrowing to a point.
float lanceolateHalfWidth(float x) {
    return 0.5f * std::sqrt(x) * (1.0f - x) / 0.3849f;
}

// Widest a little below the middle, rounded.
float ovateHalfWidth(float x) {
    return 0.5f * std::sin(kPi * std::pow(x, 0.8f));
}

// Heart-shaped: the classic heart curve, its notch at the base (x = 0) and its lobes reaching behind it.
std::vector<glm::vec2> cordateOutline(std::uint32_t points) {
    std::vector<glm::vec2> outline;
    for (std::uint32_t i = 0; i < points; ++i) {
        // t = 0 is the notch; the curve runs counter-clockwise seen from +z once mapped below.
        float t = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(points);
        float s = std::sin(t);
        float across = 16.0f * s * s * s;
        float along = 13.0f * std::cos(t) - 5.0f * std::cos(2 * t) - 2.0f * std::cos(3 * t) - std::cos(4 * t);
        outline.emplace_back((5.0f - along) / 22.0f, -across / 32.0f);
    }
    return outline;
}

void addBlade(MeshBuilder& b, const std::vector<glm::vec2>& outline, glm::vec2 centre, float shape) {
    b.fan(centre, outline, shape);
}

// A leaf's stalk (a rachis, a petiole): a strip along the midrib from the base to `end`.
void addStalk(MeshBuilder& b, float end, float halfWidth, float shape) {
    const glm::vec3 normal(0, 0, 1);
    std::uint32_t s0 = b.vertex({0, -halfWidth, 0}, normal, 0, shape);
    std::uint32_t s1 = b.vertex({end, -halfWidth, 0}, normal, 0, shape);
    std::uint32_t s2 = b.vertex({end, halfWidth, 0}, normal, 0, shape);
    std::uint32_t s3 = b.vertex({0, halfWidth, 0}, normal, 0, shape);
    b.triangle(s0, s1, s2);
    b.triangle(s0, s2, s3);
}

// How finely a surface is cut: as drawn, the few triangles its shadow is cast from (a shadow on the ground or on
// another organ hardly shows a leaf's teeth, and each casting triangle is a volume the device must draw), or fewer
// still for the shadow of a surface a few pixels across (Far: stalks left out, the fewest outline points, polygons
// fanned from their first point).
enum class Detail { Drawn, Shadow, Far };

// A pinnate compound leaf: a rachis with two pairs of leaflets and a terminal one.
void addCompound(MeshBuilder& b, float shape, Detail detail) {
    const float rachisEnd = 0.62f;
    if (detail != Detail::Far) addStalk(b, rachisEnd, 0.03f, shape);

    struct Leaflet {
        glm::vec2 base;
        float angle; // from the midrib, counter-clockwise
        float length;
        float width;
    };
    const Leaflet leaflets[] = {
        {{0.20f, 0}, 1.0f, 0.45f, 0.30f},
        {{0.20f, 0}, -1.0f, 0.45f, 0.30f},
        {{0.42f, 0}, 0.8f, 0.45f, 0.30f},
        {{0.42f, 0}, -0.8f, 0.45f, 0.30f},
        {{rachisEnd - 0.02f, 0}, 0.0f, 0.40f, 0.55f},
    };
    std::vector<glm::vec2> unit = bladeOutline(ovateHalfWidth, detail == Detail::Drawn ? 6 : 2);
    for (const Leaflet& leaflet : leaflets) {
        glm::vec2 along(std::cos(leaflet.angle), std::sin(leaflet.angle));
        glm::vec2 across(-along.y, along.x);
        std::vector<glm::vec2> outline;
        for (glm::vec2 p : unit) {
            outline.push_back(leaflet.base + p.x * leaflet.length * along + p.y * leaflet.width * across);
        }
        b.fan(leaflet.base + 0.45f * leaflet.length * along, outline, shape);
    }
}

// Oxalis' leaf: a long petiole and, at its end, three obcordate leaflets (notched at their tips) spread like
// a clover's.
void addTrifoliate(MeshBuilder& b, float shape, Detail detail) {
    const float petioleEnd = 0.58f;
    if (detail != Detail::Far) addStalk(b, petioleEnd, 0.018f, shape);
    // The cordate outline reversed along its midrib: narrow at the petiole, notched at the tip.
    std::vector<glm::vec2> obcordate = cordateOutline(detail == Detail::Drawn ? 24 : (detail == Detail::Far ? 6 : 8));
    // The lobes reach past the notch: the drawn leaflet spans [0, reach] before it is scaled, and the coarser cuts
    // are scaled as it is, so that they stay inside it.
    float reach = 0.0f;
    for (glm::vec2 p : cordateOutline(24)) reach = std::max(reach, 1.0f - p.x);
    for (glm::vec2& p : obcordate) p = glm::vec2(1.0f - p.x, p.y) / reach;
    std::reverse(obcordate.begin(), obcordate.end()); // counter-clockwise again
    // The notch last now: first for the far cut, which is fanned from its first point and only the notch sees the
    // whole leaflet.
    if (detail == Detail::Far) std::rotate(obcordate.begin(), obcordate.end() - 1, obcordate.end());
    const glm::vec2 base(petioleEnd, 0.0f);
    const float length = 0.42f, width = 0.5f;
    for (float angle : {0.0f, 2.1f, -2.1f}) {
        glm::vec2 along(std::cos(angle), std::sin(angle));
        glm::vec2 across(-along.y, along.x);
        std::vector<glm::vec2> outline;
        for (glm::vec2 p : obcordate) outline.push_back(base + p.x * length * along + p.y * width * length * across);
        b.fan(base + 0.5f * length * along, outline, shape);
    }
}

// Lantana's leaf: ovate, its margin toothed (every other point of the outline set in).
std::vector<glm::vec2> serrateOutline(std::uint32_t pointsPerSide) {
    std::vector<glm::vec2> outline = bladeOutline(ovateHalfWidth, pointsPerSide);
    for (size_t i = 1; i < outline.size(); ++i)
        if (i % 2 == 0 && outline[i].x > 0.08f && outline[i].x < 0.95f) outline[i].y *= 0.86f;
    return outline;
}

// Blossoms face along +x (the heading: away from the stalk), their unit diameter across y and z. A petal or
// floret at angle `around` the x axis lies along `radial`, turned `rise` radians up from the y-z plane.
glm::vec3 radialAt(float around) {
    return {0.0f, std::cos(around), std::sin(around)};
}
glm::vec3 tangentAt(float around) {
    return {0.0f, -std::sin(around), std::cos(around)};
}

// A petal from `base` along the radial direction at `around`, risen by `rise` toward +x; outline as bladeOutline's.
void addPetal(MeshBuilder& b, glm::vec3 base, float around, float rise, float length, float width,
              const std::vector<glm::vec2>& unit, float shape, float tint) {
    const glm::vec3 along = std::cos(rise) * radialAt(around) + std::sin(rise) * glm::vec3(1, 0, 0);
    std::vector<glm::vec2> outline;
    for (glm::vec2 p : unit) outline.emplace_back(p.x * length, p.y * width);
    b.fanIn(base, along, tangentAt(around), {0.5f * length, 0.0f}, outline, shape, tint);
}

// Widest near the tip, rounded: a petal of Oxalis or a rose.
float obovateHalfWidth(float x) {
    return 0.5f * std::sin(kPi * std::pow(x, 1.6f));
}
float roundHalfWidth(float x) {
    return 0.5f * std::sin(kPi * std::pow(x, 0.9f));
}

// Oxalis' flower: five obovate petals spreading from a shallow funnel around a yellow eye.
void addStarBlossom(MeshBuilder& b, float shape, Detail detail) {
    const std::vector<glm::vec2> petal = bladeOutline(obovateHalfWidth, detail == Detail::Drawn ? 3 : 2);
    for (int k = 0; k < 5; ++k)
        addPetal(b, glm::vec3(0), 2.0f * kPi * float(k) / 5.0f, 0.35f, 0.5f, 0.36f, petal, shape, 0.0f);
    if (detail != Detail::Drawn) return; // the eye lies in the petals' shadow
    std::vector<glm::vec2> eye;
    for (int k = 0; k < 6; ++k) eye.push_back(0.1f * glm::vec2(std::cos(kPi * k / 3.0f), std::sin(kPi * k / 3.0f)));
    b.fanIn({0.03f, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0}, eye, shape, 1.0f);
}

// Lantana's flower head: florets on a dome, the inner ones yellow, the outer ones of the organ's colour, each a
// small cross of four rounded lobes.
void addHeadBlossom(MeshBuilder& b, float shape, Detail detail) {
    std::vector<glm::vec2> floret; // the shadow's: the four lobes' tips
    for (int k = 0; k < 8; k += detail == Detail::Drawn ? 1 : 2) {
        const float angle = kPi * float(k) / 4.0f, radius = k % 2 == 0 ? 0.2f : 0.13f;
        floret.push_back(radius * glm::vec2(std::cos(angle), std::sin(angle)));
    }
    struct Ring {
        int florets;
        float polar; // from the dome's top, radians
        float tint;
    };
    for (const Ring ring : {Ring{1, 0.0f, 1.0f}, Ring{3, 0.45f, 1.0f}, Ring{5, 0.95f, 0.0f}}) {
        for (int k = 0; k < ring.florets; ++k) {
            const float around = 2.0f * kPi * (float(k) + 0.5f * float(ring.florets % 2)) / float(ring.florets);
            const glm::vec3 outward = std::cos(ring.polar) * glm::vec3(1, 0, 0) + std::sin(ring.polar) * radialAt(around);
            const glm::vec3 centre = glm::vec3(0.12f, 0, 0) + glm::vec3(0.3f, 0.42f, 0.42f) * outward;
            // Two axes across the floret: its face looks out of the dome.
            const glm::vec3 a = glm::normalize(glm::cross(tangentAt(around), outward));
            const glm::vec3 c = glm::cross(outward, a);
            b.fanIn(centre, a, c, {0, 0}, floret, shape, ring.tint);
        }
    }
}

// A rose: three rings of rounded petals, each ring smaller and more upright than the one outside it.
void addRoseBlossom(MeshBuilder& b, float shape, Detail detail) {
    const std::vector<glm::vec2> petal = bladeOutline(roundHalfWidth, detail == Detail::Drawn ? 3 : 2),
                                 small = bladeOutline(roundHalfWidth, 2);
    for (int k = 0; k < 5; ++k) {
        const float around = 2.0f * kPi * float(k) / 5.0f;
        addPetal(b, glm::vec3(0), around, 0.45f, 0.5f, 0.42f, petal, shape, 0.0f);
        addPetal(b, glm::vec3(0.02f, 0, 0), around + kPi / 5.0f, 1.0f, 0.36f, 0.34f, petal, shape, 0.0f);
    }
    for (int k = 0; k < 3; ++k)
        addPetal(b, glm::vec3(0.04f, 0, 0), 2.0f * kPi * float(k) / 3.0f + 0.3f, 1.3f, 0.26f, 0.26f, small, shape,
                 0.0f);
}

// Every surface shape in one mesh (the built-in leaves and blossoms, then the models), each vertex tagged with its
// shape, at the given detail; `shapes` gets each shape's first triangle (counted from the mesh's first) and count.
void addSurfaceShapes(MeshBuilder& b, const std::vector<ir::LeafModel>& leafModels, Detail detail,
                      std::vector<std::array<std::uint32_t, 2>>& shapes, std::uint32_t first) {
    const bool drawn = detail == Detail::Drawn, far = detail == Detail::Far;
    auto add = [&](auto&& build) {
        const std::uint32_t before = b.triangles();
        build(static_cast<float>(shapes.size()));
        shapes.push_back({before - first, b.triangles() - before});
    };
    const std::uint32_t bladePoints = drawn ? 12 : (far ? 2 : 3);
    add([&](float s) { addBlade(b, bladeOutline(lanceolateHalfWidth, bladePoints), {0.35f, 0}, s); });
    add([&](float s) { addBlade(b, bladeOutline(ovateHalfWidth, bladePoints), {0.45f, 0}, s); });
    add([&](float s) { addBlade(b, cordateOutline(drawn ? 32 : (far ? 5 : 10)), {0.4f, 0}, s); });
    add([&](float s) { addCompound(b, s, detail); });
    add([&](float s) { addTrifoliate(b, s, detail); });
    add([&](float s) {
        addBlade(b, drawn ? serrateOutline(24) : bladeOutline(ovateHalfWidth, far ? 2 : 4), {0.45f, 0}, s);
    });
    add([&](float s) { addStarBlossom(b, s, detail); });
    add([&](float s) { addHeadBlossom(b, s, detail); });
    add([&](float s) { addRoseBlossom(b, s, detail); });
    for (const ir::LeafModel& model : leafModels) {
        add([&](float s) {
            for (std::size_t t = 0; t < model.normals.size(); ++t) {
                const auto& n = model.normals[t];
                std::uint32_t corner[3];
                for (std::size_t c = 0; c < 3; ++c) {
                    const auto& p = model.corners[3 * t + c];
                    corner[c] = b.vertex({p[0], p[1], p[2]}, {n[0], n[1], n[2]}, 0, s);
                }
                b.triangle(corner[0], corner[1], corner[2]);
            }
        });
    }
}

MeshRange addSurfaces(MeshBuilder& b, const std::vector<ir::LeafModel>& leafModels, Detail detail,
                      std::vector<std::array<std::uint32_t, 2>>& shapes) {
    b.begin();
    addSurfaceShapes(b, leafModels, detail, shapes, b.triangles());
    return b.end();
}

// Marks the edges two of the triangles [first, first + count) share (by their vertices, as a fan shares them).
void markInteriorEdges(OrganMeshData& data, std::uint32_t first, std::uint32_t count) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
    auto edge = [&](std::uint32_t t, std::uint32_t k) {
        const std::uint32_t a = data.indices[3 * t + k], b = data.indices[3 * t + (k + 1) % 3];
        return std::make_pair(std::min(a, b), std::max(a, b));
    };
    for (std::uint32_t t = first; t < first + count; ++t)
        for (std::uint32_t k = 0; k < 3; ++k) ++uses[edge(t, k)];
    for (std::uint32_t t = first; t < first + count; ++t)
        for (std::uint32_t k = 0; k < 3; ++k)
            if (uses[edge(t, k)] == 2) data.interiorEdges[t] |= 1u << k;
}

// The corners of `triangles` (the first, counted from the range's first, and how many) of a range.
std::vector<glm::vec3> triangleCorners(const OrganMeshData& data, const MeshRange& range,
                                       std::array<std::uint32_t, 2> triangles) {
    std::vector<glm::vec3> corners;
    for (std::uint32_t i = 3 * triangles[0]; i < 3 * (triangles[0] + triangles[1]); ++i) {
        const shared::MeshVertex& v =
            data.vertices[static_cast<std::size_t>(range.vertexOffset) + data.indices[range.firstIndex + i]];
        corners.emplace_back(v.position.x, v.position.y, v.position.z);
    }
    return corners;
}

// Each shape's far shadow (OrganMeshData::leafFarShadowTriangles) into the leaf hull begun at triangle `hullFirst`:
// a silhouette quadrilateral where the far cut has more than two triangles, else the far cut itself. It lies across
// the shape's thinnest axis at its middle, with the area the drawn shape covers seen along that axis: a leaf's in its
// plane (z, out of its face), a blossom's across its heading (x).
void addFarShadows(MeshBuilder& b, OrganMeshData& data, std::uint32_t hullFirst) {
    const MeshRange hull = b.end();
    for (std::uint32_t shape = 0; shape < data.leafFarHullTriangles.size(); ++shape) {
        const std::array<std::uint32_t, 2> far = data.leafFarHullTriangles[shape];
        std::optional<std::array<glm::vec2, 4>> quad;
        int thinnest = 2;
        float middle = 0.0f;
        if (far[1] > 2) {
            const std::vector<glm::vec3> cut = triangleCorners(data, hull, far);
            glm::vec3 low = cut[0], high = cut[0];
            for (const glm::vec3& p : cut) {
                low = glm::min(low, p);
                high = glm::max(high, p);
            }
            const glm::vec3 extent = high - low;
            for (int axis : {1, 0})
                if (extent[axis] < extent[thinnest]) thinnest = axis;
            middle = 0.5f * (low[thinnest] + high[thinnest]);
            // The other two axes in turn after it, so that the quadrilateral's winding faces along it.
            auto seen = [&](const glm::vec3& p) { return glm::vec2(p[(thinnest + 1) % 3], p[(thinnest + 2) % 3]); };
            std::vector<glm::vec2> outline, face;
            for (const glm::vec3& p : cut) outline.push_back(seen(p));
            for (const glm::vec3& p :
                 triangleCorners(data, data.organs[shared::kOrganLeaf], data.leafShapeTriangles[shape]))
                face.push_back(seen(p));
            quad = silhouetteQuad(std::move(outline), coveredArea(face));
        }
        if (!quad) {
            data.leafFarShadowTriangles.push_back(far);
            continue;
        }
        glm::vec3 normal(0.0f);
        normal[thinnest] = 1.0f;
        const std::uint32_t first = b.triangles();
        std::array<std::uint32_t, 4> corner{};
        for (std::size_t c = 0; c < 4; ++c) {
            glm::vec3 p;
            p[thinnest] = middle;
            p[(thinnest + 1) % 3] = (*quad)[c].x;
            p[(thinnest + 2) % 3] = (*quad)[c].y;
            corner[c] = b.vertex(p, normal, 0.0f, static_cast<float>(shape));
        }
        b.triangle(corner[0], corner[1], corner[2]);
        b.triangle(corner[0], corner[2], corner[3]);
        data.leafFarShadowTriangles.push_back({first - hullFirst, 2});
    }
}

} // namespace

OrganMeshData buildOrganMeshes(const std::vector<ir::LeafModel>& leafModels) {
    using namespace shared;
    OrganMeshData data;
    MeshBuilder b(data);

    data.organs[kOrganStem] = addStem(b, kStemSides);
    data.hulls[kOrganStem] = addStem(b, kStemHullSides);
    const MeshRange stemBand = addStemBand(b);
    // The hull's rings and meridians are every other one of the drawn sphere's.
    data.organs[kOrganSphere] = addSphere(b, 16, 10);
    data.hulls[kOrganSphere] = addSphere(b, 8, 5);
    data.organs[kOrganDisc] = addDisc(b, 20);
    data.hulls[kOrganDisc] = data.organs[kOrganDisc];

    data.organs[kOrganLeaf] = addSurfaces(b, leafModels, Detail::Drawn, data.leafShapeTriangles);
    // The leaf hull: every shape's shadow cut, then every shape's far cut and far shadow, in one range.
    b.begin();
    const std::uint32_t hullFirst = b.triangles();
    addSurfaceShapes(b, leafModels, Detail::Shadow, data.leafHullTriangles, hullFirst);
    b.fanFromOutline(true);
    addSurfaceShapes(b, leafModels, Detail::Far, data.leafFarHullTriangles, hullFirst);
    b.fanFromOutline(false);
    addFarShadows(b, data, hullFirst);
    data.hulls[kOrganLeaf] = b.end();
    data.interiorEdges.assign(data.indices.size() / 3, 0);
    for (std::uint32_t shape = 0; shape <= kLeafLastShape; ++shape) {
        markInteriorEdges(data, hullFirst + data.leafHullTriangles[shape][0], data.leafHullTriangles[shape][1]);
        markInteriorEdges(data, hullFirst + data.leafFarHullTriangles[shape][0], data.leafFarHullTriangles[shape][1]);
    }
    // The silhouette quadrilaterals are flat, whatever the shape.
    for (std::uint32_t shape = 0; shape < data.leafFarShadowTriangles.size(); ++shape)
        if (data.leafFarShadowTriangles[shape] != data.leafFarHullTriangles[shape])
            markInteriorEdges(data, hullFirst + data.leafFarShadowTriangles[shape][0], 2);

    b.begin();
    for (int corner = 0; corner < 3; ++corner) {
        b.vertex(glm::vec3(static_cast<float>(corner), 0, 0), glm::vec3(0, 0, 1));
    }
    b.triangle(0, 1, 2);
    data.organs[kOrganTriangle] = b.end();
    data.hulls[kOrganTriangle] = data.organs[kOrganTriangle];

    b.begin();
    const glm::vec3 up(0, 1, 0);
    std::uint32_t g0 = b.vertex({-1, 0, -1}, up);
    std::uint32_t g1 = b.vertex({-1, 0, 1}, up);
    std::uint32_t g2 = b.vertex({1, 0, 1}, up);
    std::uint32_t g3 = b.vertex({1, 0, -1}, up);
    b.triangle(g0, g1, g2);
    b.triangle(g0, g2, g3);
    data.ground = b.end();

    data.far = data.hulls;
    data.far[kOrganStem] = stemBand;
    for (std::uint32_t kind = 0; kind < kOrganKinds; ++kind) {
        data.closedHull[kind] = kind == kOrganStem || kind == kOrganSphere;
        data.castingTriangles[kind] = data.hulls[kind].triangleCount();
    }
    data.castingTriangles[kOrganLeaf] = 0;
    for (const std::array<std::uint32_t, 2>& shape : data.leafHullTriangles)
        data.castingTriangles[kOrganLeaf] = std::max(data.castingTriangles[kOrganLeaf], shape[1]);
    return data;
}

OrganMeshes::OrganMeshes(const vk::Context& context, const std::vector<ir::LeafModel>& leafModels)
    : data_(buildOrganMeshes(leafModels)), vertices_(context, data_.vertices.size() * sizeof(shared::MeshVertex),
                                                     vk::MemoryUsage::DeviceLocal, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT),
      indices_(context, data_.indices.size() * sizeof(std::uint32_t), vk::MemoryUsage::DeviceLocal,
               VK_BUFFER_USAGE_INDEX_BUFFER_BIT) {
    vk::uploadSpan(context, vertices_, std::span<const shared::MeshVertex>(data_.vertices));
    vk::uploadSpan(context, indices_, std::span<const std::uint32_t>(data_.indices));
    leafShapeTriangles_ =
        vk::deviceBufferWith(context, std::span<const std::array<std::uint32_t, 2>>(data_.leafShapeTriangles));
    leafHullTriangles_ =
        vk::deviceBufferWith(context, std::span<const std::array<std::uint32_t, 2>>(data_.leafHullTriangles));
    leafFarHullTriangles_ =
        vk::deviceBufferWith(context, std::span<const std::array<std::uint32_t, 2>>(data_.leafFarHullTriangles));
    leafFarShadowTriangles_ =
        vk::deviceBufferWith(context, std::span<const std::array<std::uint32_t, 2>>(data_.leafFarShadowTriangles));
    interiorEdges_ = vk::deviceBufferWith(context, std::span<const std::uint32_t>(data_.interiorEdges));
}

} // namespace simeco::draw
