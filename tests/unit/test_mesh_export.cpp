// Mesh export: organ instances placed on the CPU as the renderer places them, and the OBJ, PLY and glTF files
// read back and checked against the instances they came from.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "draw/atomic_file.h"
#include "draw/organ_meshes.h"
#include "export/gltf_writer.h"
#include "export/mesh_writers.h"
#include "export/organ_geometry.h"
#include "grammar_text.h"
#include "lang/load_grammar.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"

namespace {

namespace fs = std::filesystem;
using namespace simeco;
using nlohmann::json;
using shared::OrganInstance;
using simeco::testing::grammarFromText;
using simeco::testing::lsystem;

turtle::Interpretation interpret(const ir::Grammar& g, uint32_t plants, int steps = -1) {
    stream::DeriveOptions options;
    options.plants = plants;
    options.steps = steps;
    options.homomorphism = true;
    stream::DeriveResult r = cpu::deriveCpu(g, options);
    return turtle::interpretCpu(r.string, turtle::turtleCommands(g.alphabet), {turtle::turtleSettings(g, g.alphabet)});
}

// A plant with every organ kind: stems bent at joints, a leaf, a sphere, discs of both kinds, a polygon.
turtle::Interpretation everyKind(uint32_t plants) {
    ir::Grammar g = grammarFromText(
        lsystem("F!(0.6)F[+(40)F~l]F[-(50)F@O(0.3)][&(30)F@c(0.5)][^(30)F@o(0.4)]{.f+(90)f+(90)f}", "", 0));
    g.view.undefinedSurfacesDrawn = true; // `~l` a built-in blade, as a quick grammar draws it
    return interpret(g, plants);
}

// ABOP fig. 1.24a, a bracketed plant of stems only, three steps.
turtle::Interpretation smallTree(uint32_t plants) {
    return interpret(lang::loadGrammarFile(SIMECO_SOURCE_DIR "/grammars/abop/fig1.24a.l"), plants, 3);
}

// A scratch folder of this process, removed with everything in it.
struct ScratchDir {
    fs::path path = fs::temp_directory_path() / ("simeco-export-test-" + std::to_string(::getpid()));
    ScratchDir() {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~ScratchDir() { fs::remove_all(path); }
    std::vector<std::string> entries() const {
        std::vector<std::string> names;
        for (const auto& e : fs::directory_iterator(path))
            names.push_back(e.path().filename().string());
        return names;
    }
};

glm::vec3 xyz(const shared::vec4& v) {
    return {v.x, v.y, v.z};
}

// The vertices an instance's drawn mesh has, counted from the renderer's buffers directly: the indices its
// kind's range uses, and for a leaf only those of its own shape.
std::size_t drawnVertexCount(const draw::OrganMeshData& d, const OrganInstance& o) {
    const draw::MeshRange& r = d.organs[o.kind];
    std::set<std::uint32_t> used;
    for (std::uint32_t i = 0; i < r.indexCount; ++i) {
        std::uint32_t v = static_cast<std::uint32_t>(r.vertexOffset) + d.indices[r.firstIndex + i];
        bool ownShape = std::lround(d.vertices[v].normal.w) == long(o.shape);
        if (o.kind != shared::kOrganLeaf || ownShape) used.insert(v);
    }
    return used.size();
}

struct ObjFile {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> colors;
    std::size_t normals = 0;
    std::vector<std::array<long, 3>> faces;
    std::vector<std::string> objects;
};

ObjFile readObj(const fs::path& path) {
    ObjFile obj;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream s(line);
        std::string tag;
        s >> tag;
        if (tag == "v") {
            glm::vec3 p, c;
            s >> p.x >> p.y >> p.z >> c.x >> c.y >> c.z;
            obj.positions.push_back(p);
            obj.colors.push_back(c);
        } else if (tag == "vn") {
            ++obj.normals;
        } else if (tag == "f") {
            std::array<long, 3> f{};
            for (long& index : f) {
                std::string corner;
                s >> corner;
                long normal = 0;
                EXPECT_EQ(std::sscanf(corner.c_str(), "%ld//%ld", &index, &normal), 2) << line;
                EXPECT_EQ(index, normal) << line;
            }
            obj.faces.push_back(f);
        } else if (tag == "o") {
            std::string name;
            s >> name;
            obj.objects.push_back(name);
        }
    }
    return obj;
}

turtle::Bounds boundsOf(const std::vector<glm::vec3>& points) {
    turtle::Bounds b;
    for (glm::vec3 p : points)
        b.add(p);
    return b;
}

TEST(MeshExport, ObjHasEachInstancesDrawnMeshPlantByPlant) {
    ScratchDir dir;
    for (bool allKinds : {false, true}) {
        turtle::Interpretation interp = allKinds ? everyKind(3) : smallTree(2);
        ASSERT_FALSE(interp.organs.empty());
        draw::OrganMeshData data = draw::buildOrganMeshes();
        exporter::OrganMeshSet meshes(data);
        exporter::WorldMesh mesh = exporter::placeOrgans(interp.organs, exporter::plantOrder(interp.organs), meshes);
        fs::path path = dir.path / "plants.obj";
        exporter::writeObj(path, mesh, "test");

        ObjFile obj = readObj(path);
        std::size_t expected = 0;
        for (const OrganInstance& o : interp.organs)
            expected += drawnVertexCount(data, o);
        EXPECT_EQ(obj.positions.size(), expected);
        EXPECT_EQ(obj.normals, expected);
        EXPECT_EQ(obj.faces.size(), mesh.triangleCount());
        for (const auto& f : obj.faces)
            for (long index : f)
                ASSERT_TRUE(index >= 1 && index <= static_cast<long>(expected));
        std::vector<std::string> plants;
        for (std::size_t p = 0; p < interp.plantOrigins.size(); ++p)
            plants.push_back("plant_" + std::to_string(p));
        EXPECT_EQ(obj.objects, plants) << "one object per plant, in order";
        // The colours are the instances' linear colours, sRGB-encoded.
        const OrganInstance& first = interp.organs[exporter::plantOrder(interp.organs)[0]];
        EXPECT_NEAR(obj.colors[0].x, exporter::srgbEncode(first.color.x), 1e-3f);
    }
}

TEST(MeshExport, ObjBoundsMatchTheInterpretation) {
    ScratchDir dir;
    turtle::Interpretation interp = smallTree(4);
    exporter::OrganMeshSet meshes(draw::buildOrganMeshes());
    fs::path path = dir.path / "tree.obj";
    exporter::writeObj(path, exporter::placeOrgans(interp.organs, exporter::plantOrder(interp.organs), meshes), "t");
    turtle::Bounds got = boundsOf(readObj(path).positions);
    // The turtle's bounds take each stem end as a cube of the stem's radius; the mesh is a 12-sided prism whose
    // mitred ends reach up to 5 radii along the stem (the shaders' bound on the mitre). Within that, they agree.
    float radius = 0;
    for (const OrganInstance& o : interp.organs)
        radius = std::max({radius, o.heading.w, o.up.w});
    ASSERT_GT(radius, 0.0f);
    glm::vec3 extent = interp.bounds.max - interp.bounds.min;
    ASSERT_GT(std::min(extent.x, extent.y), 20 * radius) << "the plants are large against their stems";
    for (int axis = 0; axis < 3; ++axis) {
        if (extent[axis] < 20 * radius) continue; // a flat plant's depth is all radius
        EXPECT_NEAR(got.min[axis], interp.bounds.min[axis], 5 * radius) << "axis " << axis;
        EXPECT_NEAR(got.max[axis], interp.bounds.max[axis], 5 * radius) << "axis " << axis;
    }
}

TEST(MeshExport, StemVerticesLieAtTheirRadiusAndJointsShareTheirPlane) {
    turtle::Interpretation interp = interpret(grammarFromText(lsystem("F(2)!(0.5)+(60)F(3)", "", 0)), 1);
    ASSERT_EQ(interp.count[shared::kOrganStem], 2u);
    draw::OrganMeshData data = draw::buildOrganMeshes();
    exporter::OrganMeshSet meshes(data);
    const exporter::OrganMesh& stem = meshes.mesh(shared::kOrganStem);
    ASSERT_EQ(stem.vertices.size(), 2 * draw::kStemSides + 2 * (draw::kStemSides + 1));

    const OrganInstance& a = interp.organs[0];
    const OrganInstance& b = interp.organs[1];
    EXPECT_NE(a.heading.w, b.heading.w) << "the second stem is thinner";
    glm::vec3 joint = xyz(b.position);
    glm::vec3 bisector = glm::normalize(xyz(a.heading) + xyz(b.heading));
    int ringVertices = 0;
    for (const OrganInstance* o : {&a, &b}) {
        glm::vec3 base = xyz(o->position), h = xyz(o->heading);
        for (const shared::MeshVertex& local : stem.vertices) {
            exporter::PlacedVertex v = exporter::placeVertex(*o, shared::kOrganStem, local);
            bool top = local.position.w > 0.5f;
            float radius = top ? o->up.w : o->heading.w;
            glm::vec3 offset = v.position - base;
            float fromAxis = glm::length(offset - glm::dot(offset, h) * h);
            bool onRing = local.normal.w < 0.5f || glm::length(glm::vec2(local.position.y, local.position.z)) > 0.5f;
            if (onRing) {
                EXPECT_NEAR(fromAxis, radius, 1e-4f);
                ++ringVertices;
            } else {
                EXPECT_NEAR(fromAxis, 0.0f, 1e-4f) << "a cap's centre is on the axis";
            }
            EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-5f);
            // The shared joint: a's top and b's bottom are cut on the plane bisecting their headings.
            if ((o == &a) == top) {
                EXPECT_NEAR(glm::dot(v.position - joint, bisector), 0.0f, 1e-4f);
            }
        }
    }
    EXPECT_EQ(ringVertices, 2 * 4 * static_cast<int>(draw::kStemSides));
}

