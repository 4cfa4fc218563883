// The skeleton's JSON file read back as written, and malformed skeletons refused with a message that names what is
// wrong (cycles, disconnected stems, zero-length stems, numbers that are not finite, JSON that is not JSON).
#include <cmath>
#include <string>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "ir/source_loc.h"
#include "skeleton/internodes.h"
#include "skeleton/skeleton_check.h"
#include "skeleton/skeleton_json.h"

namespace simeco::test {
namespace {

using skeleton::Plant;
using skeleton::Stem;

// A trunk of two segments, a branch from its middle point and a twig from the branch's base: four stems.
Plant smallTree() {
    Plant p;
    p.stems.push_back({0, -1, -1, {{0, 0, 0}, {0, 1, 0}, {0.1, 2, 0}}, 0.2, {}});
    p.stems.push_back({1, 0, 1, {{0, 1, 0}, {0.7, 1.6, 0.2}}, 0.1, {}});
    p.stems.push_back({2, 1, 1, {{0.7, 1.6, 0.2}, {0.9, 2.1, -0.3}}, 0.05, {}});
    p.stems.push_back({3, 0, -1, {{0.05, 1.5, 0}, {-0.5, 1.9, 0}}, 0.05, {}}); // on the trunk's second segment
    skeleton::Organ leaf;
    leaf.stem = 2;
    leaf.point = 1;
    leaf.position = {0.9, 2.1, -0.3};
    leaf.heading = {0, 0, 1};
    leaf.size = 0.3;
    p.organs.push_back(leaf);
    return p;
}

// The error checkPlant or the reader gives, or "" when it accepts.
std::string refusal(Plant p) {
    try {
        skeleton::checkPlant(p, "tree.json", 0);
    } catch (const ir::InputError& e) {
        return e.formatted();
    }
    return "";
}

std::string readError(const std::string& text) {
    try {
        skeleton::Skeleton s = skeleton::parseSkeletonJson(text, "tree.json");
        skeleton::checkSkeleton(s, "tree.json");
    } catch (const ir::InputError& e) {
        return e.formatted();
    }
    return "";
}

TEST(SkeletonFile, WhatIsWrittenIsReadBack) {
    skeleton::Skeleton written;
    written.source = "a \"small\" tree";
    written.plants.push_back(smallTree());
    written.plants.front().stems[1].widths = {0.1};
    skeleton::Skeleton read = skeleton::parseSkeletonJson(skeleton::skeletonJson(written), "tree.json");
    ASSERT_EQ(read.plants.size(), 1u);
    EXPECT_EQ(read.source, written.source);
    const Plant& a = written.plants.front();
    const Plant& b = read.plants.front();
    ASSERT_EQ(b.stems.size(), a.stems.size());
    for (size_t k = 0; k < a.stems.size(); ++k) {
        EXPECT_EQ(b.stems[k].id, a.stems[k].id);
        EXPECT_EQ(b.stems[k].parent, a.stems[k].parent);
        EXPECT_EQ(b.stems[k].attach, a.stems[k].attach);
        EXPECT_DOUBLE_EQ(b.stems[k].width, a.stems[k].width);
        ASSERT_EQ(b.stems[k].points.size(), a.stems[k].points.size());
        for (size_t j = 0; j < a.stems[k].points.size(); ++j)
            EXPECT_NEAR(glm::length(b.stems[k].points[j] - a.stems[k].points[j]), 0.0, 1e-8);
    }
    ASSERT_EQ(b.organs.size(), 1u);
    EXPECT_EQ(b.organs[0].stem, 2);
    EXPECT_EQ(b.organs[0].point, 1);
    EXPECT_DOUBLE_EQ(b.organs[0].size, 0.3);
}

TEST(SkeletonFile, ABranchStartingWithinASegmentGetsAPointThere) {
    Plant p = smallTree();
    ASSERT_EQ(refusal(p), "");
    skeleton::checkPlant(p, "tree.json", 0);
    EXPECT_EQ(p.stems[0].points.size(), 4u) << "the trunk gains the point stem 3 starts at";
    EXPECT_EQ(p.stems[3].attach, 2);
    EXPECT_EQ(p.stems[1].attach, 1) << "a branch below the new point keeps its point";
    skeleton::InternodeTree tree = skeleton::internodeTree(p);
    EXPECT_EQ(tree.internodes.size(), 6u);
    EXPECT_EQ(tree.roots.size(), 1u);
    EXPECT_EQ(tree.levels, 3) << "the trunk's first segment; its second and the branch; the rest";
}

TEST(SkeletonFile, TheMainChildIsTheStraightestOn) {
    Plant p = smallTree();
    skeleton::checkPlant(p, "tree.json", 0);
    skeleton::InternodeTree tree = skeleton::internodeTree(p);
    const skeleton::Internode& first = tree.internodes[size_t(tree.roots.front())];
    ASSERT_EQ(first.children.size(), 2u);
    const skeleton::Internode& main = tree.internodes[size_t(first.children.front())];
    EXPECT_EQ(main.stem, 0) << "the trunk goes on rather than the branch that leans away";
}

TEST(SkeletonFile, MalformedSkeletonsAreRefusedWithWhatIsWrong) {
    Plant loop = smallTree();
    loop.stems[0].parent = 2;
    loop.stems[0].attach = 1;
    EXPECT_NE(refusal(loop).find("loop back"), std::string::npos) << refusal(loop);

    Plant apart = smallTree();
    apart.stems[3].parent = -1;
    apart.stems[3].points = {{5, 0, 0}, {5, 1, 0}};
    EXPECT_NE(refusal(apart).find("not connected"), std::string::npos) << refusal(apart);

    Plant offParent = smallTree();
    offParent.stems[2].attach = -1;
    offParent.stems[2].points.front() = {3, 3, 3};
    EXPECT_NE(refusal(offParent).find("does not start on its parent"), std::string::npos) << refusal(offParent);

    Plant zero = smallTree();
    zero.stems[1].points = {{0, 1, 0}, {0, 1, 0}};
    EXPECT_NE(refusal(zero).find("coincide"), std::string::npos) << refusal(zero);

    Plant nan = smallTree();
    nan.stems[2].points[1].x = std::nan("");
    EXPECT_NE(refusal(nan).find("not a finite number"), std::string::npos) << refusal(nan);

    Plant unknownParent = smallTree();
    unknownParent.stems[2].parent = 9;
    EXPECT_NE(refusal(unknownParent).find("not a stem"), std::string::npos) << refusal(unknownParent);

    Plant twice = smallTree();
    twice.stems[3].id = 1;
    EXPECT_NE(refusal(twice).find("used twice"), std::string::npos) << refusal(twice);

    Plant onePoint = smallTree();
    onePoint.stems[2].points.pop_back();
    EXPECT_NE(refusal(onePoint).find("two or more"), std::string::npos) << refusal(onePoint);
}

TEST(SkeletonFile, MalformedFilesAreRefusedAtTheirPlace) {
    EXPECT_EQ(readError("{\"plants\": [\n  {\"stems\": [\n    {\"id\": 0, \"points\": [[0, 0, 0], [0, 1, 0]]},,\n"),
              "tree.json:3:49: error: syntax error while parsing value - unexpected ','; expected '[', '{', or a "
              "literal");
    EXPECT_NE(readError("{\"plants\": [{\"stems\": [{\"id\": 0, \"points\": [[0, 0], [0, 1, 0]]}]}]}")
                  .find("/plants/0/stems/0/points/0: expected [x, y, z]"),
              std::string::npos);
    EXPECT_NE(readError("{\"plants\": [{\"stems\": [{\"id\": 0, \"points\": [[0, 1e999, 0], [0, 1, 0]]}]}]}")
                  .find("number overflow"),
              std::string::npos);
    EXPECT_NE(readError("{\"plants\": []}").find("no plants"), std::string::npos);
    EXPECT_NE(readError("{\"plants\": [{\"stems\": []}]}").find("no stems"), std::string::npos);
    EXPECT_EQ(readError("{\"plants\": [{\"stems\": [{\"id\": 0, \"points\": [[0, 0, 0], [0, 1, 0]]}]}]}"), "");
}

} // namespace
} // namespace simeco::test
