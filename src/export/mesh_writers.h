// Mesh files of the organs: Wavefront OBJ and binary PLY of the world-space triangles (gltf_writer.h writes
// glTF). Each is written atomically (draw/atomic_file.h): a failure throws draw::OutputError naming the file
// and leaves nothing behind.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "export/organ_geometry.h"

namespace simeco::exporter {

enum class MeshFormat { Obj, Ply, Gltf };

// The format a file name asks for by its extension (.obj, .ply, .gltf, any case); none for another.
std::optional<MeshFormat> meshFormatOf(const std::filesystem::path& path);

// `comment` goes into the file's header (one line: where the geometry comes from).
//
// OBJ: one object `plant_N` per plant run, `v x y z r g b` with sRGB vertex colours (what OBJ readers that
// take vertex colours expect), `vn`, and faces `f a//a b//b c//c`.
void writeObj(const std::filesystem::path& path, const WorldMesh& mesh, const std::string& comment);

// PLY, binary little-endian: vertices x y z nx ny nz (float) red green blue (uchar, sRGB), faces
// vertex_indices (uchar count 3, int) and plant (int).
void writePly(const std::filesystem::path& path, const WorldMesh& mesh, const std::string& comment);

} // namespace simeco::exporter
