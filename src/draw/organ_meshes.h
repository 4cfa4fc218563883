// The procedural meshes organs are drawn with, one per organ kind, in organ-local coordinates (x along the
// heading, y along left = up x heading, z along up; see render/organs/organ_transform.glsl), plus the low-poly hulls
// that cast their shadows and the ground plane, all in one vertex buffer and one index buffer on the device.
#pragma once

#include <vector>

#include "ir/leaf_model.h"

#include <array>
#include <cstdint>
#include <vector>

#include "render/shared/draw_layout.h"
#include "vk/buffer.h"

namespace simeco::vk {
class Context;
}

namespace simeco::draw {

// A mesh inside the shared buffers, as an indexed draw takes it.
struct MeshRange {
    std::uint32_t firstIndex = 0;
    std::uint32_t indexCount = 0;
    std::int32_t vertexOffset = 0;

    std::uint32_t triangleCount() const { return indexCount / 3; }
};

struct OrganMeshData {
    std::vector<shared::MeshVertex> vertices;
    std::vector<std::uint32_t> indices; // triangles wound counter-clockwise seen from outside (right-handed)
    std::array<MeshRange, shared::kOrganKinds> organs; // drawn, by kind (kOrgan*)
    std::array<MeshRange, shared::kOrganKinds> hulls;  // cast shadows, by kind
    // Drawn where an organ is a few pixels across, by kind: its hull, but a stem's band (addStemBand); a leaf is drawn
    // there with its shape's far cut (leafFarHullTriangles).
    std::array<MeshRange, shared::kOrganKinds> far;
    // Whether a kind's hull is closed (casts from the faces turned away from the sun) or an open sheet.
    std::array<bool, shared::kOrganKinds> closedHull{};
    // Per leaf shape (the built-in ones, then the models), its triangles within the drawn leaf mesh and within the
    // leaf hull (a shape cut coarser, which its shadow is cast from): the first, counted from the range's first, and
    // how many. A leaf is drawn, and casts, from its own shape's alone.
    std::vector<std::array<std::uint32_t, 2>> leafShapeTriangles, leafHullTriangles;
    // The same for the far cut of each shape, also within the leaf hull's range: fewer triangles still, which a leaf
    // a few pixels across on screen is drawn with.
    std::vector<std::array<std::uint32_t, 2>> leafFarHullTriangles;
    // What a leaf a few pixels across casts its shadow from, within the leaf hull: a silhouette quadrilateral
    // (leaf_silhouette.h) across the shape's thinnest axis with the area it covers seen along it (a leaf's in its
    // plane, a blossom's across its heading); two triangles in place of the far cut's many. A shape whose far cut has
    // two at most casts from that.
    std::vector<std::array<std::uint32_t, 2>> leafFarShadowTriangles;
    // Per triangle of the index buffer: bit k set where its edge k (corner k to corner k + 1) is shared with another
    // triangle of the same flat leaf shape. The shadow volumes of a flat sheet's triangles meet there with opposite
    // sides, which cancel in the stencil, so they leave them out (shadow_volume.vert). Zero elsewhere.
    std::vector<std::uint32_t> interiorEdges;
    // Hull triangles one instance of a kind can cast at most (a leaf's: its shape's in the leaf hull).
    std::array<std::uint32_t, shared::kOrganKinds> castingTriangles{};
    MeshRange ground; // the square [-1, 1]^2 in x and z at y = 0, facing +y
};

// Sides of the drawn stem and of its shadow hull; the hull's corners are corners of the drawn stem, so the
// hull lies inside it.
inline constexpr std::uint32_t kStemSides = 12;
inline constexpr std::uint32_t kStemHullSides = 6;

// The meshes, built on the CPU. Leaf vertices carry their shape (kLeaf*) in normal.w; the leaf shapes share the
// leaf kind's range and each instance keeps only the triangles of its own shape. `leafModels` add shapes after
// the built-in ones: model k is shape kSurfaceLastShape + 1 + k.
OrganMeshData buildOrganMeshes(const std::vector<ir::LeafModel>& leafModels = {});

// The meshes on the device, usable as vertex, index and storage buffers.
class OrganMeshes {
public:
    explicit OrganMeshes(const vk::Context& context, const std::vector<ir::LeafModel>& leafModels = {});

    const OrganMeshData& data() const { return data_; }
    const vk::Buffer& vertices() const { return vertices_; }
    const vk::Buffer& indices() const { return indices_; }
    const vk::Buffer& leafShapeTriangles() const { return leafShapeTriangles_; }
    const vk::Buffer& leafHullTriangles() const { return leafHullTriangles_; }
    const vk::Buffer& leafFarHullTriangles() const { return leafFarHullTriangles_; }
    const vk::Buffer& leafFarShadowTriangles() const { return leafFarShadowTriangles_; }
    const vk::Buffer& interiorEdges() const { return interiorEdges_; }

private:
    OrganMeshData data_;
    vk::Buffer vertices_;
    vk::Buffer indices_;
    vk::Buffer leafShapeTriangles_;
    vk::Buffer leafHullTriangles_;
    vk::Buffer leafFarHullTriangles_;
    vk::Buffer leafFarShadowTriangles_;
    vk::Buffer interiorEdges_;
};

} // namespace simeco::draw
