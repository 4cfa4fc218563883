// Contour curves (`curve:` in a view file): reading `.con` files and evaluating curveX/Y/Z and curveGAL as
// cpfg does. The expected numbers come from a separate Python transcription of cpfg's CCurveXYZ
// (curveXYZ.cpp: uniform / clamped cubic B-spline and Bezier evaluation, 100-sample chord-length table,
// bisection and linear interpolation), printed with %.17g.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

#include "ir/contour_curve.h"
#include "ir/source_loc.h"
#include "lang/cpfg_contour.h"

namespace {

namespace fs = std::filesystem;
using simeco::ir::ContourCurve;
using simeco::ir::ContourType;
using simeco::ir::curveCoordinate;
using simeco::ir::curveLength;

constexpr double kTolerance = 1e-12;

// A fresh temporary directory, removed with the fixture.
class ContourFiles : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("simeco-contour-" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }

    std::string write(const std::string& name, const std::string& text) {
        fs::path p = dir_ / name;
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }

    // The error parseContourFile reports for `text`; fails the test when it reports none.
    simeco::ir::InputError errorFor(const std::string& text) {
        std::string path = write("bad.con", text);
        try {
            simeco::lang::parseContourFile(path);
        } catch (const simeco::ir::InputError& e) {
            EXPECT_EQ(e.loc().file, path);
            return e;
        }
        ADD_FAILURE() << "no error for:\n" << text;
        return simeco::ir::InputError({}, "");
    }

    fs::path dir_;
};

const char* kProfile = "version: 1.4\n"
                       "contact: 0 0 0\n"
                       "end: 0 0 0\n"
                       "heading: 0 1 0\n"
                       "up: 0 0 -1\n"
                       "size: 1\n"
                       "points: 4\n"
                       "range: 0.0 1.0\n"
                       "dimension: 4\n"
                       "type: bspline\n"
                       "0.269398 -0.447751 0.000000 3\n"
                       "0.251672 -0.146409 0.000000 1\n"
                       "0.178207 0.113511 0.000000 1\n"
                       "0.002079 0.143115 0.000000 3\n";

// The profile of the phyllotaxis-ridley model (its profile.con), read from a file.
TEST_F(ContourFiles, ProfileMatchesCpfgArcLengthEvaluation) {
    ContourCurve c = simeco::lang::parseContourFile(write("profile.con", kProfile));
    EXPECT_EQ(c.name, "profile.con");
    EXPECT_EQ(c.type, ContourType::BSpline);
    ASSERT_EQ(c.points.size(), 4u);
    EXPECT_EQ(c.xs.size(), 8u); // multiplicities 3 + 1 + 1 + 3
    EXPECT_NEAR(curveLength(c), 0.71811818215111556, kTolerance);

    struct Sample {
        double t, x, y;
    };
    const Sample samples[] = {
        {0.0, 0.26939800000000003, -0.4477509999999999},   {0.001, 0.2693567665251686, -0.44705003092786549},
        {0.25, 0.25690376200011161, -0.26870102173076876}, {0.5, 0.23053692338002243, -0.091190558984574704},
        {0.73, 0.17136916647549574, 0.061963845417991048}, {1.0, 0.0020790000000000001, 0.14311499999999999},
    };
    for (const Sample& s : samples) {
        EXPECT_NEAR(curveCoordinate(c, 0, s.t), s.x, kTolerance) << "t = " << s.t;
        EXPECT_NEAR(curveCoordinate(c, 1, s.t), s.y, kTolerance) << "t = " << s.t;
        EXPECT_EQ(curveCoordinate(c, 2, s.t), 0.0);
    }
    // t is clamped to [0, 1].
    EXPECT_EQ(curveCoordinate(c, 0, -3.0), curveCoordinate(c, 0, 0.0));
    EXPECT_EQ(curveCoordinate(c, 1, 7.5), curveCoordinate(c, 1, 1.0));

    // `curve: profile.con 50` samples more coarsely, which changes the length and the mapping a little.
    simeco::ir::sampleContourCurve(c, 50);
    EXPECT_NEAR(curveLength(c), 0.7180573903395594, kTolerance);
    EXPECT_NEAR(curveCoordinate(c, 0, 0.5), 0.23053366518024485, kTolerance);
}

