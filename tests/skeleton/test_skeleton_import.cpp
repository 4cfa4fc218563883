// Skeletons drawn elsewhere: an OBJ file of polylines, whose parents are found from where they touch, and three
// orthogonal views (front, side, top) read from JSON or SVG and combined into 3D, with malformed input refused at
// its line and column.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "../unit/temporary_folder.h"
#include "ir/source_loc.h"
#include "skeleton/skeleton_check.h"
#include "skeleton/skeleton_obj.h"
#include "skeleton/three_views.h"

namespace simeco::test {
namespace {

using skeleton::Plant;
using skeleton::Stem;
using skeleton::ThreeViews;

constexpr double kPi = 3.14159265358979323846;

// The error `read` refuses its input with; fails the test where it accepts it.
ir::InputError refusal(const std::function<void()>& read) {
    try {
        read();
    } catch (const ir::InputError& e) {
        return e;
    }
    ADD_FAILURE() << "the input was accepted";
    return ir::InputError({}, "(accepted)");
}

const Stem& stemById(const Plant& plant, int id) {
    for (const Stem& s : plant.stems)
        if (s.id == id) return s;
    throw std::runtime_error("no stem " + std::to_string(id));
}

void expectPoints(const Stem& s, const std::vector<glm::dvec3>& want, double tolerance) {
    ASSERT_EQ(s.points.size(), want.size()) << "stem " << s.id;
    for (size_t k = 0; k < want.size(); ++k)
        EXPECT_LE(glm::length(s.points[k] - want[k]), tolerance)
            << "stem " << s.id << " point " << k << ": (" << s.points[k].x << ", " << s.points[k].y << ", "
            << s.points[k].z << ") instead of (" << want[k].x << ", " << want[k].y << ", " << want[k].z << ")";
}

// Every stem of `want` in `got` with the same parent, width and points (within `tolerance`).
void expectSamePlant(const Plant& got, const Plant& want, double tolerance) {
    ASSERT_EQ(got.stems.size(), want.stems.size());
    for (const Stem& w : want.stems) {
        const Stem& g = stemById(got, w.id);
        EXPECT_EQ(g.parent, w.parent) << "stem " << w.id;
        EXPECT_DOUBLE_EQ(g.width, w.width) << "stem " << w.id;
        expectPoints(g, w.points, tolerance);
    }
}

// ---- OBJ ----

// A twig from the middle of the trunk's first segment, a branch written tip first, and the trunk written from the
// top down, with the indices, comments and statements an exporter writes.
const char* kThreeStemObj = R"(# three stems
g plant
v 0 0.5 0       # 1: the twig's base, inside the trunk's first segment
v -1 1.2 0.5    # 2
vt 0.5 0.5
o branch
v 1 3 0.2       # 3: the branch's tip
v 0.5 2.6 0
v 0 2 0         # 5: the trunk's top, where the branch grows
v 0 1 0
v 0 0 0         # 7: the plant's base
l 1 2
l 3/1 4/1 5/1
usemtl bark
l -3 -2 -1
)";

TEST(ObjSkeleton, ParentsAndDirectionsComeFromWhereStemsTouch) {
    skeleton::Skeleton sk = skeleton::parseObjSkeleton(kThreeStemObj, "plant.obj");
    ASSERT_EQ(sk.plants.size(), 1u);
    Plant& plant = sk.plants[0];
    ASSERT_EQ(plant.stems.size(), 3u);
    // Ids in the order of the file's line elements.
    const Stem &twig = stemById(plant, 0), &branch = stemById(plant, 1), &trunk = stemById(plant, 2);
    EXPECT_EQ(trunk.parent, -1);
    EXPECT_EQ(branch.parent, 2);
    EXPECT_EQ(twig.parent, 2);
    EXPECT_EQ(twig.attach, -1);
    expectPoints(trunk, {{0, 0, 0}, {0, 1, 0}, {0, 2, 0}}, 0.0);        // turned to start at the base
    expectPoints(branch, {{0, 2, 0}, {0.5, 2.6, 0}, {1, 3, 0.2}}, 0.0); // turned to start on the trunk
    expectPoints(twig, {{0, 0.5, 0}, {-1, 1.2, 0.5}}, 0.0);
    EXPECT_EQ(twig.width, 0.0);

    skeleton::checkSkeleton(sk, "plant.obj");
    // The twig's base lies inside the trunk's first segment: the check inserts it as the trunk's point 1.
    expectPoints(trunk, {{0, 0, 0}, {0, 0.5, 0}, {0, 1, 0}, {0, 2, 0}}, 0.0);
    EXPECT_EQ(twig.attach, 1);
    EXPECT_EQ(branch.attach, 3);
}

struct MalformedObj {
    const char* text;
    int line, col;
    const char* message;
};

TEST(ObjSkeleton, MalformedLinesAreRefusedAtTheirLineAndColumn) {
    const MalformedObj cases[] = {
        {"v 0 0 0\nv 0 1.x 0\nl 1 2\n", 2, 5, "'1.x' is not a finite number"},
        {"v 0 0 0\nv 0 inf 0\nl 1 2\n", 2, 5, "'inf' is not a finite number"},
        {"v 0 0\nv 0 1 0\nl 1 2\n", 1, 1, "three coordinates"},
        {"v 0 0 0\nv 0 1 0\nl 1 9\n", 3, 5, "vertex 9 does not exist: the file has 2 vertices"},
        {"v 0 0 0\nv 0 1 0\nl 1 0\n", 3, 5, "vertex index 0 does not exist"},
        {"v 0 0 0\nv 0 1 0\nl\t1  -3\n", 3, 6, "counts back past the first vertex"},
        {"v 0 0 0\nv 0 1 0\nl 1 x/2\n", 3, 5, "'x/2' is not a vertex index"},
        {"v 0 0 0\nv 0 1 0\n  l 2  # one vertex\n", 3, 3, "two or more vertices"},
        {"v 0 0 0\nv 0 1 0\nf 1 2 2\n", 0, 0, "no line elements"},
    };
    for (const MalformedObj& c : cases) {
        ir::InputError e = refusal([&] { skeleton::parseObjSkeleton(c.text, "bad.obj"); });
        EXPECT_EQ(e.loc().file, "bad.obj") << c.text;
        EXPECT_EQ(e.loc().line, c.line) << c.text;
        EXPECT_EQ(e.loc().col, c.col) << c.text;
        EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << c.text << "\n" << e.what();
    }
}

TEST(ObjSkeleton, StemsThatDoNotTouchMakeThePlantFallApart) {
    skeleton::Skeleton sk =
        skeleton::parseObjSkeleton("v 0 0 0\nv 0 1 0\nv 2 0.5 0\nv 3 1 0\nl 1 2\nl 3 4\n", "apart.obj");
    ASSERT_EQ(sk.plants.at(0).stems.size(), 2u);
    EXPECT_EQ(sk.plants[0].stems[0].parent, -1);
    EXPECT_EQ(sk.plants[0].stems[1].parent, -1);
    ir::InputError e = refusal([&] { skeleton::checkSkeleton(sk, "apart.obj"); });
    EXPECT_NE(std::string(e.what()).find("not connected"), std::string::npos) << e.what();
}

// ---- three views ----

Stem makeStem(int id, int parent, double width, std::vector<glm::dvec3> points) {
    Stem s;
    s.id = id;
    s.parent = parent;
    s.width = width;
    s.points = std::move(points);
    return s;
}

// A small tree of bent stems leaving the xy plane: a trunk, two branches from its points and a twig from the
// middle of a branch's first segment (where the check inserts a point).
Plant bentTree() {
    Plant p;
    p.stems.push_back(makeStem(0, -1, 0.2, {{0, 0, 0}, {0.1, 1, 0.05}, {0.05, 2, 0.2}, {-0.1, 3, 0.3}}));
    p.stems.push_back(makeStem(1, 0, 0.1, {{0.1, 1, 0.05}, {0.6, 1.5, -0.3}, {1.2, 1.8, -0.5}}));
    p.stems.push_back(makeStem(2, 0, 0.08, {{0.05, 2, 0.2}, {-0.5, 2.4, 0.6}, {-0.8, 2.9, 1.1}}));
    p.stems.push_back(makeStem(3, 1, 0.04, {{0.35, 1.25, -0.125}, {0.4, 1.6, 0.2}, {0.3, 1.9, 0.4}}));
    skeleton::checkPlant(p, "tree", 0);
    return p;
}

// A tree of smooth bent stems, each sampled at `n` points (n - 1 a multiple of 4, so that the branches grow from
// points of their parents), to draw views of with different numbers of points.
glm::dvec3 trunkAt(double t) {
    return {0.2 * std::sin(kPi * t), 3.0 * t, 0.3 * (1.0 - std::cos(kPi * t / 2.0))};
}
glm::dvec3 branchAt(double s) {
    return trunkAt(0.5) +
           glm::dvec3(1.2 * s, 0.6 * s + 0.2 * std::sin(kPi * s), -0.8 * s + 0.15 * std::sin(2 * kPi * s));
}
glm::dvec3 otherBranchAt(double s) {
    return trunkAt(0.75) +
           glm::dvec3(-1.0 * s + 0.1 * std::sin(2 * kPi * s), 0.8 * s, 0.9 * s - 0.2 * std::sin(kPi * s));
}
glm::dvec3 twigAt(double s) {
    return branchAt(0.5) + glm::dvec3(0.15 * std::sin(kPi * s), 0.5 * s, 0.6 * s);
}

Plant curvedTree(int n) {
    auto sampled = [n](glm::dvec3 (*at)(double)) {
        std::vector<glm::dvec3> points;
        for (int k = 0; k < n; ++k)
            points.push_back(at(double(k) / double(n - 1)));
        return points;
    };
    Plant p;
    p.stems.push_back(makeStem(0, -1, 0.2, sampled(trunkAt)));
    p.stems.push_back(makeStem(1, 0, 0.1, sampled(branchAt)));
    p.stems.push_back(makeStem(2, 0, 0.1, sampled(otherBranchAt)));
    p.stems.push_back(makeStem(3, 1, 0.05, sampled(twigAt)));
    return p;
}

double tolerance(const Plant& p, double fraction) {
    return fraction * skeleton::plantSize(p);
}

TEST(ThreeViews, JsonOfTheProjectionsRebuildsThePlant) {
    Plant tree = bentTree();
    std::string json = skeleton::threeViewsJson(skeleton::projectThreeViews(tree));
    skeleton::Skeleton sk = skeleton::parseThreeViewsJson(json, "tree.json");
    ASSERT_EQ(sk.plants.size(), 1u);
    skeleton::checkSkeleton(sk, "tree.json");
    expectSamePlant(sk.plants[0], tree, tolerance(tree, 1e-6));
    EXPECT_EQ(stemById(sk.plants[0], 3).attach, 1);
}

// The views as an SVG drawing, the SVG's y pointing down: the front as polylines, the side as absolute paths and
// the top as relative ones, with a decoration in each view.
std::string svgOf(const ThreeViews& views, bool withParents) {
    std::ostringstream out;
    out.precision(17);
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<!-- three views of a tree -->\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"-5 -5 10 10\">\n  <g id=\"front\">\n";
    for (const skeleton::ViewStem& s : views.front.stems) {
        out << "    <polyline data-stem=\"" << s.id << "\"";
        if (withParents) out << " data-parent=\"" << s.parent.value_or(-1) << "\"";
        out << " data-width=\"" << s.width << "\" points=\"";
        for (const glm::dvec2& p : s.points)
            out << p.x << "," << -p.y << " ";
        out << "\" fill=\"none\"/>\n";
    }
    out << "    <text x=\"0\" y=\"1\">front &amp; back</text>\n  </g>\n  <g id='side'>\n";
    for (const skeleton::ViewStem& s : views.side.stems) {
        out << "    <path data-stem=\"" << s.id << "\" d=\"M " << s.points[0].x << " " << -s.points[0].y << " L";
        for (size_t k = 1; k < s.points.size(); ++k)
            out << " " << s.points[k].x << "," << -s.points[k].y;
        out << "\"></path>\n";
    }
    out << "    <line x1=\"0\" y1=\"0\" x2=\"1\" y2=\"0\"/>\n  </g>\n  <g id=\"top\">\n";
    for (const skeleton::ViewStem& s : views.top.stems) {
        out << "    <path data-stem=\"" << s.id << "\" d=\"m" << s.points[0].x << "," << -s.points[0].y;
        for (size_t k = 1; k < s.points.size(); ++k)
            out << " " << s.points[k].x - s.points[k - 1].x << " " << -(s.points[k].y - s.points[k - 1].y);
        out << "\"/>\n";
    }
    out << "  </g>\n</svg>\n";
    return out.str();
}

TEST(ThreeViews, SvgOfTheProjectionsRebuildsThePlant) {
    Plant tree = bentTree();
    skeleton::Skeleton sk = skeleton::parseThreeViewsSvg(svgOf(skeleton::projectThreeViews(tree), true), "tree.svg");
    ASSERT_EQ(sk.plants.size(), 1u);
    skeleton::checkSkeleton(sk, "tree.svg");
    expectSamePlant(sk.plants[0], tree, tolerance(tree, 1e-6));
}

TEST(ThreeViews, SvgWithoutParentsFindsThemFromWhereStemsTouch) {
    Plant tree = bentTree();
    skeleton::Skeleton sk = skeleton::parseThreeViewsSvg(svgOf(skeleton::projectThreeViews(tree), false), "tree.svg");
    skeleton::checkSkeleton(sk, "tree.svg");
    expectSamePlant(sk.plants.at(0), tree, tolerance(tree, 1e-6));
}

TEST(ThreeViews, SvgPathsWithHorizontalAndVerticalLines) {
    const char* svg = R"(<svg xmlns="http://www.w3.org/2000/svg">
<g id="front"><path data-stem="0" d="M0,0 V-2 H1 v-1"/></g>
<g id="side"><path data-stem="0" d="m 0 0 0-2 l0,0 L1e0 -3"/></g>
<g id="top"><path data-stem="0" d="M 0 0 L 0 0 h 1 V 1"/></g>
</svg>)";
    skeleton::Skeleton sk = skeleton::parseThreeViewsSvg(svg, "hv.svg");
    skeleton::checkSkeleton(sk, "hv.svg");
    expectPoints(sk.plants.at(0).stems.at(0), {{0, 0, 0}, {0, 2, 0}, {1, 2, 0}, {1, 3, 1}}, 1e-12);
}