TEST(MeshExport, AGeneralizedCylindersCornersHaveSmoothNormals) {
    // A straight round cylinder of width 2 (cpfg's mesh, `line style: cylinder`): every corner's normal points
    // straight out from the axis, on whichever triangle it lies, not along the triangle's own facing.
    ir::Grammar g = grammarFromText(lsystem("#(2)@GsF(3)@Ge(2)", "", 0));
    g.view.cpfgCylinders = true;
    g.view.lineStyle = ir::LineStyle::Cylinder;
    g.view.cylinderSides = 8;
    turtle::Interpretation interp = interpret(g, 1);
    ASSERT_EQ(interp.count[shared::kOrganTriangle], 2u * 2u * 8u);
    draw::OrganMeshData data = draw::buildOrganMeshes();
    exporter::OrganMeshSet meshes(data);
    const exporter::OrganMesh& triangle = meshes.mesh(shared::kOrganTriangle);
    int corners = 0;
    for (uint32_t k = 0; k < interp.count[shared::kOrganTriangle]; ++k) {
        const OrganInstance& o = interp.organs[interp.first[shared::kOrganTriangle] + k];
        ASSERT_EQ(o.shape, shared::kTriangleOfCylinder);
        for (const shared::MeshVertex& local : triangle.vertices) {
            const exporter::PlacedVertex v = exporter::placeVertex(o, shared::kOrganTriangle, local);
            const glm::vec3 out = glm::normalize(glm::vec3(v.position.x, 0.0f, v.position.z));
            EXPECT_NEAR(glm::distance(v.normal, out), 0.0f, 1e-5f);
            ++corners;
        }
    }
    EXPECT_EQ(corners, 3 * 2 * 2 * 8);
}