// The phyllotaxis-ridley model's own file, when the shared corpus is present.
TEST(ContourCurve, CorpusProfileFile) {
    fs::path path = fs::path(SIMECO_SHARED_DIR) / "corpus/cpfg-vlab/models/03-inverse-modeling/06-phyllotaxis-ridley" /
                    "profile.con";
    if (!fs::exists(path)) GTEST_SKIP() << "no corpus at " << path;
    ContourCurve c = simeco::lang::parseContourFile(path.string());
    EXPECT_NEAR(curveLength(c), 0.71811818215111556, kTolerance);
    EXPECT_NEAR(curveCoordinate(c, 1, 0.25), -0.26870102173076876, kTolerance);
}

// Every curve type over the same five points (the third with multiplicity 2), 100 samples; values at
// t = 0, 0.3 and 1 as (x, y, z).
TEST(ContourCurve, AllTypesMatchCpfg) {
    struct Expected {
        ContourType type;
        double length;
        double p[3][3];
    };
    const Expected cases[] = {
        {ContourType::BSpline,
         1.777761906020904,
         {{0.83333333333333326, 0.16666666666666666, 0.33333333333333331},
          {0.99475481581539504, 0.63612301360820456, 0.17931590110359524},
          {0.25000025000074999, 1.1666661666671665, -0.16666716666566675}}},
        {ContourType::BSplineClosed,
         4.6646169962338737,
         {{0.83333333333333326, 0.16666666666666666, 0.33333333333333331},
          {0.55661008671716783, 1.0135714087181302, -0.20473069574375335},
          {0.83333283333283281, 0.16666616666716616, 0.33333333333283333}}},
        {ContourType::BSplineEndpoint,
         4.0152941750296387,
         {{0, 0, 0},
          {0.96560311817677857, 0.45256053740663643, 0.2565212903850711},
          {0.49999850000299978, 1.9999970000029994, 0.99999550000524928}}},
        {ContourType::BSplinePhantom,
         4.1842444580029117,
         {{0, 0, 0},
          {0.96735080272300089, 0.43959441891387169, 0.26387819190456463},
          {0.49999949999999993, 1.9999989999999996, 0.99999849999999979}}},
        {ContourType::Bezier,
         1.6619170336433868,
         {{0, 0, 0},
          {0.45142121624121523, 0.086766282610353657, 0.18232746681543077},
          {0.99999999999999989, 0.99999999999699996, 1.4999954998255656e-12}}},
    };
    const double ts[3] = {0.0, 0.3, 1.0};
    for (const Expected& e : cases) {
        ContourCurve c;
        c.type = e.type;
        c.points = {{0, 0, 0, 1}, {1, 0, 0.5, 1}, {1, 1, 0, 2}, {0, 1, -0.5, 1}, {0.5, 2, 1, 1}};
        simeco::ir::sampleContourCurve(c);
        SCOPED_TRACE(static_cast<int>(e.type));
        EXPECT_NEAR(curveLength(c), e.length, kTolerance);
        for (int i = 0; i < 3; ++i)
            for (int axis = 0; axis < 3; ++axis)
                EXPECT_NEAR(curveCoordinate(c, axis, ts[i]), e.p[i][axis], kTolerance) << "t = " << ts[i];
    }
}

