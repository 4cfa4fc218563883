// Organ instances as world-space triangles on the CPU: the geometry `simeco render` draws, for mesh files.
// The placement of a mesh vertex by an instance mirrors render/organs/organ_transform.glsl; keep the two in step.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "compute/shared/organ_layout.h"
#include "draw/organ_meshes.h"

namespace simeco::exporter {

// One organ mesh vertex placed in the world by an instance.
struct PlacedVertex {
    glm::vec3 position;
    glm::vec3 normal; // unit length (the shaders leave that to the fragment stage)
    bool present;     // false: the vertex belongs to another leaf shape of the shared leaf mesh
};

// organVertex of render/organs/organ_transform.glsl on the CPU. One difference: a disc that faces the viewer (@o)
// lies in the heading-left plane like an @c disc, because a mesh file has no viewer to face.
PlacedVertex placeVertex(const shared::OrganInstance& o, std::uint32_t kind, const shared::MeshVertex& local);

// Names of the organ kinds and surface shapes (a model's `model_k`), for groups and meshes in the files.
const char* organKindName(std::uint32_t kind);
std::string leafShapeName(std::uint32_t shape);

inline constexpr std::uint32_t kSurfaceShapes = shared::kSurfaceLastShape + 1;

// The triangles one instance draws and only the vertices they use, in organ-local coordinates.
struct OrganMesh {
    std::vector<shared::MeshVertex> vertices;
    std::vector<std::uint32_t> indices; // into `vertices`, counter-clockwise seen from the front
};

// The drawn meshes of the renderer split per kind, and the shared leaf mesh split per shape, so that an
// instance's mesh is exactly what it draws: no collapsed vertices of other leaf shapes.
class OrganMeshSet {
public:
    explicit OrganMeshSet(const draw::OrganMeshData& data);

    // The mesh of a kind; for kOrganLeaf, of one shape (kLeaf*, then the models).
    const OrganMesh& mesh(std::uint32_t kind, std::uint32_t shape = 0) const;
    const OrganMesh& forInstance(const shared::OrganInstance& o) const;
    // The surface shapes it holds (the built-in ones, then the models it was built with), and the one it draws a
    // leaf with: its own, or the ovate blade for a model it does not hold.
    std::uint32_t leafShapes() const { return static_cast<std::uint32_t>(leaves_.size()); }
    std::uint32_t shapeOf(const shared::OrganInstance& o) const;

private:
    std::array<OrganMesh, shared::kOrganKinds> kinds_;
    std::vector<OrganMesh> leaves_;
};

// Triangles in the world with per-vertex normals and colours, in runs of one plant each.
struct WorldMesh {
    struct PlantRun {
        std::uint32_t plant = 0;
        std::uint32_t firstVertex = 0;
        std::uint32_t vertexCount = 0;
        std::uint32_t firstTriangle = 0;
        std::uint32_t triangleCount = 0;
    };

    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<glm::vec3> colors;      // linear RGB: the colour of the instance that placed the vertex
    std::vector<std::uint32_t> indices; // three per triangle, counter-clockwise seen from the front
    std::vector<PlantRun> plants;       // consecutive instances of one plant; a plant may have several runs

    std::size_t triangleCount() const { return indices.size() / 3; }
};

// The instances `order` names (indices into `organs`), each with its mesh, one after the other.
WorldMesh placeOrgans(std::span<const shared::OrganInstance> organs, std::span<const std::uint32_t> order,
                      const OrganMeshSet& meshes);

// Every instance, plant by plant (each plant's in their order in `organs`): one run per plant.
std::vector<std::uint32_t> plantOrder(std::span<const shared::OrganInstance> organs);

// Whether a kind's placement is one affine map per instance (sphere, disc, leaf): such instances can be
// stored as a transform of one shared mesh. Stems taper and mitre; polygon triangles carry their vertices.
bool isAffineKind(std::uint32_t kind);

// The affine placement of an instance of an affine kind as glTF composes it: position = translation +
// rotation * (scale * local). The rotation takes local x, y, z to heading, left, up (made orthonormal).
struct InstanceTransform {
    glm::vec3 translation;
    glm::quat rotation;
    glm::vec3 scale;
};
InstanceTransform instanceTransform(const shared::OrganInstance& o);

// Linear colour to the sRGB transfer function, clamped to [0, 1]: what OBJ and PLY viewers expect.
float srgbEncode(float linear);

} // namespace simeco::exporter