TEST(MeshExport, AffineKindsPlaceTheirMeshByTheirInstanceTransform) {
    turtle::Interpretation interp = everyKind(1);
    exporter::OrganMeshSet meshes(draw::buildOrganMeshes());
    int checked = 0;
    for (const OrganInstance& o : interp.organs) {
        if (!exporter::isAffineKind(o.kind)) continue;
        exporter::InstanceTransform t = exporter::instanceTransform(o);
        EXPECT_NEAR(glm::length(t.rotation), 1.0f, 1e-5f);
        for (const shared::MeshVertex& local : meshes.forInstance(o).vertices) {
            exporter::PlacedVertex v = exporter::placeVertex(o, o.kind, local);
            ASSERT_TRUE(v.present);
            glm::vec3 p = t.translation +
                          t.rotation * (t.scale * glm::vec3(local.position.x, local.position.y, local.position.z));
            EXPECT_NEAR(glm::length(p - v.position), 0.0f, 1e-4f) << exporter::organKindName(o.kind);
            glm::vec3 n = t.rotation * glm::vec3(local.normal.x, local.normal.y, local.normal.z);
            EXPECT_GT(glm::dot(n, v.normal), 0.999f) << exporter::organKindName(o.kind);
        }
        ++checked;
    }
    EXPECT_EQ(checked, 4) << "a sphere, two discs and a leaf";
}

