// glTF 2.0 of the organs: one .gltf JSON file with its binary buffer embedded as a base64 data URI.
//
// Organs whose placement is affine (spheres, discs, leaves) are stored once per kind (leaves once per shape)
// in organ-local coordinates, on a node instancing it with EXT_mesh_gpu_instancing (TRANSLATION, ROTATION,
// SCALE and the custom `_COLOR_0`, linear RGB, which three.js reads as the instance colour). Stems (tapered,
// mitred on their joints) and polygon triangles are baked into world space with COLOR_0. Every kind has its
// own material, white, because glTF multiplies a colour attribute by the base colour.
#pragma once

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>

#include "compute/shared/organ_layout.h"
#include "export/organ_geometry.h"

namespace simeco::exporter {

struct GltfOptions {
    // false: bake every organ into world space, for viewers without EXT_mesh_gpu_instancing.
    bool instancing = true;
    std::string source; // the grammar or scene, named in the asset's extras
    std::uint32_t plants = 0;
};

// Writes atomically (draw/atomic_file.h); throws draw::OutputError naming the file on failure.
void writeGltf(const std::filesystem::path& path, std::span<const shared::OrganInstance> organs,
               const OrganMeshSet& meshes, const GltfOptions& options);

} // namespace simeco::exporter
