#include "export/organ_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace simeco::exporter {
namespace {

using namespace shared;

glm::vec3 xyz(const vec4& v) {
    return {v.x, v.y, v.z};
}

glm::vec3 unitOr(glm::vec3 v, glm::vec3 fallback) {
    float length = glm::length(v);
    return length > 1e-20f ? v / length : fallback;
}

// stemRingPoint of organ_transform.glsl.
glm::vec3 stemRingPoint(glm::vec3 ringCentre, glm::vec3 offset, glm::vec3 heading, glm::vec3 otherHeading,
                        glm::vec3& planeNormal) {
    planeNormal = heading;
    if (glm::dot(otherHeading, otherHeading) > 1e-12f) {
        glm::vec3 bisector = heading + glm::normalize(otherHeading);
        if (glm::dot(bisector, bisector) > 1e-6f) {
            planeNormal = glm::normalize(bisector);
        }
    }
    float along = -glm::dot(planeNormal, offset) / std::max(glm::dot(planeNormal, heading), 0.2f);
    return ringCentre + offset + along * heading;
}

// The vertices a range of the shared index buffer uses, kept if `keep` says so, renumbered in buffer order;
// triangles with a vertex left out are dropped.
template <typename Keep>
OrganMesh extractMesh(const draw::OrganMeshData& data, const draw::MeshRange& range, Keep keep) {
    std::vector<std::uint32_t> used;
    for (std::uint32_t i = 0; i < range.indexCount; ++i) {
        used.push_back(static_cast<std::uint32_t>(range.vertexOffset) + data.indices[range.firstIndex + i]);
    }
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    std::erase_if(used, [&](std::uint32_t v) { return !keep(data.vertices[v]); });

    OrganMesh mesh;
    for (std::uint32_t v : used) {
        mesh.vertices.push_back(data.vertices[v]);
    }
    auto local = [&](std::uint32_t index) -> std::int64_t {
        std::uint32_t v = static_cast<std::uint32_t>(range.vertexOffset) + index;
        auto it = std::lower_bound(used.begin(), used.end(), v);
        return it != used.end() && *it == v ? it - used.begin() : -1;
    };
    for (std::uint32_t t = 0; t < range.triangleCount(); ++t) {
        std::int64_t corners[3];
        for (int c = 0; c < 3; ++c) {
            corners[c] = local(data.indices[range.firstIndex + 3 * t + static_cast<std::uint32_t>(c)]);
        }
        if (corners[0] >= 0 && corners[1] >= 0 && corners[2] >= 0) {
            for (std::int64_t c : corners) {
                mesh.indices.push_back(static_cast<std::uint32_t>(c));
            }
        }
    }
    return mesh;
}

} // namespace