TEST(MeshExport, PlyHeaderParsesAndTheBinaryBodyHasItsSize) {
    ScratchDir dir;
    turtle::Interpretation interp = everyKind(2);
    exporter::OrganMeshSet meshes(draw::buildOrganMeshes());
    exporter::WorldMesh mesh = exporter::placeOrgans(interp.organs, exporter::plantOrder(interp.organs), meshes);
    fs::path path = dir.path / "plants.ply";
    exporter::writePly(path, mesh, "from a test\nwith a line break");

    std::ifstream in(path, std::ios::binary);
    std::string line;
    std::vector<std::string> header;
    std::size_t vertices = 0, faces = 0;
    while (std::getline(in, line) && line != "end_header") {
        header.push_back(line);
        std::sscanf(line.c_str(), "element vertex %zu", &vertices);
        std::sscanf(line.c_str(), "element face %zu", &faces);
    }
    ASSERT_EQ(line, "end_header");
    ASSERT_GE(header.size(), 3u);
    EXPECT_EQ(header[0], "ply");
    EXPECT_EQ(header[1], "format binary_little_endian 1.0");
    EXPECT_EQ(header[2], "comment from a test with a line break");
    EXPECT_EQ(vertices, mesh.positions.size());
    EXPECT_EQ(faces, mesh.triangleCount());
    auto bodyStart = static_cast<std::size_t>(in.tellg());
    std::size_t vertexBytes = 6 * 4 + 3, faceBytes = 1 + 3 * 4 + 4;
    EXPECT_EQ(fs::file_size(path), bodyStart + vertices * vertexBytes + faces * faceBytes);

    std::vector<char> body(fs::file_size(path) - bodyStart);
    in.read(body.data(), static_cast<std::streamsize>(body.size()));
    float first[3];
    std::memcpy(first, body.data(), sizeof first);
    EXPECT_EQ(first[0], mesh.positions[0].x);
    EXPECT_EQ(first[2], mesh.positions[0].z);
    // The last face: count 3, indices in range, the last plant.
    const char* lastFace = body.data() + vertices * vertexBytes + (faces - 1) * faceBytes;
    EXPECT_EQ(lastFace[0], 3);
    std::int32_t indices[3], plant;
    std::memcpy(indices, lastFace + 1, sizeof indices);
    std::memcpy(&plant, lastFace + 13, sizeof plant);
    for (std::int32_t i : indices)
        EXPECT_TRUE(i >= 0 && static_cast<std::size_t>(i) < vertices);
    EXPECT_EQ(plant, 1);
}

std::vector<std::uint8_t> decodeBase64(const std::string& text) {
    std::vector<std::uint8_t> out;
    std::uint32_t bits = 0;
    int count = 0;
    for (char c : text) {
        const char* digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
        const char* at = std::strchr(digits, c);
        if (c == '=' || at == nullptr) break;
        bits = (bits << 6) | static_cast<std::uint32_t>(at - digits);
        if (++count == 4) {
            out.insert(out.end(), {std::uint8_t(bits >> 16), std::uint8_t(bits >> 8), std::uint8_t(bits)});
            bits = 0;
            count = 0;
        }
    }
    if (count == 3) out.insert(out.end(), {std::uint8_t(bits >> 10), std::uint8_t(bits >> 2)});
    if (count == 2) out.push_back(std::uint8_t(bits >> 4));
    return out;
}

// A glTF file read back: the JSON and its embedded buffer, with the accessors' data as floats or uints.
struct Gltf {
    json doc;
    std::vector<std::uint8_t> buffer;