// `views` with one view's stems drawn through the points of `coarse` (the same stems sampled at other points).
ThreeViews withViewOf(ThreeViews views, const Plant& coarse, const std::string& view) {
    ThreeViews other = skeleton::projectThreeViews(coarse);
    if (view == "front") views.front = other.front;
    if (view == "side") views.side = other.side;
    if (view == "top") views.top = other.top;
    return views;
}

// Compares each stem of `got` point by point with the same stem of the `truths` (the tree sampled as the views
// are) that has as many points (the leading view's), before the check, which may insert a point where a resampled
// base meets its parent between two points; then checks the plant.
void expectLikeTruths(Plant got, const std::vector<Plant>& truths) {
    const double size = skeleton::plantSize(truths.at(0));
    ASSERT_EQ(got.stems.size(), truths[0].stems.size());
    double worst = 0.0;
    for (const Stem& g : got.stems) {
        const Stem* want = nullptr;
        for (const Plant& truth : truths)
            if (stemById(truth, g.id).points.size() == g.points.size()) want = &stemById(truth, g.id);
        ASSERT_NE(want, nullptr) << "stem " << g.id << " has " << g.points.size() << " points";
        EXPECT_EQ(g.parent, want->parent);
        expectPoints(g, want->points, 0.01 * size);
        for (size_t k = 0; k < g.points.size(); ++k)
            worst = std::max(worst, glm::length(g.points[k] - want->points[k]));
    }
    ::testing::Test::RecordProperty("worst_error_fraction", std::to_string(worst / size));
    EXPECT_NO_THROW(skeleton::checkPlant(got, "mixed.json", 0));
}