PlacedVertex placeVertex(const OrganInstance& o, std::uint32_t kind, const MeshVertex& local) {
    PlacedVertex v{};
    v.present = true;
    glm::vec3 H = xyz(o.heading);
    glm::vec3 U = xyz(o.up);
    glm::vec3 L = glm::cross(U, H);
    if (kind == kOrganStem) {
        bool top = local.position.w > 0.5f;
        float segmentLength = o.position.w;
        float radiusBottom = o.heading.w;
        float radiusTop = o.up.w;
        glm::vec3 radial = local.position.y * L + local.position.z * U; // unit on the rings, zero at cap centres
        glm::vec3 ringCentre = xyz(o.position) + (top ? segmentLength : 0.0f) * H;
        glm::vec3 planeNormal;
        v.position = stemRingPoint(ringCentre, (top ? radiusTop : radiusBottom) * radial, H,
                                   top ? xyz(o.nextHeading) : xyz(o.previousHeading), planeNormal);
        if (local.normal.w > 0.5f) {
            v.normal = top ? planeNormal : -planeNormal;
        } else {
            // The side of a cone: the radial direction tilted by the taper.
            v.normal = radial * std::max(segmentLength, 1e-6f) + (radiusBottom - radiusTop) * H;
        }
        v.normal = unitOr(v.normal, H);
    } else if (kind == kOrganSphere) {
        glm::vec3 direction = local.position.x * H + local.position.y * L + local.position.z * U;
        v.position = xyz(o.position) + o.heading.w * direction;
        v.normal = unitOr(direction, U);
    } else if (kind == kOrganDisc) {
        // Both disc orientations lie in the heading-left plane: the shaders turn @o discs to the camera, and a
        // mesh file has none.
        glm::vec3 axisA = H;
        glm::vec3 axisB = L;
        v.position = xyz(o.position) + o.heading.w * (local.position.x * axisA + local.position.y * axisB);
        v.normal = unitOr(glm::cross(axisA, axisB), U);
    } else if (kind == kOrganLeaf) {
        // The leaf mesh holds every shape; a vertex of another shape collapses onto the base. A model the mesh
        // set does not hold is drawn as the ovate blade (OrganMeshSet::shapeOf).
        const auto shape = static_cast<std::uint32_t>(local.normal.w + 0.5f);
        v.present = shape == o.shape || (o.shape > kSurfaceLastShape && shape == kLeafOvate);
        v.position = xyz(o.position);
        if (v.present) {
            v.position += local.position.x * o.position.w * H + local.position.y * o.heading.w * L +
                          local.position.z * o.up.w * U;
        }
        // Normals scale by the inverse of the positions' scales.
        const glm::vec3 inverse = 1.0f / glm::max(glm::vec3(o.position.w, o.heading.w, o.up.w), glm::vec3(1e-20f));
        v.normal = unitOr(local.normal.x * inverse.x * H + local.normal.y * inverse.y * L +
                              local.normal.z * inverse.z * U,
                          glm::vec3(0, 1, 0));
    } else {
        // kOrganTriangle: the mesh is three vertices numbered by local.x.
        glm::vec3 a = xyz(o.position);
        glm::vec3 b = xyz(o.heading);
        glm::vec3 c = xyz(o.up);
        auto corner = static_cast<std::uint32_t>(local.position.x + 0.5f);
        v.position = corner == 0 ? a : (corner == 1 ? b : c);
        v.normal = unitOr(glm::cross(b - a, c - a), glm::vec3(0, 1, 0));
        if (o.shape == kTriangleOfCylinder) { // smooth across the cylinder, turned to the triangle's side
            const glm::vec3 n = corner == 0   ? xyz(o.previousHeading)
                                : corner == 1 ? xyz(o.nextHeading)
                                              : glm::vec3(o.position.w, o.heading.w, o.up.w);
            if (glm::dot(n, n) > 0.0f) v.normal = glm::dot(n, v.normal) < 0.0f ? -n : n;
        }
    }
    return v;
}

const char* organKindName(std::uint32_t kind) {
    switch (kind) {
    case kOrganStem:
        return "stem";
    case kOrganSphere:
        return "sphere";
    case kOrganDisc:
        return "disc";
    case kOrganLeaf:
        return "leaf";
    case kOrganTriangle:
        return "polygon"; // a polygon's or a generalized cylinder's triangle
    default:
        return "organ";
    }
}

std::string leafShapeName(std::uint32_t shape) {
    if (shape > kSurfaceLastShape) return "model_" + std::to_string(shape - kSurfaceLastShape - 1);
    switch (shape) {
    case kLeafLanceolate:
        return "lanceolate";
    case kLeafOvate:
        return "ovate";
    case kLeafCordate:
        return "cordate";
    case kLeafTrifoliate:
        return "trifoliate";
    case kLeafSerrate:
        return "serrate";
    case kBlossomStar:
        return "star_blossom";
    case kBlossomHead:
        return "flower_head";
    case kBlossomRose:
        return "rose_blossom";
    default:
        return "compound";
    }
}

OrganMeshSet::OrganMeshSet(const draw::OrganMeshData& data) {
    auto all = [](const MeshVertex&) { return true; };
    for (std::uint32_t kind = 0; kind < kOrganKinds; ++kind) {
        kinds_[kind] = extractMesh(data, data.organs[kind], all);
    }
    // The built-in shapes and as many models as the leaf mesh holds.
    std::uint32_t shapes = kSurfaceShapes;
    const draw::MeshRange& leaf = data.organs[kOrganLeaf];
    for (std::uint32_t i = 0; i < leaf.indexCount; ++i) {
        const std::size_t vertex = static_cast<std::size_t>(leaf.vertexOffset) + data.indices[leaf.firstIndex + i];
        const MeshVertex& v = data.vertices[vertex];
        shapes = std::max(shapes, static_cast<std::uint32_t>(v.normal.w + 0.5f) + 1);
    }
    for (std::uint32_t shape = 0; shape < shapes; ++shape) {
        leaves_.push_back(extractMesh(data, leaf, [shape](const MeshVertex& v) {
            return static_cast<std::uint32_t>(v.normal.w + 0.5f) == shape;
        }));
    }
}