// Fewer than four evaluation points give the origin and a zero length, as in cpfg; a curve whose points
// coincide stays at that point (its length is rounding noise, as in cpfg).
TEST(ContourCurve, DegenerateCurves) {
    ContourCurve few;
    few.points = {{1, 2, 3, 1}, {4, 5, 6, 2}};
    simeco::ir::sampleContourCurve(few);
    EXPECT_EQ(curveLength(few), 0.0);
    EXPECT_EQ(curveCoordinate(few, 0, 0.5), 0.0);

    ContourCurve still;
    still.points = {{0.5, -1, 2, 4}};
    simeco::ir::sampleContourCurve(still);
    EXPECT_NEAR(curveLength(still), 0.0, kTolerance);
    EXPECT_NEAR(curveCoordinate(still, 1, 0.7), -1.0, kTolerance);
}

// Older files without the `version:` header, two numbers per point (the default dimension), and a nested
// `points:` block (one point's own curve, which curveX ignores).
TEST_F(ContourFiles, ReadsMinimalAndNestedFiles) {
    ContourCurve c = simeco::lang::parseContourFile(write("plain.con", "points: 4\n"
                                                                       "type: bezier\n"
                                                                       "0 0\n"
                                                                       "1 0\n"
                                                                       "points: 2\n"
                                                                       "9 9\n"
                                                                       "8 8\n"
                                                                       "1 1\n"
                                                                       "0 1"));
    EXPECT_EQ(c.type, ContourType::Bezier);
    ASSERT_EQ(c.points.size(), 4u);
    EXPECT_EQ(c.points[2].x, 1.0);
    EXPECT_EQ(c.points[2].y, 1.0);
    EXPECT_EQ(c.points[3].multiplicity, 1);
    EXPECT_NEAR(curveCoordinate(c, 0, 0.0), 0.0, kTolerance);
    EXPECT_NEAR(curveCoordinate(c, 1, 1.0), 1.0, 1e-5);
}

TEST_F(ContourFiles, MalformedFilesReportLineAndColumn) {
    struct Case {
        std::string text;
        int line, col;
        const char* message;
    };
    const Case cases[] = {
        {"version: 1.4\ntype: bspline\n", 2, 1, "must follow a 'points:' line"},
        {"points: 2\ndimension: 3\n0 0 0\n1 x 0\n", 4, 3, "expected a number, found 'x'"},
        {"points: 2\ndimension: 4\n0 0 0 1\n1 1 0\n", 4, 1, "expected 4 numbers per point"},
        {"points: 1\n0 0\n1 1\n", 3, 1, "more points than the 'points:' line declares"},
        {"points: 3\n0 0\n1 1\n", 1, 1, "declares 3 points but lists 2"},
        {"points: four\n", 1, 9, "'points:' expected a number, found 'four'"},
        {"points: 2\ndimension: 7\n", 2, 12, "from 2 to 4"},
        // Far outside long's range (found by the fuzzer: its conversion was undefined), and NaN.
        {"points: 2\ndimension: 5e44\n", 2, 12, "from 2 to 4"},
        {"points: 2\ndimension: nan\n", 2, 12, "expected a number, found 'nan'"},
        {"points: 1\ndimension: 4\n0 0 0 nan\n", 3, 7, "expected a number, found 'nan'"},
        {"contact: 0 0\n", 1, 13, "'contact:' needs 3 number(s)"},
        {"points: 1\ndimension: 4\n0 0 0 -2\n", 3, 7, "multiplicity"},
        {"points: 16\ntype: bezier-surface\n", 2, 7, "bezier-surface"},
        {"cver 1 3\nname: leaf\n", 1, 1, "'cver' contour"},
        {"version: 1.4\n", 1, 1, "expected a 'points: N' line"},
    };
    for (const Case& c : cases) {
        simeco::ir::InputError e = errorFor(c.text);
        EXPECT_EQ(e.loc().line, c.line) << c.text;
        EXPECT_EQ(e.loc().col, c.col) << c.text;
        EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos) << c.text << " -> " << e.what();
    }
    EXPECT_THROW(simeco::lang::parseContourFile((dir_ / "missing.con").string()), simeco::ir::InputError);
}

} // namespace
