// cpfg's `.s` surfaces (lang/cpfg_surface.h) and how `~` draws them: the patches cut as the view or the file says,
// turned from the file's frame into the turtle's and scaled to the view's size; the turtle moved to the end point;
// nothing drawn for a surface a .l model's view does not define; a malformed file refused at its line and column.
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "compute/shared/organ_layout.h"
#include "cpu/derive.h"
#include "ir/source_loc.h"
#include "lang/cpfg_surface.h"
#include "lang/load_grammar.h"
#include "square_surface.h"
#include "temporary_folder.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"
#include "turtle/turtle_settings.h"

namespace simeco {
namespace {

using testing::squareSurface;

TEST(CpfgSurface, APatchIsCutAsTheViewOrTheFileSays) {
    // The view's steps, else the file's S precision for both directions (as cpfg), else five.
    EXPECT_EQ(lang::parseCpfgSurface(squareSurface(), "sq.s", 1.0f, 3, 2).mesh.corners.size(), 3u * 2u * 3u * 2u);
    EXPECT_EQ(lang::parseCpfgSurface(squareSurface("PRECISION S: 4 T: 7\n"), "sq.s", 1.0f).mesh.corners.size(),
              3u * 2u * 4u * 4u);
    EXPECT_EQ(lang::parseCpfgSurface(squareSurface(), "sq.s", 1.0f).mesh.corners.size(), 3u * 2u * 5u * 5u);
    EXPECT_EQ(lang::parseCpfgSurface(squareSurface(), "sq.s", 1.0f, 40, 40).mesh.corners.size(),
              3u * 2u * 10u * 10u); // at most ten
    EXPECT_EQ(lang::parseCpfgSurface(squareSurface("PRECISION S: 5e21 T: 1\n"), "sq.s", 1.0f).mesh.corners.size(),
              3u * 2u * 10u * 10u);
    EXPECT_EQ(lang::parseCpfgSurface(squareSurface("PRECISION S: -5e21 T: 1\n"), "sq.s", 1.0f).mesh.corners.size(),
              3u * 2u * 1u * 1u); // at least one
}

TEST(CpfgSurface, ItStandsOnItsContactPointInTheTurtlesFrameAtTheViewsSize) {
    // Size 2: the four-unit square is half as large; the contact point (2, 0) is its origin, the file's y (its
    // heading) the turtle's heading and the file's x, which is cpfg's left of heading +y and up -z, the turtle's.
    const ir::SurfaceModel s = lang::parseCpfgSurface(squareSurface(), "sq.s", 2.0f, 2, 2);
    std::array<float, 3> lo{1e9f, 1e9f, 1e9f}, hi{-1e9f, -1e9f, -1e9f};
    for (const auto& c : s.mesh.corners)
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], c[k] * s.reach);
            hi[k] = std::max(hi[k], c[k] * s.reach);
        }
    EXPECT_NEAR(lo[0], 0.0f, 1e-5f); // along the heading from the contact point
    EXPECT_NEAR(hi[0], 2.0f, 1e-5f);
    EXPECT_NEAR(lo[1], -1.0f, 1e-5f); // across, one each side
    EXPECT_NEAR(hi[1], 1.0f, 1e-5f);
    EXPECT_NEAR(lo[2], 0.0f, 1e-6f); // flat
    EXPECT_NEAR(hi[2], 0.0f, 1e-6f);
    EXPECT_NEAR(s.reach, std::sqrt(5.0f), 1e-5f); // the far corners
    EXPECT_NEAR(s.mesh.area, 2.0f * 2.0f / 5.0f, 1e-4f); // in units of the reach, squared
    EXPECT_NEAR(s.endPoint[0], 2.0f, 1e-5f);
    EXPECT_NEAR(s.endPoint[1], 0.0f, 1e-5f);
    EXPECT_NEAR(s.endPoint[2], 0.0f, 1e-5f);
    // The smooth normals of a flat patch are its plane's.
    for (const auto& n : s.mesh.cornerNormals) EXPECT_NEAR(std::abs(n[2]), 1.0f, 1e-5f);
}