const OrganMesh& OrganMeshSet::mesh(std::uint32_t kind, std::uint32_t shape) const {
    if (kind >= kOrganKinds) {
        throw std::out_of_range("organ kind " + std::to_string(kind) + " has no mesh");
    }
    return kind == kOrganLeaf ? leaves_[shape < leaves_.size() ? shape : kLeafOvate] : kinds_[kind];
}

std::uint32_t OrganMeshSet::shapeOf(const OrganInstance& o) const {
    return o.shape < leaves_.size() ? o.shape : kLeafOvate;
}

const OrganMesh& OrganMeshSet::forInstance(const OrganInstance& o) const {
    return mesh(o.kind, o.kind == kOrganLeaf ? shapeOf(o) : 0);
}

WorldMesh placeOrgans(std::span<const OrganInstance> organs, std::span<const std::uint32_t> order,
                      const OrganMeshSet& meshes) {
    std::size_t vertices = 0, indices = 0;
    for (std::uint32_t i : order) {
        const OrganMesh& m = meshes.forInstance(organs[i]);
        vertices += m.vertices.size();
        indices += m.indices.size();
    }
    // OBJ, PLY and glTF all index vertices with 32 bits at most.
    if (vertices > std::numeric_limits<std::uint32_t>::max()) {
        throw std::length_error("the plants have " + std::to_string(vertices) +
                                " mesh vertices, more than a mesh file can index (2^32 - 1)");
    }
    WorldMesh world;
    world.positions.reserve(vertices);
    world.normals.reserve(vertices);
    world.colors.reserve(vertices);
    world.indices.reserve(indices);
    for (std::uint32_t i : order) {
        const OrganInstance& o = organs[i];
        const OrganMesh& m = meshes.forInstance(o);
        auto base = static_cast<std::uint32_t>(world.positions.size());
        auto firstTriangle = static_cast<std::uint32_t>(world.triangleCount());
        glm::vec3 color(o.color.x, o.color.y, o.color.z);
        for (const MeshVertex& local : m.vertices) {
            PlacedVertex v = placeVertex(o, o.kind, local);
            world.positions.push_back(v.position);
            world.normals.push_back(v.normal);
            world.colors.push_back(color);
        }
        for (std::uint32_t index : m.indices) {
            world.indices.push_back(base + index);
        }
        if (world.plants.empty() || world.plants.back().plant != o.plant) {
            world.plants.push_back({o.plant, base, 0, firstTriangle, 0});
        }
        WorldMesh::PlantRun& run = world.plants.back();
        run.vertexCount += static_cast<std::uint32_t>(m.vertices.size());
        run.triangleCount += static_cast<std::uint32_t>(m.indices.size() / 3);
    }
    return world;
}

std::vector<std::uint32_t> plantOrder(std::span<const OrganInstance> organs) {
    std::vector<std::uint32_t> order(organs.size());
    for (std::uint32_t i = 0; i < order.size(); ++i) {
        order[i] = i;
    }
    std::stable_sort(order.begin(), order.end(),
                     [&](std::uint32_t a, std::uint32_t b) { return organs[a].plant < organs[b].plant; });
    return order;
}

bool isAffineKind(std::uint32_t kind) {
    return kind == kOrganSphere || kind == kOrganDisc || kind == kOrganLeaf;
}

InstanceTransform instanceTransform(const OrganInstance& o) {
    // The rotation needs an orthonormal frame; the turtle's is one up to rounding.
    glm::vec3 H = unitOr(xyz(o.heading), glm::vec3(0, 1, 0));
    glm::vec3 L = glm::cross(xyz(o.up), H);
    if (glm::dot(L, L) < 1e-12f) {
        L = glm::cross(std::abs(H.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0), H);
    }
    L = glm::normalize(L);
    glm::vec3 U = glm::cross(H, L);

    InstanceTransform t;
    t.translation = xyz(o.position);
    t.rotation = glm::normalize(glm::quat_cast(glm::mat3(H, L, U)));
    float r = o.heading.w;
    switch (o.kind) {
    case kOrganLeaf:
        t.scale = {o.position.w, o.heading.w, o.up.w};
        break;
    default:
        t.scale = {r, r, r};
        break; // spheres and discs: the radius
    }
    return t;
}

float srgbEncode(float linear) {
    float x = std::isfinite(linear) ? std::clamp(linear, 0.0f, 1.0f) : 0.0f;
    return x <= 0.0031308f ? 12.92f * x : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
}

} // namespace simeco::exporter
