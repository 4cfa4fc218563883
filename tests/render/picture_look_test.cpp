// How a model's picture looks, end to end: a grammar and its view file in, the settings `simeco render` makes of
// them (app::renderSettings), a frame out. The cloud library draws without a ground on its colour map's
// background, outlines appear only in the outline style, a paper cut is two tones, and a cpfg tree without a view
// file draws in slender pixel lines.
#include <gtest/gtest.h>

#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <set>
#include <string>

#include "app/render_options.h"
#include "cpu/derive.h"
#include "lang/load_grammar.h"
#include "test_scene.h"
#include "turtle/turtle_commands.h"
#include "turtle/turtle_cpu.h"

namespace simeco::test {
namespace {

const std::string kGrammars = std::string(SIMECO_SOURCE_DIR) + "/grammars/";

struct Picture {
    ir::Grammar grammar;
    draw::RenderSettings settings;
    draw::Frame frame;
};

class PictureLook : public RenderTest {
protected:
    // The grammar derived and interpreted by the references, drawn as `simeco render` would with these options.
    Picture render(const std::string& path, app::PictureOptions options) {
        Picture p;
        p.grammar = lang::loadGrammarFile(path);
        stream::DeriveOptions derive;
        derive.homomorphism = true;
        stream::ModuleString string = cpu::deriveCpu(p.grammar, derive).string;
        turtle::Interpretation drawn =
            turtle::interpretCpu(string, turtle::turtleCommands(p.grammar.alphabet),
                                 {turtle::turtleSettings(p.grammar, p.grammar.alphabet)});
        TestScene scene = uploadScene(context(), drawn.organs);
        p.settings = app::renderSettings(options, p.grammar.view);
        p.frame = renderer().render(scene.instances, scene.table, scene.bounds, p.settings);
        return p;
    }
};

glm::vec3 rgbAt(const draw::Frame& frame, std::size_t pixel) {
    return {frame.rgba[4 * pixel], frame.rgba[4 * pixel + 1], frame.rgba[4 * pixel + 2]};
}

app::PictureOptions small(const std::string& style = "") {
    app::PictureOptions options;
    options.size = "240x180";
    options.style = style;
    return options;
}

// A view's first directional light (`light: V: x,y,z`) is the picture's sun; without one the sun stays the
// renderer's.
TEST(PictureSettings, AViewsLightIsTheSun) {
    ir::ViewSettings view;
    const glm::vec3 renderers = app::renderSettings(small(), view).sunDirection;
    view.look.sunDirection = std::array{0.6f, 0.0f, 0.8f};
    const glm::vec3 sun = app::renderSettings(small(), view).sunDirection;
    EXPECT_FLOAT_EQ(sun.x, 0.6f);
    EXPECT_FLOAT_EQ(sun.y, 0.0f);
    EXPECT_FLOAT_EQ(sun.z, 0.8f);
    EXPECT_GT(glm::length(renderers - sun), 0.1f);
}

TEST_F(PictureLook, ACloudDrawsWithoutAGroundOnItsColourMapsBackgroundAndFillsASaneShareOfTheFrame) {
    Picture p = render(kGrammars + "clouds/head-c1a.l", small());
    maybeSavePreview(p.frame, "cloud_c1a");
    EXPECT_FALSE(p.settings.ground);
    EXPECT_EQ(p.settings.shadows, draw::Shadows::None);
    EXPECT_EQ(p.settings.style, draw::Style::Outline);
    const std::array<float, 3> mapped = p.grammar.view.palette.at(0);
    EXPECT_EQ(p.settings.background, glm::vec3(mapped[0], mapped[1], mapped[2]));
    std::size_t cloud = 0;
    for (std::size_t i = 0; i < p.frame.pixelCount(); ++i) {
        if (p.frame.organ[i] != draw::Frame::kNoId) {
            ++cloud;
            continue;
        }
        // No ground: every pixel that shows no organ is the background's, all the way down the frame, or the ink
        // of the outline around the cloud.
        const glm::vec3 rgb = rgbAt(p.frame, i);
        ASSERT_TRUE(rgb == p.settings.background || rgb == p.settings.outlineColor) << "pixel " << i;
    }
    const double share = double(cloud) / double(p.frame.pixelCount());
    EXPECT_GT(share, 0.10);
    EXPECT_LT(share, 0.85);
    // Framed: the cloud touches no edge of the frame.
    PixelBox box = organPixels(p.frame);
    EXPECT_GT(box.minX, 0);
    EXPECT_GT(box.minY, 0);
    EXPECT_LT(box.maxX, int(p.frame.width) - 1);
    EXPECT_LT(box.maxY, int(p.frame.height) - 1);
}

TEST_F(PictureLook, OutlinesAppearOnlyInTheOutlineStyle) {
    const std::string cloud = kGrammars + "clouds/head-c1b.l";
    for (const char* style : {"lit", "toon", "outline"}) {
        SCOPED_TRACE(style);
        Picture p = render(cloud, small(style));
        maybeSavePreview(p.frame, std::string("cloud_c1b_") + style);
        std::size_t ink = 0, organs = 0;
        for (std::size_t i = 0; i < p.frame.pixelCount(); ++i) {
            if (p.frame.organ[i] == draw::Frame::kNoId && rgbAt(p.frame, i) == p.settings.background) continue;
            ++organs;
            if (rgbAt(p.frame, i) == p.settings.outlineColor) ++ink;
        }
        ASSERT_GT(organs, 500u);
        // The white tubes are never that dark when lit; in the outline style their silhouettes are inked.
        if (std::string(style) == "outline") EXPECT_GT(ink, organs / 20);
        else EXPECT_EQ(ink, 0u);
    }
}

TEST_F(PictureLook, APaperCutIsTheOrgansColourWithThePaperShowingThroughAlongItsEdges) {
    app::PictureOptions options = small("paper-cut");
    options.background = "paper";
    Picture p = render(kGrammars + "clouds/head-c4.l", options);
    maybeSavePreview(p.frame, "cloud_c4_paper_cut");
    EXPECT_EQ(p.settings.background, draw::kPaperColor);
    const std::array<float, 3> first = p.grammar.view.palette.at(1); // the turtle's colour, as the head uses
    const glm::vec3 cut(first[0], first[1], first[2]);
    // Multisampled, an edge's pixels mix the two by the share of the pixel each covers: every pixel lies between.
    const glm::vec3 across = cut - draw::kPaperColor;
    const int most = std::abs(across.x) >= std::max(std::abs(across.y), std::abs(across.z)) ? 0
                     : std::abs(across.y) >= std::abs(across.z)                            ? 1
                                                                                            : 2;
    std::size_t colour = 0, paperInside = 0, mixed = 0;
    for (std::size_t i = 0; i < p.frame.pixelCount(); ++i) {
        const glm::vec3 rgb = rgbAt(p.frame, i);
        const float share = (rgb[most] - draw::kPaperColor[most]) / across[most];
        ASSERT_GE(share, -1e-5f) << "pixel " << i;
        ASSERT_LE(share, 1.0f + 1e-5f) << "pixel " << i;
        for (int c = 0; c < 3; ++c)
            ASSERT_NEAR(rgb[c], draw::kPaperColor[c] + share * across[c], 1e-4f) << "pixel " << i << " is no mix";
        // The mean of equal samples may round in the last bit.
        const bool isCut = share > 1.0f - 1e-4f, isPaper = share < 1e-4f;
        if (!isCut && !isPaper) ++mixed;
        if (p.frame.organ[i] == draw::Frame::kNoId) continue;
        if (isCut) ++colour;
        else if (isPaper) ++paperInside;
    }
    // The cuts are drawn over the edges in whole pixels; the pieces' edges they leave are smooth.
    EXPECT_GT(mixed, 100u);
    EXPECT_GT(colour, 1000u);
    // The cuts: along the spheres' edges and where the sun does not reach, the paper shows within the cloud.
    EXPECT_GT(paperInside, colour / 50);
}

TEST_F(PictureLook, ACpfgTreeWithoutAViewFileDrawsInSlenderPixelLines) {
    // ABOP's monopodial tree with its `!` widths of world units: without a view file cpfg draws them as pixels.
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / ("simeco-no-view-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    fs::copy_file(kGrammars + "abop/fig2.6-monopodial.l", dir / "tree.l", fs::copy_options::overwrite_existing);
    app::PictureOptions options;
    options.size = "240x320";
    options.shadows = "none";
    Picture p = render((dir / "tree.l").string(), options);
    fs::remove_all(dir);
    maybeSavePreview(p.frame, "monopodial_without_view");
    EXPECT_EQ(p.grammar.view.lineStyle, ir::LineStyle::Pixel);
    PixelBox tree = organPixels(p.frame);
    ASSERT_FALSE(tree.empty());
    const int height = tree.maxY - tree.minY + 1;
    ASSERT_GT(height, int(p.frame.height) / 4);
    // The trunk, in the lowest tenth of the tree: its `!(10)` ten pixels wide, not a disc of radius 5 under a
    // trunk of length 1 (what world units would draw).
    int widest = 0;
    for (int y = tree.maxY - height / 10; y <= tree.maxY; ++y) {
        int left = int(p.frame.width), right = -1;
        for (int x = 0; x < int(p.frame.width); ++x) {
            if (p.frame.organ[p.frame.index(std::uint32_t(x), std::uint32_t(y))] == draw::Frame::kNoId) continue;
            left = std::min(left, x);
            right = std::max(right, x);
        }
        widest = std::max(widest, right - left + 1);
    }
    EXPECT_LE(widest, 11);
    EXPECT_LT(widest, height / 10);
}

} // namespace
} // namespace simeco::test
