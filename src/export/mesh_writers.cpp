#include "export/mesh_writers.h"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <vector>

#include <fmt/format.h>

#include "draw/atomic_file.h"
#include "export/output_file.h"

namespace simeco::exporter {
namespace {

// Text is gathered in a buffer and written in pieces of about this size, so a large field never sits whole
// in memory twice.
constexpr std::size_t kFlushBytes = 1 << 20;

std::string oneLine(const std::string& text) {
    std::string line = text;
    std::replace_if(
        line.begin(), line.end(), [](char c) { return c == '\n' || c == '\r'; }, ' ');
    return line;
}

void flushIfFull(fmt::memory_buffer& buffer, OutputFile& file, bool force = false) {
    if (force || buffer.size() >= kFlushBytes) {
        file.write(buffer.data(), buffer.size());
        buffer.clear();
    }
}

std::uint8_t srgbByte(float linear) {
    return static_cast<std::uint8_t>(std::lround(srgbEncode(linear) * 255.0f));
}

// Little-endian whatever the host, as the PLY header declares.
void putU32(std::vector<std::uint8_t>& out, std::uint32_t v) {
    for (int i = 0; i < 4; ++i) {
        out.push_back(static_cast<std::uint8_t>(v >> (8 * i)));
    }
}

void putFloat(std::vector<std::uint8_t>& out, float v) {
    putU32(out, std::bit_cast<std::uint32_t>(v));
}

} // namespace

std::optional<MeshFormat> meshFormatOf(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".obj") return MeshFormat::Obj;
    if (ext == ".ply") return MeshFormat::Ply;
    if (ext == ".gltf") return MeshFormat::Gltf;
    return std::nullopt;
}

void writeObj(const std::filesystem::path& path, const WorldMesh& mesh, const std::string& comment) {
    draw::writeAtomically(path, [&](const std::filesystem::path& temporary) {
        OutputFile file(temporary);
        fmt::memory_buffer out;
        auto text = std::back_inserter(out);
        fmt::format_to(text, "# {}\n", oneLine(comment));
        fmt::format_to(text, "# {} vertices, {} triangles, {} plant runs; vertex colours (after x y z) are sRGB\n",
                       mesh.positions.size(), mesh.triangleCount(), mesh.plants.size());
        for (const WorldMesh::PlantRun& run : mesh.plants) {
            fmt::format_to(text, "o plant_{}\n", run.plant);
            for (std::uint32_t v = run.firstVertex; v < run.firstVertex + run.vertexCount; ++v) {
                const glm::vec3& p = mesh.positions[v];
                const glm::vec3& c = mesh.colors[v];
                fmt::format_to(text, "v {} {} {} {:.4f} {:.4f} {:.4f}\n", p.x, p.y, p.z, srgbEncode(c.x),
                               srgbEncode(c.y), srgbEncode(c.z));
                flushIfFull(out, file);
            }
            for (std::uint32_t v = run.firstVertex; v < run.firstVertex + run.vertexCount; ++v) {
                const glm::vec3& n = mesh.normals[v];
                fmt::format_to(text, "vn {:.5f} {:.5f} {:.5f}\n", n.x, n.y, n.z);
                flushIfFull(out, file);
            }
            for (std::uint32_t t = run.firstTriangle; t < run.firstTriangle + run.triangleCount; ++t) {
                // OBJ counts vertices from 1.
                std::uint64_t a = std::uint64_t(mesh.indices[3 * t]) + 1;
                std::uint64_t b = std::uint64_t(mesh.indices[3 * t + 1]) + 1;
                std::uint64_t c = std::uint64_t(mesh.indices[3 * t + 2]) + 1;
                fmt::format_to(text, "f {0}//{0} {1}//{1} {2}//{2}\n", a, b, c);
                flushIfFull(out, file);
            }
        }
        flushIfFull(out, file, true);
        file.close();
    });
}

void writePly(const std::filesystem::path& path, const WorldMesh& mesh, const std::string& comment) {
    // PLY's `int` indices are signed.
    if (mesh.positions.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max())) {
        throw draw::OutputError("cannot write '" + path.string() + "': " + std::to_string(mesh.positions.size()) +
                                " vertices are more than PLY's int indices reach");
    }
    std::string header = fmt::format("ply\n"
                                     "format binary_little_endian 1.0\n"
                                     "comment {}\n"
                                     "comment vertex colours are sRGB; face property plant is the plant index\n"
                                     "element vertex {}\n"
                                     "property float x\nproperty float y\nproperty float z\n"
                                     "property float nx\nproperty float ny\nproperty float nz\n"
                                     "property uchar red\nproperty uchar green\nproperty uchar blue\n"
                                     "element face {}\n"
                                     "property list uchar int vertex_indices\n"
                                     "property int plant\n"
                                     "end_header\n",
                                     oneLine(comment), mesh.positions.size(), mesh.triangleCount());
    draw::writeAtomically(path, [&](const std::filesystem::path& temporary) {
        OutputFile file(temporary);
        file.write(header);
        std::vector<std::uint8_t> out;
        out.reserve(kFlushBytes + 64);
        auto flush = [&](bool force) {
            if (force || out.size() >= kFlushBytes) {
                file.write(out.data(), out.size());
                out.clear();
            }
        };
        for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
            for (const glm::vec3* attribute : {&mesh.positions[v], &mesh.normals[v]}) {
                putFloat(out, attribute->x);
                putFloat(out, attribute->y);
                putFloat(out, attribute->z);
            }
            const glm::vec3& c = mesh.colors[v];
            out.insert(out.end(), {srgbByte(c.x), srgbByte(c.y), srgbByte(c.z)});
            flush(false);
        }
        for (const WorldMesh::PlantRun& run : mesh.plants) {
            for (std::uint32_t t = run.firstTriangle; t < run.firstTriangle + run.triangleCount; ++t) {
                out.push_back(3);
                for (int c = 0; c < 3; ++c) {
                    putU32(out, mesh.indices[3 * t + static_cast<std::uint32_t>(c)]);
                }
                putU32(out, run.plant);
                flush(false);
            }
        }
        flush(true);
        file.close();
    });
}

} // namespace simeco::exporter