TEST(ThreeViews, ASideViewWithFewerPointsIsResampled) {
    Plant fine = curvedTree(17), coarse = curvedTree(13);
    // Not a subset of the front's points: the same stems sampled elsewhere.
    ThreeViews views = withViewOf(skeleton::projectThreeViews(fine), coarse, "side");
    ASSERT_EQ(views.side.stems[0].points.size(), 13u);
    // Each stem has the points of the view that sees it longest: the twig (stem 3), rising in y and z, the side's.
    Plant got = skeleton::plantFromThreeViews(views, "mixed.json");
    EXPECT_EQ(stemById(got, 3).points.size(), 13u);
    EXPECT_EQ(stemById(got, 1).points.size(), 17u);
    expectLikeTruths(got, {fine, coarse});
    // Through the JSON text as well.
    expectLikeTruths(skeleton::parseThreeViewsJson(skeleton::threeViewsJson(views), "mixed.json").plants.at(0),
                     {fine, coarse});
}

TEST(ThreeViews, ViewsWithFewerPointsThanTheSideAreResampled) {
    Plant fine = curvedTree(33), coarse = curvedTree(9);
    ThreeViews views = withViewOf(withViewOf(skeleton::projectThreeViews(fine), coarse, "front"), coarse, "top");
    ASSERT_EQ(views.front.stems[0].points.size(), 9u);
    ASSERT_EQ(views.side.stems[0].points.size(), 33u);
    // Each stem has the points of the view that sees it longest: the side's 33 or the front's or top's 9.
    expectLikeTruths(skeleton::plantFromThreeViews(views, "mixed.json"), {fine, coarse});
}