    std::size_t components(const json& accessor) const {
        std::string type = accessor["type"];
        return type == "SCALAR" ? 1 : type == "VEC3" ? 3 : type == "VEC4" ? 4 : 0;
    }
    // Checks the accessor lies inside its view and the view inside the buffer, then reads it.
    template <typename T> std::vector<T> read(int index) const {
        const json& a = doc["accessors"][index];
        const json& view = doc["bufferViews"][a["bufferView"].get<int>()];
        std::size_t offset = view["byteOffset"].get<std::size_t>() + a.value("byteOffset", std::size_t(0));
        std::size_t count = a["count"].get<std::size_t>() * components(a);
        EXPECT_EQ(offset % 4, 0u);
        EXPECT_FALSE(view.contains("byteStride")) << "tightly packed";
        EXPECT_LE(a.value("byteOffset", std::size_t(0)) + count * 4, view["byteLength"].get<std::size_t>());
        EXPECT_LE(view["byteOffset"].get<std::size_t>() + view["byteLength"].get<std::size_t>(), buffer.size());
        std::vector<T> values(count);
        if (offset + count * 4 <= buffer.size()) std::memcpy(values.data(), buffer.data() + offset, count * 4);
        return values;
    }
};

// glTF's schema gives every array at least one item.
void expectNoEmptyArrays(const json& value, const std::string& where = "") {
    if (value.is_array()) {
        EXPECT_FALSE(value.empty()) << where;
    }
    if (value.is_structured()) {
        for (auto it = value.begin(); it != value.end(); ++it)
            expectNoEmptyArrays(*it, where + "/" + (value.is_object() ? it.key() : "[]"));
    }
}

Gltf readGltf(const fs::path& path) {
    Gltf g;
    std::ifstream in(path);
    g.doc = json::parse(in);
    expectNoEmptyArrays(g.doc);
    if (!g.doc.contains("buffers")) return g;
    std::string uri = g.doc["buffers"][0]["uri"];
    const std::string prefix = "data:application/octet-stream;base64,";
    EXPECT_EQ(uri.rfind(prefix, 0), 0u);
    g.buffer = decodeBase64(uri.substr(prefix.size()));
    EXPECT_EQ(g.buffer.size(), g.doc["buffers"][0]["byteLength"].get<std::size_t>());
    return g;
}

// Every primitive: POSITION's min and max are those of its data, indices address its vertices, normals are unit.
// Returns the vertices of all meshes.
std::size_t checkMeshes(const Gltf& g) {
    std::size_t vertices = 0;
    for (const json& mesh : g.doc["meshes"]) {
        for (const json& primitive : mesh["primitives"]) {
            int position = primitive["attributes"]["POSITION"];
            const json& accessor = g.doc["accessors"][position];
            EXPECT_EQ(accessor["componentType"], 5126);
            std::vector<float> p = g.read<float>(position);
            std::size_t count = p.size() / 3;
            vertices += count;
            for (int axis = 0; axis < 3; ++axis) {
                float lo = INFINITY, hi = -INFINITY;
                for (std::size_t v = 0; v < count; ++v) {
                    lo = std::min(lo, p[3 * v + axis]);
                    hi = std::max(hi, p[3 * v + axis]);
                }
                EXPECT_EQ(accessor["min"][axis].get<float>(), lo) << mesh["name"];
                EXPECT_EQ(accessor["max"][axis].get<float>(), hi) << mesh["name"];
            }
            std::vector<float> n = g.read<float>(primitive["attributes"]["NORMAL"]);
            EXPECT_EQ(n.size(), p.size());
            for (std::size_t v = 0; v < count && 3 * v + 2 < n.size(); ++v)
                EXPECT_NEAR(glm::length(glm::vec3(n[3 * v], n[3 * v + 1], n[3 * v + 2])), 1.0f, 1e-4f);
            EXPECT_EQ(g.doc["accessors"][primitive["indices"].get<int>()]["componentType"], 5125);
            std::vector<std::uint32_t> indices = g.read<std::uint32_t>(primitive["indices"]);
            EXPECT_EQ(indices.size() % 3, 0u);
            EXPECT_TRUE(std::all_of(indices.begin(), indices.end(), [&](std::uint32_t i) { return i < count; }));
            EXPECT_TRUE(primitive.contains("material"));
        }
    }
    return vertices;
}

