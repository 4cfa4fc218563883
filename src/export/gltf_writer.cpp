#include "export/gltf_writer.h"

#include <array>
#include <bit>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

#include "draw/atomic_file.h"
#include "export/output_file.h"

namespace simeco::exporter {
namespace {

using nlohmann::json;
using shared::OrganInstance;

// glTF 2.0 constants (accessor.componentType, bufferView.target, primitive.mode).
constexpr int kFloat = 5126;
constexpr int kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962;
constexpr int kElementArrayBuffer = 34963;
constexpr int kTriangles = 4;
constexpr const char* kInstancing = "EXT_mesh_gpu_instancing";

std::string base64(const std::vector<std::uint8_t>& bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        std::uint32_t chunk = std::uint32_t(bytes[i]) << 16;
        if (i + 1 < bytes.size()) chunk |= std::uint32_t(bytes[i + 1]) << 8;
        if (i + 2 < bytes.size()) chunk |= bytes[i + 2];
        out += kDigits[(chunk >> 18) & 63];
        out += kDigits[(chunk >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(chunk >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[chunk & 63] : '=';
    }
    return out;
}

// The JSON document and its binary buffer, grown a view and an accessor at a time.
class GltfBuilder {
public:
    GltfBuilder() {
        for (const char* array : {"accessors", "bufferViews", "meshes", "materials", "nodes"}) {
            doc_[array] = json::array();
        }
    }

    json& doc() { return doc_; }
    const std::vector<std::uint8_t>& buffer() const { return buffer_; }

    // Vertex attributes: positions carry min and max, which glTF requires of POSITION.
    int vec3Accessor(const std::vector<glm::vec3>& values, std::optional<int> target, bool bounds) {
        std::vector<float> flat;
        flat.reserve(3 * values.size());
        for (const glm::vec3& v : values) {
            flat.insert(flat.end(), {v.x, v.y, v.z});
        }
        int index = accessor(view(flat, target), kFloat, values.size(), "VEC3");
        if (bounds) {
            glm::vec3 lo(INFINITY), hi(-INFINITY);
            for (const glm::vec3& v : values) {
                if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) {
                    throw std::runtime_error("an organ has a vertex that is not a finite number");
                }
                lo = glm::min(lo, v);
                hi = glm::max(hi, v);
            }
            doc_["accessors"][index]["min"] = {lo.x, lo.y, lo.z};
            doc_["accessors"][index]["max"] = {hi.x, hi.y, hi.z};
        }
        return index;
    }

    int quaternionAccessor(const std::vector<glm::quat>& values) {
        std::vector<float> flat;
        flat.reserve(4 * values.size());
        for (const glm::quat& q : values) {
            flat.insert(flat.end(), {q.x, q.y, q.z, q.w}); // glTF stores x, y, z, w
        }
        return accessor(view(flat, std::nullopt), kFloat, values.size(), "VEC4");
    }

    int indexAccessor(const std::vector<std::uint32_t>& indices) {
        return accessor(view(indices, kElementArrayBuffer), kUnsignedInt, indices.size(), "SCALAR");
    }

    // A mesh of one triangle primitive; COLOR_0 when `colors` is given.
    int mesh(const std::string& name, const std::vector<glm::vec3>& positions, const std::vector<glm::vec3>& normals,
             const std::vector<glm::vec3>* colors, const std::vector<std::uint32_t>& indices, int material) {
        json attributes;
        attributes["POSITION"] = vec3Accessor(positions, kArrayBuffer, true);
        attributes["NORMAL"] = vec3Accessor(normals, kArrayBuffer, false);
        if (colors != nullptr) {
            attributes["COLOR_0"] = vec3Accessor(*colors, kArrayBuffer, false);
        }
        json primitive = {{"attributes", attributes},
                          {"indices", indexAccessor(indices)},
                          {"material", material},
                          {"mode", kTriangles}};
        doc_["meshes"].push_back({{"name", name}, {"primitives", json::array({primitive})}});
        return static_cast<int>(doc_["meshes"].size()) - 1;
    }

    int node(json node) {
        doc_["nodes"].push_back(std::move(node));
        return static_cast<int>(doc_["nodes"].size()) - 1;
    }

private:
    // Every view starts 4-byte aligned: all components here are 4 bytes, and glTF wants each accessor
    // aligned to its component size (vertex attributes to 4). Values are stored little-endian, as glTF says.
    template <typename T> int view(const std::vector<T>& values, std::optional<int> target) {
        static_assert(sizeof(T) == 4);
        while (buffer_.size() % 4 != 0) {
            buffer_.push_back(0);
        }
        std::size_t offset = buffer_.size();
        for (T value : values) {
            auto bits = std::bit_cast<std::uint32_t>(value);
            for (int i = 0; i < 4; ++i) {
                buffer_.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
            }
        }
        json v = {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", buffer_.size() - offset}};
        if (target) {
            v["target"] = *target;
        }
        doc_["bufferViews"].push_back(std::move(v));
        return static_cast<int>(doc_["bufferViews"].size()) - 1;
    }

    int accessor(int bufferView, int componentType, std::size_t count, const char* type) {
        doc_["accessors"].push_back(
            {{"bufferView", bufferView}, {"componentType", componentType}, {"count", count}, {"type", type}});
        return static_cast<int>(doc_["accessors"].size()) - 1;
    }

    json doc_;
    std::vector<std::uint8_t> buffer_;
};

// Instances of one kind (and one leaf shape), in the order of `organs`.
std::vector<std::uint32_t> selectInstances(std::span<const OrganInstance> organs, const OrganMeshSet& meshes,
                                           std::uint32_t kind, std::optional<std::uint32_t> shape) {
    std::vector<std::uint32_t> chosen;
    for (std::uint32_t i = 0; i < organs.size(); ++i) {
        if (organs[i].kind == kind && (!shape || meshes.shapeOf(organs[i]) == *shape)) {
            chosen.push_back(i);
        }
    }
    return chosen;
}

std::string meshName(std::uint32_t kind, std::optional<std::uint32_t> shape) {
    std::string name = organKindName(kind);
    return shape ? name + "_" + leafShapeName(*shape) : name;
}

// An instanced node: the kind's mesh in organ-local coordinates, placed by each instance's transform.
int instancedNode(GltfBuilder& gltf, std::span<const OrganInstance> organs, const std::vector<std::uint32_t>& chosen,
                  const OrganMesh& local, const std::string& name, int material) {
    std::vector<glm::vec3> positions, normals;
    for (const shared::MeshVertex& v : local.vertices) {
        positions.emplace_back(v.position.x, v.position.y, v.position.z);
        normals.emplace_back(v.normal.x, v.normal.y, v.normal.z);
    }
    int mesh = gltf.mesh(name, positions, normals, nullptr, local.indices, material);

    std::vector<glm::vec3> translations, scales, colors;
    std::vector<glm::quat> rotations;
    for (std::uint32_t i : chosen) {
        InstanceTransform t = instanceTransform(organs[i]);
        translations.push_back(t.translation);
        rotations.push_back(t.rotation);
        scales.push_back(t.scale);
        colors.emplace_back(organs[i].color.x, organs[i].color.y, organs[i].color.z);
    }
    json attributes = {{"TRANSLATION", gltf.vec3Accessor(translations, std::nullopt, false)},
                       {"ROTATION", gltf.quaternionAccessor(rotations)},
                       {"SCALE", gltf.vec3Accessor(scales, std::nullopt, false)},
                       {"_COLOR_0", gltf.vec3Accessor(colors, std::nullopt, false)}};
    return gltf.node({{"name", name}, {"mesh", mesh}, {"extensions", {{kInstancing, {{"attributes", attributes}}}}}});
}

// A node of world-space triangles with the instances' colours.
int bakedNode(GltfBuilder& gltf, std::span<const OrganInstance> organs, const std::vector<std::uint32_t>& chosen,
              const OrganMeshSet& meshes, const std::string& name, int material) {
    WorldMesh world = placeOrgans(organs, chosen, meshes);
    for (glm::vec3& c : world.colors) {
        c = glm::clamp(c, glm::vec3(0.0f), glm::vec3(1.0f)); // COLOR_0 holds values in [0, 1]
    }
    int mesh = gltf.mesh(name, world.positions, world.normals, &world.colors, world.indices, material);
    return gltf.node({{"name", name}, {"mesh", mesh}});
}

std::string gltfText(std::span<const OrganInstance> organs, const OrganMeshSet& meshes, const GltfOptions& options) {
    GltfBuilder gltf;
    json& doc = gltf.doc();
    doc["asset"] = {{"version", "2.0"},
                    {"generator", "simeco export"},
                    {"extras", {{"source", options.source}, {"plants", options.plants}, {"organs", organs.size()}}}};

    json children = json::array();
    bool instanced = false;
    for (std::uint32_t kind = 0; kind < shared::kOrganKinds; ++kind) {
        if (selectInstances(organs, meshes, kind, std::nullopt).empty()) {
            continue;
        }
        // Open surfaces are seen from both sides, as the renderer draws them.
        bool closed = kind == shared::kOrganStem || kind == shared::kOrganSphere;
        doc["materials"].push_back(
            {{"name", organKindName(kind)},
             {"pbrMetallicRoughness",
              {{"baseColorFactor", {1.0, 1.0, 1.0, 1.0}}, {"metallicFactor", 0.0}, {"roughnessFactor", 0.8}}},
             {"doubleSided", !closed}});
        int material = static_cast<int>(doc["materials"].size()) - 1;

        std::vector<std::optional<std::uint32_t>> shapes{std::nullopt};
        if (kind == shared::kOrganLeaf) {
            shapes.clear();
            for (std::uint32_t s = 0; s < meshes.leafShapes(); ++s)
                shapes.push_back(s);
        }
        for (std::optional<std::uint32_t> shape : shapes) {
            std::vector<std::uint32_t> chosen = selectInstances(organs, meshes, kind, shape);
            if (chosen.empty()) {
                continue;
            }
            std::string name = meshName(kind, shape);
            if (options.instancing && isAffineKind(kind)) {
                children.push_back(
                    instancedNode(gltf, organs, chosen, meshes.mesh(kind, shape.value_or(0)), name, material));
                instanced = true;
            } else {
                children.push_back(bakedNode(gltf, organs, chosen, meshes, name, material));
            }
        }
    }
    std::string rootName = options.source.empty() ? "simeco" : std::filesystem::path(options.source).stem().string();
    json rootNode = {{"name", rootName}};
    if (!children.empty()) {
        rootNode["children"] = children; // glTF arrays, when present, are not empty
    }
    int root = gltf.node(rootNode);
    doc["scenes"] = json::array({{{"nodes", {root}}}});
    doc["scene"] = 0;
    if (instanced) {
        // Required, not only used: a viewer without the extension would draw each instanced mesh once, at the
        // origin, instead of the plants.
        doc["extensionsUsed"] = {kInstancing};
        doc["extensionsRequired"] = {kInstancing};
    }
    if (!gltf.buffer().empty()) {
        doc["buffers"] = json::array({{{"byteLength", gltf.buffer().size()},
                                       {"uri", "data:application/octet-stream;base64," + base64(gltf.buffer())}}});
    }
    // The same for the top-level arrays: nothing drawn leaves a scene of one empty node.
    for (const char* array : {"accessors", "bufferViews", "meshes", "materials"}) {
        if (doc[array].empty()) {
            doc.erase(array);
        }
    }
    return doc.dump();
}

} // namespace

void writeGltf(const std::filesystem::path& path, std::span<const OrganInstance> organs, const OrganMeshSet& meshes,
               const GltfOptions& options) {
    std::string text;
    try {
        text = gltfText(organs, meshes, options);
    } catch (const std::runtime_error& e) {
        throw draw::OutputError("cannot write '" + path.string() + "': " + e.what());
    } catch (const std::length_error& e) {
        throw draw::OutputError("cannot write '" + path.string() + "': " + e.what());
    }
    draw::writeAtomically(path, [&](const std::filesystem::path& temporary) {
        OutputFile file(temporary);
        file.write(text);
        file.write("\n");
        file.close();
    });
}

} // namespace simeco::exporter