TEST(ThreeViews, AStemMissingFromAViewIsRefusedByName) {
    ThreeViews views = skeleton::projectThreeViews(bentTree());
    views.top.stems.erase(views.top.stems.begin() + 2);
    ir::InputError e = refusal([&] { skeleton::parseThreeViewsJson(skeleton::threeViewsJson(views), "tree.json"); });
    EXPECT_NE(std::string(e.what()).find("stem 2 is in the front view but not in the top view"), std::string::npos)
        << e.what();

    // In an SVG drawing the error points at the stem in the front view.
    const char* svg =
        "<svg>\n<g id=\"front\">\n  <polyline data-stem=\"7\" points=\"0,0 0,-1\"/>\n</g>\n"
        "<g id=\"side\"><polyline data-stem=\"7\" points=\"0,0 0,-1\"/></g>\n<g id=\"top\"></g>\n</svg>\n";
    e = refusal([&] { skeleton::parseThreeViewsSvg(svg, "tree.svg"); });
    EXPECT_EQ(e.loc().line, 3);
    EXPECT_EQ(e.loc().col, 3);
    EXPECT_NE(std::string(e.what()).find("stem 7 is in the front view but not in the top view"), std::string::npos)
        << e.what();
}

TEST(ThreeViews, APolylineDrawnFromTipToBaseIsRefused) {
    ThreeViews views = skeleton::projectThreeViews(bentTree());
    std::vector<glm::dvec2>& side = views.side.stems[1].points;
    std::reverse(side.begin(), side.end());
    ir::InputError e = refusal([&] { skeleton::plantFromThreeViews(views, "tree.json"); });
    EXPECT_NE(std::string(e.what()).find("stem 1"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("disagree"), std::string::npos) << e.what();
}

// An SVG drawing of one vertical stem with `front`, `side` and `top` as the shapes of lines 3, 6 and 9.
std::string oneStemSvg(const std::string& front, const std::string& side, const std::string& top) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\">\n<g id=\"front\">\n" + front + "\n</g>\n<g id=\"side\">\n" +
           side + "\n</g>\n<g id=\"top\">\n" + top + "\n</g>\n</svg>\n";
}