TEST(MeshExport, GltfInstancesAffineOrgansAndBakesTheRest) {
    ScratchDir dir;
    turtle::Interpretation interp = everyKind(3);
    exporter::OrganMeshSet meshes(draw::buildOrganMeshes());
    fs::path path = dir.path / "plants.gltf";
    exporter::GltfOptions options;
    options.source = "every-kind.l";
    options.plants = 3;
    exporter::writeGltf(path, interp.organs, meshes, options);

    Gltf g = readGltf(path);
    EXPECT_EQ(g.doc["asset"]["version"], "2.0");
    EXPECT_EQ(g.doc["extensionsUsed"], json::array({"EXT_mesh_gpu_instancing"}));
    EXPECT_EQ(g.doc["extensionsRequired"], json::array({"EXT_mesh_gpu_instancing"}));
    checkMeshes(g);

    std::array<std::size_t, shared::kOrganKinds> instanced{}, baked{};
    for (const json& node : g.doc["nodes"]) {
        if (!node.contains("mesh")) continue;
        std::string name = node["name"];
        std::uint32_t kind = 0;
        while (kind < shared::kOrganKinds && name.rfind(exporter::organKindName(kind), 0) != 0)
            ++kind;
        ASSERT_LT(kind, shared::kOrganKinds) << name;
        if (!node.contains("extensions")) {
            ++baked[kind];
            EXPECT_TRUE(g.doc["meshes"][node["mesh"].get<int>()]["primitives"][0]["attributes"].contains("COLOR_0"));
            continue;
        }
        const json& attributes = node["extensions"]["EXT_mesh_gpu_instancing"]["attributes"];
        std::size_t count = g.doc["accessors"][attributes["TRANSLATION"].get<int>()]["count"];
        for (const char* attribute : {"ROTATION", "SCALE", "_COLOR_0"})
            EXPECT_EQ(g.doc["accessors"][attributes[attribute].get<int>()]["count"], count) << attribute;
        std::vector<float> rotations = g.read<float>(attributes["ROTATION"]);
        for (std::size_t i = 0; i < count; ++i)
            EXPECT_NEAR(glm::length(glm::vec4(rotations[4 * i], rotations[4 * i + 1], rotations[4 * i + 2],
                                              rotations[4 * i + 3])),
                        1.0f, 1e-5f);
        instanced[kind] += count;
    }
    for (std::uint32_t kind : {shared::kOrganSphere, shared::kOrganDisc, shared::kOrganLeaf}) {
        EXPECT_GT(interp.count[kind], 0u);
        EXPECT_EQ(instanced[kind], interp.count[kind]) << exporter::organKindName(kind);
    }
    EXPECT_EQ(baked[shared::kOrganStem], 1u);
    EXPECT_EQ(baked[shared::kOrganTriangle], 1u);
    EXPECT_EQ(g.doc["scenes"][0]["nodes"].size(), 1u);
}

// A leaf drawn from a model (a cpfg surface, a scene's .obj) is exported with the model's own triangles, placed by
// its three scales; a mesh set without the model falls back to the ovate blade.
TEST(MeshExport, ALeafModelIsExportedWithItsOwnTriangles) {
    ir::LeafModel square; // two triangles: x along the heading from 0 to 1, y across from 0 to 1, z out of it 0.5
    square.corners = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5f}, {0, 0, 0}, {1, 1, 0.5f}, {0, 1, 0}};
    square.normals = {{0, 0, 1}, {0, 0, 1}};
    OrganInstance leaf{};
    leaf.kind = shared::kOrganLeaf;
    leaf.shape = shared::kSurfaceLastShape + 1;
    leaf.position = {1, 2, 3, 2.0f}; // along
    leaf.heading = {0, 1, 0, 3.0f};  // across
    leaf.up = {0, 0, 1, 4.0f};       // out of it
    const exporter::OrganMeshSet withModel(draw::buildOrganMeshes({square}));
    EXPECT_EQ(withModel.leafShapes(), exporter::kSurfaceShapes + 1);
    EXPECT_EQ(withModel.shapeOf(leaf), leaf.shape);
    const std::vector<std::uint32_t> order{0};
    exporter::WorldMesh mesh = exporter::placeOrgans(std::span(&leaf, 1), order, withModel);
    ASSERT_EQ(mesh.triangleCount(), 2u);
    // The corner (1, 1, 0.5): 2 along the heading (+y), 3 across (left, U x H = -x), 2 out of it (+z).
    bool found = false;
    for (const glm::vec3& p : mesh.positions) found = found || glm::length(p - glm::vec3(-2, 4, 5)) < 1e-5f;
    EXPECT_TRUE(found);
    const exporter::OrganMeshSet builtIn(draw::buildOrganMeshes());
    EXPECT_EQ(builtIn.shapeOf(leaf), shared::kLeafOvate);
    EXPECT_EQ(exporter::placeOrgans(std::span(&leaf, 1), order, builtIn).triangleCount(),
              builtIn.mesh(shared::kOrganLeaf, shared::kLeafOvate).indices.size() / 3);
    EXPECT_EQ(exporter::leafShapeName(leaf.shape), "model_0");
}

