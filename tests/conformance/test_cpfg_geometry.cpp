// Conformance with cpfg's drawing: every `exact` model of the corpus interpreted by the reference turtle and its
// segments, spheres, discs, polygons and surfaces compared, one by one in the order drawn, with the geometry cpfg
// exported for it (geometry/*.ray.xz): the ends and radii within 1e-5 of the plant's size, the spheres', discs' and
// surfaces' places within 1e-4, the surfaces' frames and scales, and the points of each surface's patches as cpfg
// tessellated them. The models that match are listed, so that a change that breaks one fails, and the count of
// those that do is printed with the first difference of each other.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <fmt/format.h>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "compute/shared/organ_layout.h"
#include "corpus.h"
#include "cpu/derive.h"
#include "lang/load_grammar.h"
#include "ray_geometry.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_settings.h"

namespace simeco::test {
namespace {

namespace fs = std::filesystem;

// The ends and radii of a segment, and a sphere's or disc's radius, may differ by this share of the plant's size.
constexpr float kTolerance = 1e-5f;
// A sphere's or disc's centre by this share: it may end hundreds of rolls from the root (the phyllotaxis of
// Ridley, whose spheres stand after up to 300 rolls of 137.51 degrees), which simeco's floats and cpfg's doubles
// round apart.
constexpr float kCentreTolerance = 1e-4f;

// What simeco's reference turtle draws for the model, as cpfg's exporter writes it: the segments of squared length
// above 1e-5 and positive width, and the spheres.
struct Drawn {
    std::vector<RaySegment> segments;
    std::vector<RaySphere> spheres;
    std::vector<RayDisc> discs;
    std::vector<RayTriangle> polygonFans;
    std::vector<RayTriangle> cylinderTriangles;
    std::vector<RaySurface> surfaces; // in cpfg's frame and units (the surface's reach taken out of its scales)
    // The triangles of each surface the view reads, in cpfg's frame of the surface at its view's size.
    std::map<std::string, std::vector<RayTriangle>> surfaceMeshes;
};

// simeco's leaf frame (heading, left, up) to cpfg's surface frame (left, heading, up, cpfg's up being simeco's
// reversed).
glm::vec3 cpfgSurfaceFrame(const std::array<float, 3>& p) { return {p[1], p[0], -p[2]}; }

Drawn simecoDrawing(const fs::path& file) {
    const ir::Grammar g = lang::loadGrammarFile(file.string());
    stream::DeriveOptions options;
    options.homomorphism = true;
    const stream::ModuleString string = cpu::deriveCpu(g, options).string;
    const turtle::TurtleSettings settings = turtle::turtleSettings(g, g.alphabet);
    const turtle::Interpretation drawn = turtle::interpretCpu(string, turtle::turtleCommands(g.alphabet), {settings});
    Drawn out;
    for (uint32_t k = 0; k < drawn.count[shared::kOrganLeaf]; ++k) {
        const shared::OrganInstance& o = drawn.organs[drawn.first[shared::kOrganLeaf] + k];
        const ir::SymbolId id = string.sym[o.module]; // the surface's name, which follows `~`, draws it
        const float reach = settings.surfaceScale[id];
        const glm::vec3 heading(o.heading.x, o.heading.y, o.heading.z), up(o.up.x, o.up.y, o.up.z);
        out.surfaces.push_back({g.alphabet.name(id), glm::vec3(o.heading.w, o.position.w, o.up.w) / reach,
                                glm::cross(up, heading), heading, -up,
                                glm::vec3(o.position.x, o.position.y, o.position.z)});
    }
    for (const ir::ViewSettings::Surface& surface : g.view.surfaces) {
        if (!surface.model) continue;
        std::vector<RayTriangle>& mesh = out.surfaceMeshes[surface.name];
        const ir::LeafModel& m = surface.model->mesh;
        for (size_t c = 0; c + 2 < m.corners.size(); c += 3)
            mesh.push_back({{cpfgSurfaceFrame(m.corners[c]) * surface.model->reach,
                             cpfgSurfaceFrame(m.corners[c + 1]) * surface.model->reach,
                             cpfgSurfaceFrame(m.corners[c + 2]) * surface.model->reach}});
    }
    for (uint32_t k = 0; k < drawn.count[shared::kOrganStem]; ++k) {
        const shared::OrganInstance& o = drawn.organs[drawn.first[shared::kOrganStem] + k];
        const glm::vec3 from(o.position.x, o.position.y, o.position.z);
        const glm::vec3 to = from + glm::vec3(o.heading.x, o.heading.y, o.heading.z) * o.position.w;
        if (glm::dot(to - from, to - from) <= 1e-5f || o.heading.w <= 0.0f) continue;
        out.segments.push_back({from, to, o.heading.w, o.up.w});
    }
    for (uint32_t kind : {shared::kOrganSphere, shared::kOrganDisc})
        for (uint32_t k = 0; k < drawn.count[kind]; ++k) {
            const shared::OrganInstance& o = drawn.organs[drawn.first[kind] + k];
            (kind == shared::kOrganSphere ? out.spheres : out.discs)
                .push_back({glm::vec3(o.position.x, o.position.y, o.position.z), o.heading.w});
        }
    for (uint32_t k = 0; k < drawn.count[shared::kOrganTriangle]; ++k) {
        const shared::OrganInstance& o = drawn.organs[drawn.first[shared::kOrganTriangle] + k];
        (o.shape == shared::kTriangleOfCylinder ? out.cylinderTriangles : out.polygonFans)
            .push_back({{glm::vec3(o.position.x, o.position.y, o.position.z),
                         glm::vec3(o.heading.x, o.heading.y, o.heading.z), glm::vec3(o.up.x, o.up.y, o.up.z)}});
    }
    return out;
}

// Whether every corner of one mesh lies within `tolerance` of a corner of the other, both ways.
bool sameCorners(const std::vector<RayTriangle>& a, const std::vector<RayTriangle>& b, float tolerance) {
    auto covered = [tolerance](const std::vector<RayTriangle>& from, const std::vector<RayTriangle>& by) {
        for (const RayTriangle& t : from)
            for (const glm::vec3& p : t.corners) {
                bool near = false;
                for (const RayTriangle& u : by)
                    for (const glm::vec3& q : u.corners) near = near || glm::distance(p, q) <= tolerance;
                if (!near) return false;
            }
        return true;
    };
    return covered(a, b) && covered(b, a);
}

// The first difference between cpfg's surfaces (the ones its file defines; it places undefined ones too, which
// draw nothing) and simeco's, or nothing.
std::string surfaceDifference(const RayGeometry& cpfg, const Drawn& drawn, float tolerance) {
    std::vector<RaySurface> placed = cpfg.surfaces;
    std::erase_if(placed, [&](const RaySurface& s) { return !cpfg.surfaceMeshes.contains(s.id); });
    if (placed.size() != drawn.surfaces.size())
        return fmt::format("{} surfaces, cpfg draws {}", drawn.surfaces.size(), placed.size());
    for (size_t k = 0; k < placed.size(); ++k) {
        const RaySurface &a = placed[k], &b = drawn.surfaces[k];
        const float scale = std::max({1.0f, a.scale.x, a.scale.y, a.scale.z});
        if (a.id != b.id || glm::distance(a.position, b.position) > kCentreTolerance / kTolerance * tolerance ||
            glm::distance(a.scale, b.scale) > 1e-4f * scale || glm::distance(a.left, b.left) > 1e-3f ||
            glm::distance(a.heading, b.heading) > 1e-3f || glm::distance(a.up, b.up) > 1e-3f)
            return fmt::format("surface {}: ~{} scaled ({:.4g},{:.4g},{:.4g}) at ({:.4g},{:.4g},{:.4g}) heading "
                               "({:.3g},{:.3g},{:.3g}) up ({:.3g},{:.3g},{:.3g}), cpfg's ~{} ({:.4g},{:.4g},{:.4g}) "
                               "at ({:.4g},{:.4g},{:.4g}) heading ({:.3g},{:.3g},{:.3g}) up ({:.3g},{:.3g},{:.3g})",
                               k, b.id, b.scale.x, b.scale.y, b.scale.z, b.position.x, b.position.y, b.position.z,
                               b.heading.x, b.heading.y, b.heading.z, b.up.x, b.up.y, b.up.z, a.id, a.scale.x,
                               a.scale.y, a.scale.z, a.position.x, a.position.y, a.position.z, a.heading.x,
                               a.heading.y, a.heading.z, a.up.x, a.up.y, a.up.z);
    }
    for (const auto& [id, mesh] : cpfg.surfaceMeshes) {
        const auto ours = drawn.surfaceMeshes.find(id);
        if (ours == drawn.surfaceMeshes.end()) return fmt::format("surface {} is not read", id);
        if (ours->second.size() != mesh.size())
            return fmt::format("surface {}: {} triangles, cpfg's {}", id, ours->second.size(), mesh.size());
        float extent = 0.0f;
        for (const RayTriangle& t : mesh)
            for (const glm::vec3& p : t.corners) extent = std::max(extent, glm::length(p));
        if (!sameCorners(mesh, ours->second, 1e-4f * std::max(extent, 1e-6f)))
            return fmt::format("surface {}: its points differ from cpfg's", id);
    }
    return {};
}

// The first difference between cpfg's segments and spheres and simeco's, or nothing.
std::string firstDifference(const RayGeometry& cpfg, const Drawn& drawn) {
    const std::vector<RaySegment>& got = drawn.segments;
    if (cpfg.segments.size() != got.size())
        return fmt::format("{} segments, cpfg draws {}", got.size(), cpfg.segments.size());
    const float tolerance = kTolerance * std::max(cpfg.size(), 1e-6f);
    if (std::string d = surfaceDifference(cpfg, drawn, tolerance); !d.empty()) return d;
    for (const auto& [name, want, have] : {std::tuple("sphere", &cpfg.spheres, &drawn.spheres),
                                            std::tuple("disc", &cpfg.discs, &drawn.discs)}) {
        if (want->size() != have->size()) return fmt::format("{} {}s, cpfg draws {}", have->size(), name, want->size());
        for (size_t k = 0; k < have->size(); ++k) {
            const RaySphere &a = (*want)[k], &b = (*have)[k];
            if (glm::distance(a.centre, b.centre) > kCentreTolerance / kTolerance * tolerance ||
                std::abs(a.radius - b.radius) > tolerance)
                return fmt::format("{} {}: radius {:.4g} at ({:.4g},{:.4g},{:.4g}), cpfg's {:.4g} at "
                                   "({:.4g},{:.4g},{:.4g})",
                                   name, k, b.radius, b.centre.x, b.centre.y, b.centre.z, a.radius, a.centre.x,
                                   a.centre.y, a.centre.z);
        }
    }
    if (cpfg.polygonFans.size() != drawn.polygonFans.size())
        return fmt::format("{} polygon triangles, cpfg's polygons make {}", drawn.polygonFans.size(),
                           cpfg.polygonFans.size());
    for (size_t k = 0; k < drawn.polygonFans.size(); ++k)
        for (int c = 0; c < 3; ++c)
            if (glm::distance(cpfg.polygonFans[k].corners[c], drawn.polygonFans[k].corners[c]) > tolerance)
                return fmt::format("polygon triangle {}: corner {} differs", k, c);
    if (cpfg.cylinderTriangles.size() != drawn.cylinderTriangles.size())
        return fmt::format("{} generalized cylinder triangles, cpfg draws {}", drawn.cylinderTriangles.size(),
                           cpfg.cylinderTriangles.size());
    for (size_t k = 0; k < drawn.cylinderTriangles.size(); ++k)
        for (int c = 0; c < 3; ++c) {
            const glm::vec3 a = cpfg.cylinderTriangles[k].corners[c], b = drawn.cylinderTriangles[k].corners[c];
            if (glm::distance(a, b) > tolerance)
                return fmt::format("generalized cylinder triangle {}: corner {} at ({:.5g},{:.5g},{:.5g}), cpfg's "
                                   "({:.5g},{:.5g},{:.5g})",
                                   k, c, b.x, b.y, b.z, a.x, a.y, a.z);
        }
    for (size_t k = 0; k < got.size(); ++k) {
        const RaySegment &a = cpfg.segments[k], &b = got[k];
        if (glm::distance(a.from, b.from) > tolerance || glm::distance(a.to, b.to) > tolerance)
            return fmt::format("segment {}: ({:.4g},{:.4g},{:.4g})-({:.4g},{:.4g},{:.4g}), cpfg's "
                               "({:.4g},{:.4g},{:.4g})-({:.4g},{:.4g},{:.4g})",
                               k, b.from.x, b.from.y, b.from.z, b.to.x, b.to.y, b.to.z, a.from.x, a.from.y, a.from.z,
                               a.to.x, a.to.y, a.to.z);
        if (std::abs(a.fromRadius - b.fromRadius) > tolerance || std::abs(a.toRadius - b.toRadius) > tolerance)
            return fmt::format("segment {}: radius {:.4g} to {:.4g}, cpfg's {:.4g} to {:.4g}", k, b.fromRadius,
                               b.toRadius, a.fromRadius, a.toRadius);
    }
    return {};
}

// The exact models whose every segment matches cpfg's today: a change that breaks one of them fails here.
const std::set<std::string> kMatching = {
    "01-Introduction/01-quadratic-Koch",
    "01-Introduction/02-snowflake-exercise",
    "01-Introduction/03-snowflake",
    "01-Introduction/04-compound",
    "01-Introduction/05-compound-homo",
    "01-Introduction/06-compound-param",
    "01-Introduction/07-fractal-ferns",
    "01-Introduction/08-continuous-time",
    "01-Introduction/09-continuous-decomp",
    "01-Introduction/10-recursive",
    "01-Introduction/11-alternating-exercise",
    "01-Introduction/12-alternating",
    "02-Mod-vis-3D/01-planation",
    "02-Mod-vis-3D/02-decussate",
    "02-Mod-vis-3D/03-decussate-shaded",
    "02-Mod-vis-3D/04-perspective",
    "02-Mod-vis-3D/05-monopodial",
    "02-Mod-vis-3D/06-comp-leaf-perspective",
    "02-Mod-vis-3D/09-monopodial-spiral/09-monopodial-maple",
    "02-Mod-vis-3D/09-monopodial-spiral",
    "02-Mod-vis-3D/10-sympodial",
    "02-Mod-vis-3D/11-sympodial-asym",
    "03-inverse-modeling/01-herb-lily",
    "03-inverse-modeling/02-fern-leaf",
    "03-inverse-modeling/06-phyllotaxis-ridley",
    "04-Signaling/01-hormone-up",
    "04-Signaling/02-hormone-down",
    "04-Signaling/03-signal-down",
    "04-Signaling/04-florigen",
    "04-Signaling/05-florigen-param",
    "04-Signaling/06-florigen+auxin",
    "04-Signaling/07-acrotonic-2-signals",
    "04-Signaling/08-basipetal-2-signals",
    "04-Signaling/09-mycelis-schematic",
    "04-Signaling/10-mycelis-realistic",
    "04-Signaling/11-acropetal-1-signal",
    "04-Signaling/12-basipetal-1-signal",
    "04-Signaling/13-mesotonic-1-signal",
    "04-Signaling/21-insect-schematic",
    "04-Signaling/22-insect-realistic",
    "05-Quantitative-info-flow/01-pipe-model",
    "05-Quantitative-info-flow/03-Borcher-Honda",
    "05-Quantitative-info-flow/ShootRoot",
    "07-Open/05-phyllotaxis-Vogel",
};

using CpfgGeometry = ScratchFolderTest;

TEST_F(CpfgGeometry, SegmentsSpheresDiscsAndPolygonsMatchCpfgsDrawing) {
    std::vector<CorpusModel> models = readManifest();
    std::erase_if(models, [](const CorpusModel& m) { return m.compare != "exact"; });
    ASSERT_EQ(models.size(), 44u) << "the corpus manifest was not found or is incomplete at " << kCorpus;
    std::vector<std::string> matching, differing;
    // Compared in the models that match.
    size_t segments = 0, spheres = 0, discs = 0, triangles = 0, cylinderTriangles = 0, surfaces = 0;
    for (const CorpusModel& model : models) {
        std::string name = model.folder;
        std::replace(name.begin(), name.end(), '/', '_');
        const RayGeometry cpfg = readRayGeometry(kCorpus / "geometry" / (name + ".ray.xz"));
        std::string difference;
        try {
            difference = firstDifference(cpfg, simecoDrawing(kCorpus / "models" / model.folder / model.file));
        } catch (const std::exception& e) {
            difference = std::string("not drawn: ") + e.what();
        }
        if (difference.empty()) {
            matching.push_back(model.folder);
            segments += cpfg.segments.size(), spheres += cpfg.spheres.size(), discs += cpfg.discs.size();
            triangles += cpfg.polygonFans.size();
            cylinderTriangles += cpfg.cylinderTriangles.size();
            surfaces += std::count_if(cpfg.surfaces.begin(), cpfg.surfaces.end(),
                                      [&](const RaySurface& r) { return cpfg.surfaceMeshes.contains(r.id); });
        } else {
            differing.push_back(model.folder + ": " + difference);
        }
    }
    for (const std::string& d : differing) std::printf("differs from cpfg: %s\n", d.c_str());
    std::printf("exact models drawn as cpfg draws their segments, spheres, discs, polygons, generalized cylinders and "
                "surfaces: %zu of %zu (%zu segments, %zu spheres, %zu discs, %zu polygon triangles, %zu cylinder "
                "triangles, %zu surfaces)\n",
                matching.size(), models.size(), segments, spheres, discs, triangles, cylinderTriangles, surfaces);
    // Every kind was compared somewhere.
    EXPECT_GT(segments, 0u);
    EXPECT_GT(spheres, 0u);
    EXPECT_GT(discs, 0u);
    EXPECT_GT(triangles, 0u);
    EXPECT_GT(cylinderTriangles, 0u);
    EXPECT_GT(surfaces, 0u);
    for (const std::string& m : matching) std::printf("  %s\n", m.c_str());
    for (const std::string& m : kMatching)
        EXPECT_NE(std::find(matching.begin(), matching.end(), m), matching.end()) << m << " no longer matches cpfg";
}

} // namespace
} // namespace simeco::test