struct MalformedSvg {
    std::string front, side, top;
    int line;
    const char* marker; // the text the error's column points at, on that line
    const char* message;
};

TEST(ThreeViews, MalformedSvgIsRefusedAtItsLineAndColumn) {
    const std::string front = "<polyline data-stem=\"0\" points=\"0,0 0,-2\"/>";
    const std::string side = "<polyline data-stem=\"0\" points=\"0,0 0,-2\"/>";
    const std::string top = "<polyline data-stem=\"0\" points=\"0,0 0,0\"/>";
    const MalformedSvg cases[] = {
        {"<path data-stem=\"0\" d=\"M 0 0 C 0 -1 0 -1 0 -2\"/>", side, top, 3, "C 0", "a curve ('C')"},
        {front, "<path data-stem=\"0\" d=\"M 0 0 L 0 -2 z\"/>", top, 6, "z\"", "'Z' closes the path"},
        {front, "<polyline transform=\"scale(2)\" data-stem=\"0\" points=\"0,0 0,-2\"/>", top, 6, "scale",
         "a transform"},
        {front, side, "<polyline data-stem=\"0\" points=\"0,0 0,x\"/>", 9, "x\"", "unexpected 'x'"},
        {front, side, "<polyline data-stem=\"0\" points=\"0,0 0\"/>", 9, "\"/>", "where the point's y was expected"},
        {"<polyline data-stem=\"a\" points=\"0,0 0,-2\"/>", side, top, 3, "a\"", "data-stem=\"a\" is not a whole"},
        {"<polyline data-stem=\"0\" data-width=\"-1\" points=\"0,0 0,-2\"/>", side, top, 3, "-1",
         "not a number of zero or more"},
        {"<path data-stem=\"0\" d=\"L 0 -2\"/>", side, top, 3, "L 0", "starts with a move"},
        {"<path data-stem=\"0\" d=\"M 0 0 L 0 -1 M 0 -1 L 0 -2\"/>", side, top, 3, "M 0 -1", "a second move"},
        {front, "<line data-stem=\"0\" x1=\"0\" y1=\"0\" x2=\"0\" y2=\"-2\"/>", top, 6, "<line",
         "draw a stem as a <polyline> or a <path>"},
        {front, side, "<g>", 11, "</svg>", "'</svg>' closes '<g>' of line 8"},
        {front, side, "<polyline data-stem=\"0\" points=\"0,0 0,0\">", 10, "</g>", "'</g>' closes '<polyline>'"},
    };
    for (const MalformedSvg& c : cases) {
        std::string svg = oneStemSvg(c.front, c.side, c.top);
        ir::InputError e = refusal([&] { skeleton::parseThreeViewsSvg(svg, "bad.svg"); });
        std::string line = c.line == 3    ? c.front
                           : c.line == 6  ? c.side
                           : c.line == 9  ? c.top
                           : c.line == 10 ? "</g>"
                                          : "</svg>";
        EXPECT_EQ(e.loc().line, c.line) << svg << "\n" << e.what();
        EXPECT_EQ(e.loc().col, int(line.find(c.marker)) + 1) << svg << "\n" << e.what();
        EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << svg << "\n" << e.what();
    }
    // The good drawing is accepted, so that each case above fails for its own fault.
    EXPECT_NO_THROW(skeleton::parseThreeViewsSvg(oneStemSvg(front, side, top), "good.svg"));

    ir::InputError e =
        refusal([&] { skeleton::parseThreeViewsSvg("<svg><g id=\"front\"/><g id=\"side\"/></svg>", "x.svg"); });
    EXPECT_NE(std::string(e.what()).find("no top view"), std::string::npos) << e.what();
    e = refusal([&] { skeleton::parseThreeViewsSvg("<svg>\n<!-- front -->  <g id=\"front\">", "x.svg"); });
    EXPECT_EQ(e.loc().line, 2);
    EXPECT_EQ(e.loc().col, 17);
    EXPECT_NE(std::string(e.what()).find("'<g>' is never closed"), std::string::npos) << e.what();
}