TEST(MeshExport, GltfWithoutInstancingBakesWhatTheObjHolds) {
    ScratchDir dir;
    turtle::Interpretation interp = everyKind(2);
    exporter::OrganMeshSet meshes(draw::buildOrganMeshes());
    exporter::GltfOptions options;
    options.instancing = false;
    exporter::writeGltf(dir.path / "flat.gltf", interp.organs, meshes, options);
    Gltf g = readGltf(dir.path / "flat.gltf");
    EXPECT_FALSE(g.doc.contains("extensionsUsed"));
    EXPECT_FALSE(g.doc.contains("extensionsRequired"));
    std::size_t vertices = checkMeshes(g);
    exporter::WorldMesh world = exporter::placeOrgans(interp.organs, exporter::plantOrder(interp.organs), meshes);
    EXPECT_EQ(vertices, world.positions.size());
}

TEST(MeshExport, GltfOfNothingIsStillValid) {
    ScratchDir dir;
    exporter::OrganMeshSet meshes(draw::buildOrganMeshes());
    exporter::writeGltf(dir.path / "empty.gltf", {}, meshes, {});
    Gltf g = readGltf(dir.path / "empty.gltf");
    EXPECT_EQ(g.doc["asset"]["version"], "2.0");
    EXPECT_FALSE(g.doc.contains("buffers"));
    EXPECT_EQ(g.doc["nodes"].size(), 1u);
}

TEST(MeshExport, AFailedWriteThrowsAndLeavesNoFile) {
    ScratchDir dir;
    turtle::Interpretation interp = smallTree(1);
    exporter::OrganMeshSet meshes(draw::buildOrganMeshes());
    exporter::WorldMesh mesh = exporter::placeOrgans(interp.organs, exporter::plantOrder(interp.organs), meshes);
    // A folder where the file should go: the temporary file is written, the rename over the folder fails.
    fs::create_directory(dir.path / "taken.obj");
    fs::create_directory(dir.path / "taken.ply");
    fs::create_directory(dir.path / "taken.gltf");
    EXPECT_THROW(exporter::writeObj(dir.path / "taken.obj", mesh, "t"), draw::OutputError);
    EXPECT_THROW(exporter::writePly(dir.path / "taken.ply", mesh, "t"), draw::OutputError);
    EXPECT_THROW(exporter::writeGltf(dir.path / "taken.gltf", interp.organs, meshes, {}), draw::OutputError);
    // A folder that does not exist: the temporary file cannot be opened.
    EXPECT_THROW(exporter::writeObj(dir.path / "missing" / "plants.obj", mesh, "t"), draw::OutputError);
    std::vector<std::string> entries = dir.entries();
    std::sort(entries.begin(), entries.end());
    EXPECT_EQ(entries, (std::vector<std::string>{"taken.gltf", "taken.obj", "taken.ply"}));
    for (const char* name : {"taken.obj", "taken.ply", "taken.gltf"})
        EXPECT_TRUE(fs::is_empty(dir.path / name));
    try {
        exporter::writeObj(dir.path / "missing" / "plants.obj", mesh, "t");
    } catch (const draw::OutputError& e) {
        EXPECT_NE(std::string(e.what()).find("plants.obj"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("No such file"), std::string::npos) << e.what();
    }
}

TEST(MeshExport, FormatComesFromTheExtension) {
    EXPECT_EQ(exporter::meshFormatOf("a/b.obj"), exporter::MeshFormat::Obj);
    EXPECT_EQ(exporter::meshFormatOf("b.PLY"), exporter::MeshFormat::Ply);
    EXPECT_EQ(exporter::meshFormatOf("b.gltf"), exporter::MeshFormat::Gltf);
    EXPECT_FALSE(exporter::meshFormatOf("b.glb"));
    EXPECT_FALSE(exporter::meshFormatOf("obj"));
}

} // namespace