TEST(CpfgSurface, AMalformedFileIsRefusedAtItsLineAndColumn) {
    auto errorOf = [](const std::string& text) {
        try {
            lang::parseCpfgSurface(text, "bad.s", 1.0f);
        } catch (const ir::InputError& e) {
            return e.formatted();
        }
        return std::string("no error");
    };
    std::string text = squareSurface();
    EXPECT_NE(errorOf(text.replace(text.find("X: 2"), 4, "X: q")).find("bad.s:2:19: error: expected a finite number"),
              std::string::npos)
        << errorOf(text);
    const std::string noPatch = squareSurface().substr(0, squareSurface().find("square"));
    EXPECT_NE(errorOf(noPatch).find("at least one patch"), std::string::npos) << errorOf(noPatch);
    std::string cut = squareSurface();
    cut.resize(cut.size() - 20);
    EXPECT_NE(errorOf(cut).find("expected a number for a control point, found the end of the file"),
              std::string::npos)
        << errorOf(cut);
    std::string zero = squareSurface();
    EXPECT_NE(errorOf(zero.replace(zero.find("SIZE: 4"), 7, "SIZE: 0")).find("SIZE is positive"), std::string::npos);
}

// A .l model in a folder of its own with the square surface `s` in its view.
class SurfaceModel : public simeco::testing::TemporaryFolderTest {
protected:
    turtle::Interpretation drawn(const std::string& axiom, const std::string& extension = ".l") {
        std::ofstream(dir_ / "sq.s") << squareSurface();
        const std::filesystem::path model = dir_ / ("m" + extension);
        if (extension == ".l") {
            std::ofstream(model) << "Lsystem: 1\nAxiom: " << axiom << "\nendlsystem\n";
            std::ofstream(dir_ / "m.v") << "surface: s sq.s 2 2 2\n";
        } else {
            std::ofstream(model) << "axiom: " << axiom << "\niterations: 0\n";
        }
        assets_ = {};
        const ir::Grammar g = lang::loadSpecies(model.string(), nullptr, &assets_).front();
        const stream::ModuleString string = cpu::deriveCpu(g, {}).string;
        return turtle::interpretCpu(string, turtle::turtleCommands(g.alphabet),
                                    {turtle::turtleSettings(g, g.alphabet)});
    }
    ir::DrawAssets assets_; // the models the renderer draws the surfaces with
};

TEST_F(SurfaceModel, TildeDrawsTheSurfaceScaledAndMovesTheTurtleToItsEnd) {
    const turtle::Interpretation r = drawn("~s(1.5)F(1)~s(1,2,3)");
    ASSERT_EQ(r.count[shared::kOrganLeaf], 2u);
    ASSERT_EQ(r.count[shared::kOrganStem], 1u);
    const float reach = std::sqrt(5.0f);
    const shared::OrganInstance& first = r.organs[r.first[shared::kOrganLeaf]];
    EXPECT_NEAR(first.position.w, 1.5f * reach, 1e-5f);
    EXPECT_NEAR(first.heading.w, 1.5f * reach, 1e-5f);
    EXPECT_NEAR(first.up.w, 1.5f * reach, 1e-5f);
    // The segment starts where the surface ended: its end point (two units up the heading) times 1.5.
    const shared::OrganInstance& stem = r.organs[r.first[shared::kOrganStem]];
    EXPECT_NEAR(stem.position.y, 3.0f, 1e-5f);
    const shared::OrganInstance& second = r.organs[r.first[shared::kOrganLeaf] + 1];
    EXPECT_NEAR(second.position.y, 4.0f, 1e-5f);
    EXPECT_NEAR(second.heading.w, 1.0f * reach, 1e-5f); // across
    EXPECT_NEAR(second.position.w, 2.0f * reach, 1e-5f); // along
    EXPECT_NEAR(second.up.w, 3.0f * reach, 1e-5f);       // out of it
    // Drawn with the file's patches, the renderer's first model, not a built-in blade.
    ASSERT_EQ(assets_.models.size(), 1u);
    EXPECT_EQ(assets_.models[0].corners.size(), 3u * 2u * 2u * 2u);
    EXPECT_EQ(second.shape, shared::kSurfaceLastShape + 1);
}

TEST_F(SurfaceModel, ASurfaceTheViewDoesNotDefineDrawsNothingInCpfgsModelsOnly) {
    EXPECT_EQ(drawn("F~q(2)F").count[shared::kOrganLeaf], 0u);
    EXPECT_EQ(drawn("F~q(2)F").organs[1].position.y, 1.0f) << "nor moves the turtle";
    EXPECT_EQ(drawn("F~q(2)F", ".lsys").count[shared::kOrganLeaf], 1u) << "a quick grammar draws a blade";
}

} // namespace
} // namespace simeco