// Files read by their names, in a folder of the test's own.
class ImportFiles : public simeco::testing::TemporaryFolderTest {
protected:
    std::string write(const std::string& name, const std::string& text) {
        std::filesystem::path path = dir_ / name;
        std::ofstream(path, std::ios::binary) << text;
        return path.string();
    }
};

TEST_F(ImportFiles, ReadersChooseByExtensionAndNameTheFileInErrors) {
    EXPECT_EQ(skeleton::readObjSkeleton(write("plant.obj", kThreeStemObj)).plants.at(0).stems.size(), 3u);
    ThreeViews views = skeleton::projectThreeViews(bentTree());
    EXPECT_EQ(skeleton::readThreeViews(write("tree.json", skeleton::threeViewsJson(views))).plants.at(0).stems.size(),
              4u);
    EXPECT_EQ(skeleton::readThreeViews(write("tree.SVG", svgOf(views, true))).plants.at(0).stems.size(), 4u);

    std::string text = write("tree.txt", skeleton::threeViewsJson(views));
    EXPECT_NE(std::string(refusal([&] { skeleton::readThreeViews(text); }).what()).find(".json or an .svg"),
              std::string::npos);
    std::string missing = (dir_ / "missing.obj").string();
    ir::InputError e = refusal([&] { skeleton::readObjSkeleton(missing); });
    EXPECT_EQ(e.loc().file, missing);
    std::string bad = write("bad.json", "{\"views\": {\"front\": {\"stems\": [}}}");
    e = refusal([&] { skeleton::readThreeViews(bad); });
    EXPECT_EQ(e.loc().file, bad);
    EXPECT_EQ(e.loc().line, 1);
}

} // namespace
} // namespace simeco::test
